// The default Bruneton table's cache key is pinned: servers find the tables that earlier
// versions stored under it (server/cache/file_table_cache.h), so a change of the key's hash or
// of the configuration's canonical text must be deliberate.
#include <gtest/gtest.h>

#include "models/bruneton/bruneton.h"

namespace clearsky {
namespace {

TEST(BrunetonCacheKey, DefaultConfigurationKeyIsStable) {
  EXPECT_EQ(BrunetonModel::cache_key(ModelConfig{}), "bruneton-a9ee3c37742c94db");
}

}  // namespace
}  // namespace clearsky
