// The disk table cache: round trip, and every damaged or stale file is a miss, never trusted.
#include "server/cache/file_table_cache.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

#include "models/core/content_hash.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

class FileTableCacheTest : public ::testing::Test {
 protected:
  std::string read(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
  }
  void write(const std::filesystem::path& p, const std::string& s) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << s;
  }
  clearsky::testing::TempDir temp;
  const std::filesystem::path& dir = temp.path;
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
  version[8] = static_cast<char>(FileTableCache::kFormatVersion + 1);  // another format version
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

// A file of format version 1 (the same header with an FNV-1a 64 checksum of the payload), as
// written by earlier servers: a miss, never read as a version 2 file, and replaced on store.
TEST_F(FileTableCacheTest, VersionOneFilesWithAnFnvChecksumAreRebuilt) {
  FileTableCache cache(dir);
  const std::string key = "bruneton-a9ee3c37742c94db";
  const std::string payload = "a table written by format version 1";
  std::string file = "CSKYTBL\n";
  const auto put = [&file](std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) file.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  };
  put(1, 4);
  put(key.size(), 4);
  file += key;
  put(payload.size(), 8);
  put(fnv1a_64(payload), 8);
  file += payload;
  write(cache.path_of(key), file);
  EXPECT_FALSE(cache.load(key).has_value());

  cache.store(key, payload);
  EXPECT_EQ(cache.load(key), payload);
  EXPECT_EQ(static_cast<unsigned char>(read(cache.path_of(key))[8]),
            FileTableCache::kFormatVersion);
}

// The file name is the FNV-1a hash of the key (here the default Bruneton key), as in version 1,
// so that an old file is found (and replaced) rather than left behind.
TEST_F(FileTableCacheTest, FileNamesAreTheFnvHashOfTheKey) {
  FileTableCache cache(dir);
  EXPECT_EQ(cache.path_of("bruneton-a9ee3c37742c94db"), dir / "2c0551424c6a90ba.table");
}

// What the default logger writes while the object lives (the server logs through it).
class CapturedLog {
 public:
  CapturedLog() : previous_(spdlog::default_logger()) {
    auto logger = std::make_shared<spdlog::logger>(
        "captured", std::make_shared<spdlog::sinks::ostream_sink_mt>(text_));
    logger->set_level(spdlog::level::info);
    spdlog::set_default_logger(logger);
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  std::string text() const { return text_.str(); }

 private:
  std::shared_ptr<spdlog::logger> previous_;
  std::ostringstream text_;
};

// A damaged file is rebuilt with a log line naming it and saying what is wrong (it used to be
// a silent miss: the operator saw only a start that took the time of a build).
TEST_F(FileTableCacheTest, DamagedFilesAreLoggedWithTheirReason) {
  FileTableCache cache(dir);
  const std::string key = "bruneton-a9ee3c37742c94db";
  cache.store(key, std::string(1000, 'x'));
  const auto path = cache.path_of(key);
  const std::string good = read(path);
  const std::pair<std::string, std::string> damages[] = {
      {good.substr(0, good.size() - 100), "is truncated in its payload"},
      {good.substr(0, 20), "is truncated in its key"},
      {good.substr(0, 5), "is truncated before its magic"},
      {"NOTATABLE" + good.substr(9), "does not start with the table cache magic"},
      {good + "trailing", "has bytes after its payload"},
  };
  for (const auto& [content, reason] : damages) {
    SCOPED_TRACE(reason);
    write(path, content);
    CapturedLog log;
    EXPECT_FALSE(cache.load(key).has_value());
    const std::string text = log.text();
    EXPECT_NE(text.find(path.string() + " " + reason), std::string::npos) << text;
    EXPECT_NE(text.find("rebuilding"), std::string::npos) << text;
  }
  // A missing file is an ordinary miss: nothing to say.
  std::filesystem::remove(path);
  CapturedLog log;
  EXPECT_FALSE(cache.load(key).has_value());
  EXPECT_EQ(log.text(), "");
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
