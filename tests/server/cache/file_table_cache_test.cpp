// The disk table cache: round trip, and every damaged or stale file is a miss, never trusted.
#include "server/cache/file_table_cache.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace clearsky::server {
namespace {

class FileTableCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("clearsky_cache_test_" + std::to_string(std::random_device{}()));
    std::filesystem::remove_all(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string read(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
  }
  void write(const std::filesystem::path& p, const std::string& s) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << s;
  }
  std::filesystem::path dir;
};

TEST_F(FileTableCacheTest, RoundTripsBinaryPayloads) {
  FileTableCache cache(dir);
  std::string payload(100000, '\0');
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>(i * 7919 % 256);
  EXPECT_FALSE(cache.load("bruneton|1|grid").has_value());
  cache.store("bruneton|1|grid", payload);
  EXPECT_EQ(cache.load("bruneton|1|grid"), payload);
  // Only the entry remains: the temporary file was renamed.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST_F(FileTableCacheTest, CorruptTruncatedOrStaleFilesAreMisses) {
  FileTableCache cache(dir);
  const std::string key = "model|1|config";
  cache.store(key, "0123456789abcdef");
  const auto path = cache.path_of(key);
  const std::string good = read(path);

  std::string flipped = good;
  flipped.back() ^= 0x01;  // one payload bit
  write(path, flipped);
  EXPECT_FALSE(cache.load(key).has_value());

  write(path, good.substr(0, good.size() - 3));  // truncated
  EXPECT_FALSE(cache.load(key).has_value());

  std::string version = good;
  version[8] = 2;  // another format version
  write(path, version);
  EXPECT_FALSE(cache.load(key).has_value());

  // A file holding another key under this key's name (a stale or colliding entry).
  FileTableCache other(dir);
  other.store("model|1|other", "xyz");
  std::filesystem::copy_file(other.path_of("model|1|other"), path,
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_FALSE(cache.load(key).has_value());

  // Storing again repairs it.
  cache.store(key, "fresh");
  EXPECT_EQ(cache.load(key), "fresh");
}

TEST_F(FileTableCacheTest, ReportsHitsAndMisses) {
  FileTableCache cache(dir);
  int hits = 0, misses = 0;
  cache.set_observer([&](bool hit) { (hit ? hits : misses)++; });
  cache.load("a");
  cache.store("a", "1");
  cache.load("a");
  EXPECT_EQ(hits, 1);
  EXPECT_EQ(misses, 1);
}

}  // namespace
}  // namespace clearsky::server
