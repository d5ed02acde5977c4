// The columns of the open formats' CSV (api/datasets/csv_columns.h): the header, the rows'
// field counts and their values by column, with the refusals the formats give word for word.
#include "api/datasets/csv_columns.h"

#include <gtest/gtest.h>

#include <string>

#include "api/error/api_error.h"
#include "tests/support/api_refusal.h"

namespace clearsky::api {
namespace {

enum Column { kTime, kValue, kOptional };
const std::vector<std::string_view> kNames = {"time", "value", "optional"};

using Refusal = clearsky::testing::ApiRefusal;
using clearsky::testing::refusal_of;

TEST(CsvColumns, ReadsColumnsInAnyOrderByTheirIndex) {
  const CsvColumns columns("\xEF\xBB\xBFvalue, time\r\n1.5,2024-01-01T00:00:00Z\r\n-2,t2\n\n",
                           kNames);
  columns.require(kTime);
  columns.require(kValue);
  EXPECT_FALSE(columns.has(kOptional));
  ASSERT_EQ(columns.row_count(), 2u);
  const CsvRow first = columns.row(0);
  EXPECT_EQ(first.text(kTime), "2024-01-01T00:00:00Z");
  EXPECT_EQ(first.number(kValue), 1.5);
  EXPECT_FALSE(first.optional_number(kOptional));
  EXPECT_EQ(first.text(kOptional), "");
  EXPECT_EQ(columns.row(1).number(kValue), -2);
}

TEST(CsvColumns, AnEmptyFieldOfAnOptionalColumnIsNothing) {
  const CsvColumns columns("time,optional\nt1,\nt2,4\nt3,x\n", kNames);
  EXPECT_FALSE(columns.row(0).optional_number(kOptional));
  EXPECT_EQ(columns.row(1).optional_number(kOptional), 4);
  const Refusal bad = refusal_of([&] { columns.row(2).optional_number(kOptional); });
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(bad.parameter, "optional");
  EXPECT_EQ(bad.message.rfind("row 3 (line 4), optional: ", 0), 0u) << bad.message;
}

TEST(CsvColumns, RefusesTheHeaderNamingTheColumn) {
  Refusal r = refusal_of([] { CsvColumns("", kNames); });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "body");
  EXPECT_EQ(r.message, "body: empty (no header line)");
  r = refusal_of([] { CsvColumns("time,speed\n", kNames); });
  EXPECT_EQ(r.parameter, "speed");
  EXPECT_EQ(r.message,
            "header (line 1): unknown column 'speed'; the columns are time, value, optional");
  r = refusal_of([] { CsvColumns("time,,value\n", kNames); });
  EXPECT_EQ(r.parameter, "body");
  r = refusal_of([] { CsvColumns("time,value,time\n", kNames); });
  EXPECT_EQ(r.parameter, "time");
  EXPECT_EQ(r.message, "header (line 1): column time twice");
  r = refusal_of([] { CsvColumns("time\n", kNames).require(kValue); });
  EXPECT_EQ(r.parameter, "value");
  EXPECT_EQ(r.message, "header (line 1): no column value");
}

TEST(CsvColumns, RefusesARowWithAnotherFieldCount) {
  const CsvColumns columns("time,value\nt1,1\nt2\n", kNames);
  const Refusal r = refusal_of([&] { columns.row(1); });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "body");
  EXPECT_EQ(r.message, "row 2 (line 3): 1 fields, the header has 2");
}

}  // namespace
}  // namespace clearsky::api
