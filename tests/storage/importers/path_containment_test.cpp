// Tests of the containment of canonical paths (storage/importers/path_containment.h).
#include "storage/importers/path_containment.h"

#include <gtest/gtest.h>

namespace clearsky::storage {
namespace {

TEST(PathContainment, InsideMeansUnderTheFolderByWholeComponents) {
  EXPECT_TRUE(lies_within("/srv/data/a.7z", "/srv/data"));
  EXPECT_TRUE(lies_within("/srv/data/x/y", "/srv/data/"));
  EXPECT_TRUE(lies_within("/srv/data", "/srv/data"));
  EXPECT_FALSE(lies_within("/srv/database/a.7z", "/srv/data"));
  EXPECT_FALSE(lies_within("/srv", "/srv/data"));
  EXPECT_FALSE(lies_within("/etc/passwd", "/srv/data"));
  EXPECT_FALSE(lies_within("relative/a.7z", "/srv/data"));
  EXPECT_FALSE(lies_within("/srv/data/a.7z", ""));
  EXPECT_TRUE(lies_within("/etc/passwd", "/"));
}

}  // namespace
}  // namespace clearsky::storage
