// The aerosol_inversions table (storage/schema/migrations.cpp) through
// storage/repositories/aerosol_inversion_repository.h: the migration that adds it applies to the
// database of the version before it with the rows there untouched; a file's bytes come back as
// stored, ids are never reused, lists are paged newest first.
#include "storage/repositories/aerosol_inversion_repository.h"

#include <gtest/gtest.h>

#include <string>

#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

// The migration that creates aerosol_inversions, by its SQL: its index is the version it starts
// from, whatever number merges give it.
int aerosol_migration_version() {
  const auto& all = schema_migrations();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].find("CREATE TABLE aerosol_inversions") != std::string_view::npos)
      return static_cast<int>(i);
  return -1;
}

NewAerosolInversion egbert(const std::string& name) {
  NewAerosolInversion n;
  n.name = name;
  n.content_hash = "0123456789abcdef";
  n.site = "Egbert";
  n.latitude_deg = 44.226;
  n.longitude_deg = -79.75;
  n.first_day = "2013-05-27";
  n.last_day = "2013-05-27";
  n.retrieval_count = 5;
  return n;
}

TEST(AerosolInversionRepository, MigratesThePreviousVersionWithItsRowsUntouched) {
  const int before = aerosol_migration_version();
  ASSERT_GE(before, 8);
  Database db = clearsky::testing::database_at_schema_version(before);
  DatasetRepository(db).find_or_create("set", "kider2014");
  EXPECT_THROW(db.execute("SELECT 1 FROM aerosol_inversions"), SqliteError);
  EXPECT_EQ(migrate(db), latest_schema_version() - before);
  EXPECT_EQ(db.user_version(), latest_schema_version());
  EXPECT_TRUE(DatasetRepository(db).find("set"));
  EXPECT_FALSE(AerosolInversionRepository(db).find(1));
}

TEST(AerosolInversionRepository, StoresTheBytesAndNeverReusesAnId) {
  Database db = Database::open(":memory:");
  migrate(db);
  AerosolInversionRepository repository(db);
  std::string bytes = "27:05:2013,Locations=Egbert\n";
  bytes.push_back('\0');  // a blob, not text: every byte comes back
  bytes += "\xff tail";
  const std::int64_t first = repository.create(egbert("egbert"), bytes);
  const auto found = repository.find(first);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->inversion.name, "egbert");
  EXPECT_EQ(found->inversion.site, "Egbert");
  EXPECT_DOUBLE_EQ(found->inversion.latitude_deg, 44.226);
  EXPECT_EQ(found->inversion.first_day, "2013-05-27");
  EXPECT_EQ(found->inversion.retrieval_count, 5);
  EXPECT_EQ(found->size_bytes, static_cast<std::int64_t>(bytes.size()));
  EXPECT_FALSE(found->created_utc.empty());
  EXPECT_EQ(repository.content(first), bytes);
  EXPECT_FALSE(repository.content(first + 1));
  // Deleted by hand (no route deletes one): the next id is still a new one.
  db.execute("DELETE FROM aerosol_inversions");
  const std::int64_t second = repository.create(egbert("again"), "x");
  EXPECT_GT(second, first);
  NewAerosolInversion none = egbert("none");
  none.retrieval_count = 0;
  EXPECT_THROW(repository.create(none, "x"), SqliteError);
}

TEST(AerosolInversionRepository, ListsNewestFirstByPages) {
  Database db = Database::open(":memory:");
  migrate(db);
  AerosolInversionRepository repository(db);
  for (const char* name : {"n0", "n1", "n2", "n3", "n4"}) repository.create(egbert(name), "x");
  const auto first = repository.list_page(2);
  ASSERT_EQ(first.rows.size(), 2u);
  EXPECT_TRUE(first.more);
  EXPECT_EQ(first.rows[0].inversion.name, "n4");
  const auto last = repository.list_page(10, first.rows.back().id);
  ASSERT_EQ(last.rows.size(), 3u);
  EXPECT_FALSE(last.more);
  EXPECT_EQ(last.rows.back().inversion.name, "n0");
}

}  // namespace
}  // namespace clearsky::storage
