// The comment table of api/request/place_time.h against place_time_parameters(): the same rows
// in the same order, with the same units, defaults, ranges and meanings, so that the documented
// table cannot drift from the one the parser uses.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "api/request/place_time.h"

namespace clearsky::api {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

// The cells of each row of the first "// | ... |" table after the header row and its rule.
std::vector<std::vector<std::string>> comment_table(const std::filesystem::path& header) {
  std::ifstream in(header);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  int seen = 0;
  while (std::getline(in, line)) {
    if (line.rfind("// |", 0) != 0) {
      if (seen > 0) break;
      continue;
    }
    if (++seen <= 2) continue;  // the column names and the |---| rule
    std::vector<std::string> cells;
    std::size_t begin = 4;  // after "// |"
    while (begin < line.size()) {
      const std::size_t end = line.find('|', begin);
      if (end == std::string::npos) break;
      cells.push_back(trim(line.substr(begin, end - begin)));
      begin = end + 1;
    }
    rows.push_back(cells);
  }
  return rows;
}

// "[-500, 1e7]", "(-1, 1)": the interval the text writes.
Interval parse_interval(const std::string& text) {
  Interval out;
  EXPECT_GE(text.size(), 5u) << text;
  if (text.size() < 5) return out;
  out.min_open = text.front() == '(';
  out.max_open = text.back() == ')';
  EXPECT_TRUE(text.front() == '(' || text.front() == '[') << text;
  EXPECT_TRUE(text.back() == ')' || text.back() == ']') << text;
  const std::size_t comma = text.find(',');
  EXPECT_NE(comma, std::string::npos) << text;
  char* end = nullptr;
  const std::string low = trim(text.substr(1, comma - 1));
  const std::string high = trim(text.substr(comma + 1, text.size() - comma - 2));
  out.min = std::strtod(low.c_str(), &end);
  EXPECT_EQ(*end, '\0') << text;
  out.max = std::strtod(high.c_str(), &end);
  EXPECT_EQ(*end, '\0') << text;
  return out;
}

// The source tree of this build, as CMake recorded it (__FILE__ may be relative: ccache's
// base_dir rewrites paths).
std::filesystem::path source_dir() {
  std::ifstream cache(std::string(CLEARSKY_BINARY_DIR) + "/CMakeCache.txt");
  const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  std::string line;
  while (std::getline(cache, line)) {
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  }
  ADD_FAILURE() << "no " << key << " in " << CLEARSKY_BINARY_DIR << "/CMakeCache.txt";
  return {};
}

TEST(PlaceTimeTable, HeaderCommentMatchesTheCode) {
  const std::filesystem::path header = source_dir() / "api/request/place_time.h";
  ASSERT_TRUE(std::filesystem::exists(header)) << header;
  const auto rows = comment_table(header);
  const auto code = place_time_parameters();
  ASSERT_EQ(rows.size(), code.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& cells = rows[i];
    const PlaceTimeParameter& r = code[i];
    ASSERT_EQ(cells.size(), 5u) << "row " << i;
    EXPECT_EQ(cells[0], r.name);
    EXPECT_EQ(cells[1], r.unit) << r.name;
    EXPECT_EQ(cells[2], r.fallback) << r.name;
    EXPECT_EQ(cells[4], r.meaning) << r.name;
    std::string range = cells[3];
    if (r.kind == PlaceTimeKind::boolean) {
      EXPECT_EQ(range, "true/false") << r.name;
      continue;
    }
    if (r.kind == PlaceTimeKind::time) {
      ASSERT_EQ(range.rfind("years ", 0), 0u) << r.name;
      range = range.substr(6);
    }
    const Interval written = parse_interval(range);
    EXPECT_EQ(written.min, r.range.min) << r.name;
    EXPECT_EQ(written.max, r.range.max) << r.name;
    EXPECT_EQ(written.min_open, r.range.min_open) << r.name;
    EXPECT_EQ(written.max_open, r.range.max_open) << r.name;
  }
}

}  // namespace
}  // namespace clearsky::api
