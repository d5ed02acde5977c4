// Tests of server-side import paths (api/datasets/import_roots.h): only what lies under an
// import root is importable, and every other path, whether missing, outside, leading out
// through a link or a special file, gets the same refusal, so answers do not reveal which
// paths exist.
#include "api/datasets/import_roots.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>
#include <vector>

#include "api/error/api_error.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

struct Refusal {
  int status = 0;
  std::string code, parameter, message;
  bool operator==(const Refusal&) const = default;
};

Refusal refusal_of(const ImportRoots& roots, const std::string& path) {
  try {
    roots.resolve(path);
  } catch (const ApiError& e) {
    return {e.status(), e.code(), e.parameter(), e.what()};
  }
  return {};
}

struct Roots {
  clearsky::testing::TempDir dir;
  std::filesystem::path root = dir.path / "root";
  Roots() {
    std::filesystem::create_directories(root / "folder");
    std::ofstream(root / "a.7z") << "archive";
    std::ofstream(dir.path / "outside.7z") << "outside";
    std::filesystem::create_symlink(dir.path / "outside.7z", root / "out_link.7z");
    std::filesystem::create_symlink("..", root / "up");
    std::filesystem::create_symlink("a.7z", root / "in_link.7z");
    std::filesystem::create_symlink("/dev/zero", root / "zero");
    EXPECT_EQ(::mkfifo((root / "fifo.7z").c_str(), 0600), 0);
  }
};

TEST(ImportRoots, PathsUnderARootResolveToTheirCanonicalForm) {
  Roots r;
  const ImportRoots roots({r.root.string()});
  const auto canonical_root = std::filesystem::canonical(r.root);
  EXPECT_EQ(roots.resolve("a.7z").path, canonical_root / "a.7z");
  EXPECT_EQ(roots.resolve("a.7z").root, canonical_root);
  EXPECT_EQ(roots.resolve("folder").path, canonical_root / "folder");
  EXPECT_EQ(roots.resolve((r.root / "a.7z").string()).path, canonical_root / "a.7z");
  // A link that stays inside the root is followed.
  EXPECT_EQ(roots.resolve("in_link.7z").path, canonical_root / "a.7z");
  EXPECT_EQ(roots.resolve("folder/../a.7z").path, canonical_root / "a.7z");
}

TEST(ImportRoots, EveryOtherPathGetsOneRefusal) {
  Roots r;
  const ImportRoots roots({r.root.string()});
  const Refusal missing = refusal_of(roots, "missing.7z");
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.code, "path_not_importable");
  EXPECT_EQ(missing.parameter, "path");
  for (const std::string& path : std::vector<std::string>{
           "/etc/shadow", "/etc/passwd", "../../etc/passwd", "../outside.7z", "out_link.7z", "up",
           "up/outside.7z", "/dev/zero", "zero", "fifo.7z", "/proc/self/environ", "",
           (r.dir.path / "outside.7z").string(), std::string("a.7z\0x", 6)})
    EXPECT_EQ(refusal_of(roots, path), missing) << path;
}

TEST(ImportRoots, WithoutRootsPathImportsAreRefused) {
  const ImportRoots none;
  EXPECT_TRUE(none.empty());
  const Refusal refused = refusal_of(none, "/etc/passwd");
  EXPECT_EQ(refused.status, 403);
  EXPECT_EQ(refused.code, "path_imports_disabled");
  EXPECT_EQ(refused.parameter, "path");
}

TEST(ImportRoots, ARootThatIsNotAFolderIsRefusedAtStart) {
  Roots r;
  EXPECT_THROW(ImportRoots({(r.dir.path / "none").string()}), std::invalid_argument);
  EXPECT_THROW(ImportRoots({(r.root / "a.7z").string()}), std::invalid_argument);
}

}  // namespace
}  // namespace clearsky::api
