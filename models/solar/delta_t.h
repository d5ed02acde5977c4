// Delta T = TT - UT1, the difference between terrestrial time and the time the Earth's rotation
// keeps, from the date: the polynomial expressions of Espenak and Meeus (NASA, "Polynomial
// Expressions for Delta T", Five Millennium Canon of Solar Eclipses: -1999 to +3000, NASA/TP-2006-
// 214141, section 2.6), which fit the historical values of Morrison and Stephenson (2004) and the
// observed ones up to 2005 and extrapolate beyond.
//
// clang-format off
// | input / output  | unit | range                | meaning                                          |
// |-----------------|------|----------------------|--------------------------------------------------|
// | decimal year y  | year | [-1999, 3001)        | year + (month - 0.5) / 12 (the publication's y)  |
// | delta T         | s    | about -20 .. 47000   | TT - UT1                                         |
// clang-format on
//
// Accuracy, as the publication states it: the ancient expressions reproduce their tables within
// 4 s; from 1600 to 2005 the expressions follow the observed values within about 1 s; after
// 2005 they are a prediction made in 2006, which the observed Delta T has since fallen below
// (IERS: 66.07 s in 2010.0, 69.36 s in 2020.0; the expressions give 66.7 and 71.6, see
// models/solar/README.md). Users who need the observed value give it (delta_t).
// Outside the years -1999 to 3000 no expression is published: InvalidInput naming delta_t_s.
// Pure functions; thread-safe.
#pragma once

namespace clearsky {

// The publication's y for a UTC instant (unix seconds): the calendar year plus the middle of its
// month, year + (month - 0.5) / 12 (proleptic Gregorian calendar).
double delta_t_decimal_year(double unix_time_utc_s);

// Delta T (s) at decimal year y by the expression of y's interval. Throws InvalidInput (field
// delta_t_s) for y outside [-1999, 3001) or NaN.
double espenak_meeus_delta_t_s(double decimal_year);

// espenak_meeus_delta_t_s(delta_t_decimal_year(unix_time_utc_s)).
double espenak_meeus_delta_t_at_s(double unix_time_utc_s);

}  // namespace clearsky
