// Durability of the API's writes (docs/architecture.md "Storage and durability") on a database
// file: a process killed with SIGKILL during an evaluation leaves a run that start-up marks failed,
// and readers on their own connections during writes see whole datasets only (WAL). The kill during
// an import is tested in tests/storage/importers/kider_importer_test.cpp; a job due during downtime
// in tests/server/scheduler/scheduler_test.cpp.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include "api/datasets/datasets_api.h"
#include "api/evaluation/evaluation_pool.h"
#include "api/evaluation/evaluations_api.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

double sky(const ViewDirection&, double) { return 0.05; }

void add_synthetic_dataset(storage::Database& db, const std::string& name, int captures) {
  storage::Transaction t(db);
  const auto dataset = storage::DatasetRepository(db).find_or_create(name, "kider2014");
  for (int i = 0; i < captures; ++i) {
    MeasuredCapture c = testing::synthetic_capture(sky);
    c.label = std::string("c").append(std::to_string(i));
    c.unix_time_utc_s += 60.0 * i;
    storage::CaptureRepository(db).insert(dataset, c, std::string("h").append(std::to_string(i)),
                                          "test");
  }
  t.commit();
}

const ModelDescriptor& killer_descriptor() {
  static const ModelDescriptor d = [] {
    ModelDescriptor x = testing::test_descriptor();
    x.id = "killer";
    return x;
  }();
  return d;
}

TEST(Durability, KilledDuringAnEvaluationTheRunIsMarkedFailedAtStartUp) {
  clearsky::testing::TempDir dir;
  const auto path = dir.path / "db.sqlite";
  {
    storage::Database db = storage::open_database(path);
    add_synthetic_dataset(db, "synthetic", 2);
  }
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The model's precomputation kills the process: the run row is already written.
    static const std::vector<ModelFactory> factories = {
        {&killer_descriptor(),
         [](const ModelConfig&, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
           ::kill(::getpid(), SIGKILL);
           return nullptr;
         }}};
    try {
      storage::Database db = storage::open_database(path);
      api::EvaluationRequest request;
      request.dataset = "synthetic";
      request.models = {"killer"};
      api::run_evaluation(db, request, factories);
    } catch (...) {
    }
    ::_exit(3);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  storage::Database db = storage::open_database(path);
  storage::EvaluationRunRepository runs(db);
  auto listed = runs.list(1);
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0].status, "running");
  // What start-up does.
  EXPECT_EQ(runs.fail_unfinished("interrupted: the server stopped during the run"), 1);
  const auto shown = api::show_evaluation(db, listed[0].id);
  EXPECT_EQ(shown["status"], "failed");
  EXPECT_EQ(shown["error"], "interrupted: the server stopped during the run");
  EXPECT_TRUE(shown["captures"].empty());
  EXPECT_EQ(runs.fail_unfinished("again"), 0);
}

TEST(Durability, ReadersDuringWritesSeeWholeDatasets) {
  clearsky::testing::TempDir dir;
  const auto path = dir.path / "db.sqlite";
  storage::open_database(path);
  std::atomic<bool> done{false};
  std::atomic<int> reads{0};
  std::atomic<int> partial{0};
  std::thread reader([&] {
    storage::Database db = storage::open_database(path);
    while (!done) {
      for (const auto& d : api::list_datasets(db).items) {
        if (d["captures"] != 4 || d["samples"] != 4 * 81) ++partial;
      }
      ++reads;
    }
  });
  {
    storage::Database db = storage::open_database(path);
    for (int i = 0; i < 10; ++i) {
      add_synthetic_dataset(db, "d", 4);
      api::delete_dataset(db, "d");
    }
  }
  while (reads < 5) std::this_thread::yield();
  done = true;
  reader.join();
  EXPECT_EQ(partial, 0);
  EXPECT_GE(reads, 5);
}

}  // namespace
}  // namespace clearsky::server
