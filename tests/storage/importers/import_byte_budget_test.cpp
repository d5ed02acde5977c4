// Tests of the byte budget of imports (storage/importers/import_byte_budget.h): the limits are
// counted on the bytes read, per entry and per import, and a zip whose one radiance entry
// inflates far past them is refused without being read whole.
#include "storage/importers/import_byte_budget.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "storage/importers/kider_reader.h"
#include "tests/support/temp_dir.h"
#include "tests/support/zero_filled_zip.h"

namespace clearsky::storage {
namespace {

TEST(ImportByteBudget, AnEntryPastMaxEntryBytesIsRefusedNamingTheLimit) {
  ImportByteBudget budget({100, 1000});
  std::int64_t entry = 0;
  budget.charge(entry, 60, "a");
  budget.charge(entry, 40, "a");
  EXPECT_EQ(entry, 100);
  try {
    budget.charge(entry, 1, "a");
    FAIL() << "charged past max_entry_bytes";
  } catch (const ImportLimitExceeded& e) {
    EXPECT_EQ(e.limit(), "max_entry_bytes");
    EXPECT_EQ(e.limit_bytes(), 100);
    EXPECT_NE(std::string(e.what()).find("max_entry_bytes"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget.import_bytes(), 100);
}

TEST(ImportByteBudget, EntriesTogetherPastMaxImportBytesAreRefusedNamingTheLimit) {
  ImportByteBudget budget({100, 250});
  for (int i = 0; i < 2; ++i) {
    std::int64_t entry = 0;
    budget.charge(entry, 100, "entry");
  }
  std::int64_t third = 0;
  budget.charge(third, 50, "third");
  try {
    budget.charge(third, 1, "third");
    FAIL() << "charged past max_import_bytes";
  } catch (const ImportLimitExceeded& e) {
    EXPECT_EQ(e.limit(), "max_import_bytes");
    EXPECT_EQ(e.limit_bytes(), 250);
  }
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// The decompression bomb found against `clearsky serve`: a small zip with one correctly named
// radiance entry of zeros (2 GiB there, 64 MiB here) was read at its declared size.
TEST(ImportByteBudget, AZipBombEntryIsRefusedAtTheEntryLimit) {
  clearsky::testing::TempDir dir;
  const auto zip = dir.path / "bomb.zip";
  clearsky::testing::write_zero_filled_zip(
      zip, {{clearsky::testing::kider_radiance_name(0), std::int64_t{64} << 20}});
  EXPECT_LT(std::filesystem::file_size(zip), 1u << 20);
  ImportByteBudget budget({1 << 20, 8 << 20});
  KiderReadRules rules;
  rules.budget = &budget;
  try {
    read_kider_raw_files(zip, {}, rules);
    FAIL() << "the bomb was read";
  } catch (const ImportLimitExceeded& e) {
    EXPECT_EQ(e.limit(), "max_entry_bytes");
  }
  // Counted while reading: at most one read buffer past the limit was taken in.
  EXPECT_LE(budget.import_bytes(), (1 << 20) + (1 << 16));
  // The same archive held in memory (an upload read from memory) is refused the same way.
  ImportByteBudget memory_budget({1 << 20, 8 << 20});
  EXPECT_THROW(read_kider_archive_bytes(bytes_of(zip), "bomb.zip", {}, &memory_budget),
               ImportLimitExceeded);
}

TEST(ImportByteBudget, ManyEntriesUnderTheEntryLimitMeetTheImportLimit) {
  clearsky::testing::TempDir dir;
  const auto zip = dir.path / "many.zip";
  std::vector<std::pair<std::string, std::int64_t>> entries;
  for (int i = 0; i < 8; ++i)
    entries.emplace_back(clearsky::testing::kider_radiance_name(i), 512 << 10);
  clearsky::testing::write_zero_filled_zip(zip, entries);
  ImportByteBudget budget({1 << 20, 2 << 20});
  KiderReadRules rules;
  rules.budget = &budget;
  try {
    read_kider_raw_files(zip, {}, rules);
    FAIL() << "read past max_import_bytes";
  } catch (const ImportLimitExceeded& e) {
    EXPECT_EQ(e.limit(), "max_import_bytes");
  }
}

TEST(ImportByteBudget, AFolderFileIsCountedToo) {
  clearsky::testing::TempDir dir;
  const auto file = dir.path / "2013-05-27___12.00.00_-_0____0.0___12.1151.asd.rad.txt";
  std::ofstream(file) << std::string(300, 'x');
  ImportByteBudget budget({100, 1000});
  KiderReadRules rules;
  rules.budget = &budget;
  EXPECT_THROW(read_kider_raw_files(dir.path, {}, rules), ImportLimitExceeded);
}

}  // namespace
}  // namespace clearsky::storage
