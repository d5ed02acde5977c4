// The disk table cache shared by several writers (docs/deploy.md "Shared table cache"): two
// real processes (fork) storing the same entry over and over while a third reads it never leave
// or read a torn file, and leave no temporary file behind; two writers with the same process id
// (replicas in containers are often all process 1; here two caches of one process) storing at
// once leave a complete entry (the earlier temporary name, <entry>.tmp.<pid>.<counter>, was the
// same for both, and whether that tore the entry depended on timing: a regression check, not a
// reproduction); temporary files of killed writers are removed once stale.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "server/cache/file_table_cache.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

constexpr const char* kKey = "bruneton|v9|shared-cache-test";

// A payload of 8 MiB whose every byte depends on the writer and the offset, so that any mix of
// two writers' bytes is seen.
std::string payload_of(char writer) {
  std::string p(std::size_t{8} << 20, '\0');
  for (std::size_t i = 0; i < p.size(); ++i)
    p[i] = static_cast<char>((static_cast<unsigned char>(writer) * 131 + i * 7919) % 251);
  return p;
}

std::size_t files_in(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(FileTableCacheProcesses, TwoWritersAndAReaderNeverSeeATornEntry) {
  clearsky::testing::TempDir temp;
  const std::string a = payload_of('a'), b = payload_of('b');
  const auto writer = [&](const std::string& payload) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      FileTableCache cache(temp.path);
      for (int i = 0; i < 25; ++i) cache.store(kKey, payload);
      ::_exit(cache.load(kKey).has_value() ? 0 : 3);
    }
    return pid;
  };
  const pid_t first = writer(a), second = writer(b);
  ASSERT_GT(first, 0);
  ASSERT_GT(second, 0);

  FileTableCache reader(temp.path);
  int loads = 0, hits = 0, torn = 0;
  int status_first = -1, status_second = -1;
  bool first_done = false, second_done = false;
  while (!first_done || !second_done) {
    if (!first_done) first_done = ::waitpid(first, &status_first, WNOHANG) == first;
    if (!second_done) second_done = ::waitpid(second, &status_second, WNOHANG) == second;
    const std::optional<std::string> loaded = reader.load(kKey);
    ++loads;
    if (loaded) {
      ++hits;
      if (*loaded != a && *loaded != b) ++torn;
    }
  }
  EXPECT_TRUE(WIFEXITED(status_first) && WEXITSTATUS(status_first) == 0);
  EXPECT_TRUE(WIFEXITED(status_second) && WEXITSTATUS(status_second) == 0);
  EXPECT_EQ(torn, 0) << "of " << hits << " hits in " << loads << " loads";
  const std::optional<std::string> last = reader.load(kKey);
  ASSERT_TRUE(last.has_value());
  EXPECT_TRUE(*last == a || *last == b);
  // The entry alone: every temporary file was renamed.
  EXPECT_EQ(files_in(temp.path), 1u);
}

TEST(FileTableCacheProcesses, WritersWithTheSameProcessIdLeaveACompleteEntry) {
  clearsky::testing::TempDir temp;
  const std::string a = payload_of('a'), b = payload_of('b');
  // Two caches of one process: the same process id, each with its own state, as two replicas
  // that are each process 1 of their container.
  FileTableCache one(temp.path), two(temp.path);
  for (int round = 0; round < 10; ++round) {
    std::thread t1([&] { one.store(kKey, a); });
    std::thread t2([&] { two.store(kKey, b); });
    t1.join();
    t2.join();
    const std::optional<std::string> loaded = one.load(kKey);
    ASSERT_TRUE(loaded.has_value()) << "round " << round << ": the entry was torn";
    EXPECT_TRUE(*loaded == a || *loaded == b);
  }
  EXPECT_EQ(files_in(temp.path), 1u);
}

TEST(FileTableCacheProcesses, ATemporaryFileOfAKilledWriterIsRemovedOnceStale) {
  clearsky::testing::TempDir temp;
  FileTableCache cache(temp.path);
  cache.store(kKey, "entry");
  const std::filesystem::path fresh =
      cache.path_of(kKey).string() + FileTableCache::kTemporaryInfix + "fresh1";
  const std::filesystem::path stale =
      cache.path_of(kKey).string() + FileTableCache::kTemporaryInfix + "stale1";
  std::ofstream(fresh) << "half";
  std::ofstream(stale) << "half";
  std::filesystem::last_write_time(stale, std::filesystem::file_time_type::clock::now() -
                                              FileTableCache::kStaleTemporaryAge -
                                              std::chrono::seconds(60));
  // Opening the folder again (a restarted writer) removes the stale one only: the fresh one may
  // belong to a writer still at work.
  FileTableCache reopened(temp.path);
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(fresh));
  EXPECT_EQ(reopened.load(kKey), std::optional<std::string>("entry"));
}

}  // namespace
}  // namespace clearsky::server
