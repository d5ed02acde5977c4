// `clearsky serve`: the HTTP service. Options (or the same keys in the [serve] section of
// `clearsky --config FILE serve`, an INI/TOML file) fill ServerConfig
// (server/config/server_config.h). At start the default tables of every registered model are loaded
// from --cache-dir or built in the background, with progress in the log; /healthz answers at once,
// /readyz once they are ready. SIGINT/SIGTERM stop the server gracefully.
#include <pthread.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "api/datasets/upload_spool.h"
#include "api/imports/imports_api.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/registry.h"
#include "server/cache/file_table_cache.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "server/http/http_server.h"
#include "server/memory/heap_bounds.h"
#include "server/scheduler/scheduler.h"
#include "storage/repositories/evaluation_run_repository.h"

namespace clearsky::cli {

namespace {

// The registered models, or those named (--models), in registry order.
std::vector<ModelFactory> served_models(const std::vector<std::string>& ids) {
  const auto all = registered_models();
  if (ids.empty()) return {all.begin(), all.end()};
  for (const std::string& id : ids)
    if (find_model(id) == nullptr) throw CLI::ValidationError("--models", "no model " + id);
  std::vector<ModelFactory> chosen;
  for (const ModelFactory& f : all)
    if (std::find(ids.begin(), ids.end(), f.descriptor->id) != ids.end()) chosen.push_back(f);
  return chosen;
}

void run_server(const server::ServerConfig& config, const std::string& software_version) {
  // Before anything starts: too many connection slots for cpp-httplib's select(2).
  config.check_connection_slots();
  // Signals are taken by one thread with sigwait (a handler may not call into the server).
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  // Before any other thread: each thread gets a malloc arena (server/memory/heap_bounds.h).
  spdlog::info("memory: {}", server::bound_heap_arenas());

  // The database is opened (created and migrated by the storage layer) at start, so that a
  // bad --db fails here rather than at the first request that needs it.
  const storage::Database database = open_cli_database(config.db_path);
  server::FileTableCache cache(config.cache_dir);
  server::Metrics metrics;
  cache.set_observer([&metrics](bool hit) { metrics.observe_cache_lookup(hit); });

  server::TableStore::Options options;
  options.capacity = config.table_capacity;
  options.memory_budget_bytes = config.table_memory_bytes;
  options.build_wait = std::chrono::milliseconds(config.build_wait_ms);
  options.retry_after_s = config.retry_after_s;
  options.builder_threads = config.builder_threads;
  options.cache = &cache;
  const std::vector<ModelFactory> registered = served_models(config.models);
  server::TableStore tables(registered, options);
  tables.set_build_observer([&metrics](const std::string& id, double seconds, bool from_cache) {
    metrics.observe_build(id, seconds, from_cache);
  });
  tables.start_default_builds();
  if (config.prebuild_three) {
    // The paper's 3-wavelength colour method needs each model on its 3-point grid.
    const ThreeWavelengthRgb three;
    ModelConfig on_three_points;
    on_three_points.wavelengths = three.grid();
    for (const ModelFactory& f : tables.factories()) {
      if (f.descriptor->min_wavelength_nm <= on_three_points.wavelengths[0] &&
          f.descriptor->max_wavelength_nm >= on_three_points.wavelengths[2]) {
        tables.prebuild(f, on_three_points);
      }
    }
  }

  // The data endpoints: runs a crash interrupted are marked failed first, and their tickets
  // interrupted with the models they had still queued; then evaluations go to their own
  // workers and the scheduler resumes from the jobs table.
  {
    storage::Database db = storage::Database::open(config.db_path);
    const int interrupted = storage::EvaluationRunRepository(db).fail_unfinished(
        "interrupted: the server stopped during the run");
    if (interrupted > 0)
      spdlog::warn("{} evaluation runs were interrupted; marked failed", interrupted);
    const int tickets = api::interrupt_unfinished_tickets(db);
    if (tickets > 0)
      spdlog::warn("{} evaluation tickets were interrupted; marked interrupted", tickets);
    const int imports = api::fail_interrupted_imports(db);
    if (imports > 0) spdlog::warn("{} imports were interrupted; marked failed", imports);
  }
  const std::filesystem::path db_path = config.db_path;
  const auto open_database = [db_path] { return storage::Database::open(db_path); };
  api::EvaluationPool evaluations(open_database, registered,
                                  {config.evaluation_workers, config.evaluation_queue, 1});
  const server::WriteAuthorizer auth = server::WriteAuthorizer::from_option_or_environment(
      config.token, std::getenv("CLEARSKY_TOKEN"));
  if (!auth.writes_enabled())
    spdlog::warn("no token (--token or CLEARSKY_TOKEN): write endpoints are disabled");
  api::DataServices data;
  data.db_path = db_path;
  data.upload_dir =
      (db_path.has_parent_path() ? db_path.parent_path() : std::filesystem::path(".")) / "uploads";
  if (const int stale = api::remove_stale_uploads(data.upload_dir); stale > 0)
    spdlog::info("removed {} upload files left by an earlier process", stale);
  data.upload_max_bytes = config.max_upload_bytes;
  api::ImportPoolOptions import_options;
  import_options.workers = config.import_workers;
  import_options.max_queued = config.import_queue;
  import_options.log = [](std::int64_t id, bool ok, const std::string& message) {
    if (ok)
      spdlog::info("import {} succeeded {}", id, message);
    else
      spdlog::warn("import {} failed {}", id, message);
  };
  api::ImportPool imports(open_database, import_options);
  data.imports = &imports;
  data.evaluations = &evaluations;
  data.models = registered;
  data.software_version = software_version;
  server::Scheduler scheduler(open_database, evaluations, software_version);
  scheduler.start();

  server::HttpServer http(config, tables, metrics);
  http.add_data_services(data, auth);
  const int port = http.bind();
  spdlog::info(
      "clearsky serving on http://{}:{} (at most {} workers, {} models, cache {}, database {})",
      config.host, port, config.worker_threads(), registered.size(), config.cache_dir,
      config.db_path);

  std::thread signal_thread([&] {
    int received = 0;
    sigwait(&signals, &received);
    spdlog::info("signal {}: stopping", received);
    http.stop();
  });
  std::atomic<bool> done{false};
  std::thread progress_thread([&] {
    while (!done && !tables.ready()) {
      for (int i = 0; i < 50 && !done; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      for (const ModelFactory& f : tables.factories()) {
        const api::ModelState s = tables.default_state(f);
        if (s.status == api::ModelState::Status::precomputing) {
          spdlog::info("tables: {} {:.0f}% ({})", f.descriptor->id, 100.0 * s.progress, s.stage);
        }
      }
    }
    if (tables.ready()) spdlog::info("tables: every model is ready");
  });

  http.listen();
  done = true;
  progress_thread.join();
  // The signal thread waits for a signal; after a stop from elsewhere, send it one.
  pthread_kill(signal_thread.native_handle(), SIGTERM);
  signal_thread.join();
  scheduler.stop();
}

}  // namespace

void add_serve_command(CLI::App& app, const std::string& software_version) {
  auto* command = app.add_subcommand("serve", "Serve the HTTP API");
  auto config = std::make_shared<server::ServerConfig>();
  // The configuration file belongs to the top-level command (CLI11 reads it there); the serve
  // options are its [serve] section.
  app.set_config(
      "--config", "",
      "INI/TOML file; `clearsky serve` reads its [serve] section (keys: the long option names)");
  command->add_option("--host", config->host, "Address to listen on")->capture_default_str();
  command->add_option("--port", config->port, "Port (0: any free port)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  add_database_option(*command, config->db_path);
  command->add_option("--cache-dir", config->cache_dir, "Disk cache of model tables")
      ->capture_default_str();
  command->add_option("--models", config->models, "Serve only these models (default: all)")
      ->delimiter(',');
  command
      ->add_option("--threads", config->threads,
                   "Most HTTP worker threads, started on demand, one per open connection (0: 512); "
                   "threads + max-queued <= 896")
      ->capture_default_str();
  command->add_option("--max-queued", config->max_queued, "Connections waiting for a worker")
      ->capture_default_str();
  command
      ->add_option("--listen-backlog", config->listen_backlog, "Pending connections before accept")
      ->capture_default_str();
  command
      ->add_option("--payload-max-bytes", config->payload_max_bytes,
                   "Request body limit (all routes but the dataset upload)")
      ->capture_default_str();
  command
      ->add_option("--max-upload-bytes", config->max_upload_bytes,
                   "Dataset upload limit (POST /v1/datasets)")
      ->capture_default_str();
  command->add_option("--read-timeout", config->read_timeout_s, "Socket read timeout, s")
      ->capture_default_str();
  command->add_option("--write-timeout", config->write_timeout_s, "Socket write timeout, s")
      ->capture_default_str();
  command
      ->add_option("--request-head-timeout", config->request_head_timeout_s,
                   "A request head (line and headers) must arrive whole within this, s")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--min-send-rate", config->min_send_rate_bytes,
                   "Answers slower than this on average after the grace are cut, bytes/s (0: off)")
      ->capture_default_str();
  command
      ->add_option("--send-rate-grace", config->send_rate_grace_s,
                   "Time an answer has before --min-send-rate applies, s")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--keep-alive-max-count", config->keep_alive_max_count,
                   "Requests per connection")
      ->capture_default_str();
  command
      ->add_option("--keep-alive-timeout", config->keep_alive_timeout_s,
                   "Idle keep-alive timeout, s")
      ->capture_default_str();
  command->add_option("--max-views", config->max_views, "Views per batch")->capture_default_str();
  command->add_option("--max-wavelengths", config->max_wavelengths, "Wavelengths per request")
      ->capture_default_str();
  command->add_option("--max-skydome-size", config->max_skydome_size, "Skydome size limit, pixels")
      ->capture_default_str();
  command
      ->add_option("--table-capacity", config->table_capacity,
                   "Non-default table configurations kept")
      ->capture_default_str();
  command
      ->add_option("--table-memory", config->table_memory_bytes,
                   "Bytes of model tables kept or being built (defaults counted, never evicted)")
      ->capture_default_str();
  command
      ->add_option("--answer-memory", config->answer_memory_bytes,
                   "Bytes of answer buffers in flight, every worker together (a streamed "
                   "skydome's band; 503 beyond)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--build-wait-ms", config->build_wait_ms,
                   "Wait for a table build before 503, ms")
      ->capture_default_str();
  command->add_option("--retry-after", config->retry_after_s, "Retry-After of a 503, s")
      ->capture_default_str();
  command->add_option("--builder-threads", config->builder_threads, "Concurrent table builds")
      ->capture_default_str();
  command
      ->add_option("--prebuild-three", config->prebuild_three,
                   "Also build the 3-wavelength tables of rgb method=three at start")
      ->capture_default_str();
  command->add_option("--token", config->token,
                      "Bearer token of the write endpoints (default: CLEARSKY_TOKEN; none: writes "
                      "disabled)");
  command
      ->add_option("--evaluation-workers", config->evaluation_workers,
                   "Background evaluation threads")
      ->capture_default_str()
      ->check(CLI::Range(1u, 64u));
  command->add_option("--import-workers", config->import_workers, "Background import threads")
      ->capture_default_str()
      ->check(CLI::Range(1u, 16u));
  command
      ->add_option("--import-queue", config->import_queue,
                   "Imports waiting for a worker (503 beyond)")
      ->capture_default_str();
  command
      ->add_option("--evaluation-queue", config->evaluation_queue,
                   "Evaluations waiting for a worker (503 beyond)")
      ->capture_default_str();
  command
      ->add_option("--cors-origin", config->cors_origins,
                   "An origin browsers may call the API from, e.g. https://example.org "
                   "(repeatable; * for any; default: none)")
      ->allow_extra_args(false);
  command->callback([config, software_version] { run_server(*config, software_version); });
}

}  // namespace clearsky::cli
