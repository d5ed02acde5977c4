// The whole text of an open-format file (api/datasets/import_file_text.h), held to the
// import's max_entry_bytes, on a real file.
#include "api/datasets/import_file_text.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "api/error/api_error.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

TEST(ImportFileText, ReadsTheWholeFileWithinMaxEntryBytes) {
  clearsky::testing::TempDir dir;
  const auto file = dir.path / "rows.csv";
  std::ofstream(file, std::ios::binary) << "time,ghi\r\n";
  storage::ImportByteLimits limits;
  limits.max_entry_bytes = 10;
  EXPECT_EQ(read_import_file_text(file, limits, "rows.csv"), "time,ghi\r\n");

  limits.max_entry_bytes = 9;
  try {
    read_import_file_text(file, limits, "rows.csv");
    FAIL() << "read above max_entry_bytes";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 413);
    EXPECT_EQ(e.parameter(), "max_entry_bytes");
    EXPECT_STREQ(e.what(), "rows.csv: 10 bytes, above max_entry_bytes (9 bytes)");
  }
  EXPECT_THROW(read_import_file_text(dir.path / "absent.csv", limits, "absent.csv"),
               std::runtime_error);
}

}  // namespace
}  // namespace clearsky::api
