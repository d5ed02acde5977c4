// The comment table of api/skydome/skydome_options.h against skydome_option_table(): the same
// rows in the same order with the same values and defaults, so that the documented table cannot
// drift from the one the parser and the OpenAPI document use.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "api/skydome/skydome_options.h"

namespace clearsky::api {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

// The cells of each row of the first "// | ... |" table after its header row and rule.
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
    if (++seen <= 2) continue;
    std::vector<std::string> cells;
    std::size_t begin = 4;
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

// The source tree of this build, as CMake recorded it (__FILE__ may be relative under ccache).
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

TEST(SkydomeOptionsTable, HeaderCommentMatchesTheCode) {
  const auto rows = comment_table(source_dir() / "api/skydome/skydome_options.h");
  const auto table = skydome_option_table();
  ASSERT_EQ(rows.size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    ASSERT_GE(rows[i].size(), 3u);
    EXPECT_EQ(rows[i][0], table[i].name);
    std::string values;
    for (std::string_view v : table[i].values)
      values += (values.empty() ? "" : ", ") + std::string(v);
    EXPECT_EQ(rows[i][1], values) << table[i].name;
    // ground's default depends on the model, described below the table.
    const std::string expected_default =
        table[i].name == "ground" ? "see below" : std::string(table[i].default_text);
    EXPECT_EQ(rows[i][2], expected_default) << table[i].name;
  }
}

}  // namespace
}  // namespace clearsky::api
