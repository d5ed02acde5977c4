// `clearsky sun`: the sun's position (NREL SPA) and the day's sunrise, transit and sunset for a
// place and time, as text or JSON (the same answer as GET /v1/sun, through api/handlers).
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "api/handlers/sun_handler.h"
#include "api/request/parameters.h"
#include "server/cli/commands.h"

namespace clearsky::cli {
namespace {

// Each request parameter with the option that carries it on the command line; the values and
// their ranges are those of api/request/place_time.h, read through the same parser.
struct SunOption {
  const char* parameter;
  const char* option;
  const char* help;
};
constexpr SunOption kSunOptions[] = {
    {"lat", "--lat", "Latitude, North positive: decimal degrees or DMS such as 42d26'36.4\"N"},
    {"lon", "--lon", "Longitude, East positive: decimal degrees or DMS such as 76d28'55.1\"W"},
    {"time", "--time",
     "ISO 8601 time with offset or Z, e.g. 2013-05-27T11:45:00-04:00 (default: now, UTC)"},
    {"altitude", "--elevation,--altitude", "Observer elevation above sea level, m (default 0)"},
    {"pressure", "--pressure", "Annual mean local pressure for refraction, mbar (default 1013.25)"},
    {"temperature", "--temperature",
     "Annual mean local temperature for refraction, Celsius (default 15)"},
    {"delta_t", "--delta-t", "TT - UT1, s (default: Espenak-Meeus for the year)"},
    {"delta_ut1", "--delta-ut1", "UT1 - UTC, s (default 0)"},
};

std::string option_of(const std::string& parameter) {
  if (parameter == "refraction") return "--no-refraction";
  for (const SunOption& o : kSunOptions) {
    if (parameter == o.parameter) {
      const std::string names = o.option;
      return names.substr(0, names.find(','));
    }
  }
  return parameter;
}

std::string describe_time(const std::optional<double>& unix_s, const api::PlaceTime& request,
                          DayKind kind) {
  if (unix_s)
    return api::format_iso8601_time(*unix_s, request.utc_offset_min, request.utc_designator);
  return kind == DayKind::polar_day ? "none (polar day: the sun stays above the horizon)"
                                    : "none (polar night: the sun stays below the horizon)";
}

void print_text(const api::PlaceTime& request, const api::SunAnswer& answer) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(6);
  out << "time     "
      << api::format_iso8601_time(request.position.unix_time_utc_s, request.utc_offset_min,
                                  request.utc_designator)
      << '\n';
  out << "zenith   " << answer.position.zenith_deg << " degrees (topocentric"
      << (request.position.refraction ? ", with refraction" : ", without refraction") << ")\n";
  out << "azimuth  " << answer.position.azimuth_deg << " degrees (clockwise from North)\n";
  out << "delta T  " << request.position.delta_t_s << " s ("
      << (request.delta_t_from_time ? "Espenak-Meeus for the year" : "given") << ")\n";
  out << "sunrise  " << describe_time(answer.times.sunrise_utc_s, request, answer.times.day_kind)
      << '\n';
  out << "transit  " << describe_time(answer.times.transit_utc_s, request, answer.times.day_kind)
      << '\n';
  out << "sunset   " << describe_time(answer.times.sunset_utc_s, request, answer.times.day_kind)
      << '\n';
  std::cout << out.str();
}

}  // namespace

void add_sun_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "sun", "Sun zenith and azimuth (NREL SPA) and the day's sunrise, transit, sunset");
  struct Values {
    std::string text[std::size(kSunOptions)];
    bool no_refraction = false;
    bool json = false;
  };
  auto values = std::make_shared<Values>();
  std::vector<CLI::Option*> options;
  for (std::size_t i = 0; i < std::size(kSunOptions); ++i) {
    // allow_extra_args(false) keeps one value per option; negative numbers and DMS are values.
    options.push_back(
        command->add_option(kSunOptions[i].option, values->text[i], kSunOptions[i].help));
  }
  command->add_flag("--no-refraction", values->no_refraction, "Leave out atmospheric refraction");
  command->add_flag("--json", values->json, "Print one JSON object");
  command->callback([values, options] {
    try {
      api::Parameters parameters("clearsky sun");
      for (std::size_t i = 0; i < std::size(kSunOptions); ++i) {
        if (options[i]->count() > 0) parameters.add(kSunOptions[i].parameter, values->text[i]);
      }
      if (values->no_refraction) parameters.add("refraction", "false");
      const api::PlaceTime request = api::parse_sun_query(parameters, api::current_unix_time_s());
      const api::SunAnswer answer = api::compute_sun(request);
      if (values->json) {
        std::cout << api::sun_answer_to_json(request, answer).dump(2) << '\n';
      } else {
        print_text(request, answer);
      }
    } catch (const api::ApiError& e) {
      throw std::runtime_error(option_of(e.parameter()) + ": " + e.reason());
    }
  });
}

}  // namespace clearsky::cli
