// `clearsky serve`: the HTTP service. Options (or the same keys in the [serve] section of
// `clearsky --config FILE serve`, an INI/TOML file) fill ServerConfig
// (server/config/server_config.h). At start the default tables of every registered model are loaded
// from --cache-dir or built in the background, with progress in the log; /healthz answers at once,
// /readyz once they are ready. `--role query` runs a replica without a database (the data
// endpoints answer 404 no_database, no scheduler); SIGINT/SIGTERM drain the server: /readyz 503,
// --drain-delay, then requests in flight get --drain-timeout (docs/deploy.md).
#include <pthread.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <span>
#include <thread>

#include "api/datasets/upload_spool.h"
#include "api/fits/fit_pool.h"
#include "api/imports/imports_api.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/registry.h"
#include "server/auth/token_file.h"
#include "server/cache/file_table_cache.h"
#include "server/cli/aerosol_inversion_source_installed.h"
#include "server/cli/commands.h"
#include "server/cli/database_option.h"
#include "server/http/http_server.h"
#include "server/memory/heap_bounds.h"
#include "server/scheduler/scheduler.h"
#include "server/tables/day_sun_states.h"
#include "server/tables/start_builds.h"
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

// The writer's data services (docs/deploy.md "Roles"): the database opened (created and
// migrated) at start, so that a bad --db fails here rather than at the first request; runs and
// imports a crash interrupted marked failed (fits interrupted); the evaluation, import and fit
// pools; the scheduler.
class WriterServices {
 public:
  WriterServices(const server::ServerConfig& config, const api::ImportRoots& import_roots,
                 std::span<const ModelFactory> models, const std::string& software_version)
      : database_(open_and_recover(config.db_path)),
        db_path_(config.db_path),
        evaluations_(open_database(), models,
                     {config.evaluation_workers, config.evaluation_queue, 1}),
        imports_(open_database(), import_options(config)),
        fits_(open_database(), {1, config.evaluation_queue, 1}) {
    data_.db_path = db_path_;
    data_.upload_dir =
        (db_path_.has_parent_path() ? db_path_.parent_path() : std::filesystem::path(".")) /
        "uploads";
    if (const int stale = api::remove_stale_uploads(data_.upload_dir); stale > 0)
      spdlog::info("removed {} upload files left by an earlier process", stale);
    data_.upload_max_bytes = config.max_upload_bytes;
    data_.import_roots = import_roots;
    for (const std::filesystem::path& root : data_.import_roots.roots())
      spdlog::info("path imports may read {}", root.string());
    data_.imports = &imports_;
    data_.evaluations = &evaluations_;
    data_.fits = &fits_;
    data_.models = models;
    data_.software_version = software_version;
    scheduler_.emplace(open_database(), evaluations_, software_version);
    scheduler_->start();
  }
  ~WriterServices() { scheduler_->stop(); }
  WriterServices(const WriterServices&) = delete;
  WriterServices& operator=(const WriterServices&) = delete;

  const api::DataServices& data() const { return data_; }
  // Evaluations and jobs take their models from the server's tables (EvaluationRequest::provider).
  void use_models_of(const api::ModelProvider& tables) { evaluations_.set_provider(&tables); }

 private:
  // Opens (creates, migrates) the database, then marks failed the runs and imports a crash
  // interrupted, and interrupted their tickets with the models they had still queued, before
  // any worker starts.
  static storage::Database open_and_recover(const std::string& path) {
    storage::Database database = open_cli_database(path);
    storage::Database db = storage::Database::open(path);
    const int interrupted = storage::EvaluationRunRepository(db).fail_unfinished(
        "interrupted: the server stopped during the run");
    if (interrupted > 0)
      spdlog::warn("{} evaluation runs were interrupted; marked failed", interrupted);
    const int tickets = api::interrupt_unfinished_tickets(db);
    if (tickets > 0)
      spdlog::warn("{} evaluation tickets were interrupted; marked interrupted", tickets);
    const int imports = api::fail_interrupted_imports(db);
    if (imports > 0) spdlog::warn("{} imports were interrupted; marked failed", imports);
    const int fits = api::interrupt_unfinished_fits(db);
    if (fits > 0) spdlog::warn("{} fits were interrupted; marked interrupted", fits);
    return database;
  }
  api::EvaluationPool::OpenDatabase open_database() const {
    return [path = db_path_] { return storage::Database::open(path); };
  }
  static api::ImportPoolOptions import_options(const server::ServerConfig& config) {
    api::ImportPoolOptions options;
    options.workers = config.import_workers;
    options.max_queued = config.import_queue;
    options.limits.max_entry_bytes = config.max_entry_bytes;
    options.limits.max_import_bytes = config.max_import_bytes;
    options.log = [](std::int64_t id, bool ok, const std::string& message) {
      if (ok)
        spdlog::info("import {} succeeded {}", id, message);
      else
        spdlog::warn("import {} failed {}", id, message);
    };
    return options;
  }

  storage::Database database_;
  std::filesystem::path db_path_;
  api::EvaluationPool evaluations_;
  api::ImportPool imports_;
  api::FitPool fits_;
  api::DataServices data_;
  std::optional<server::Scheduler> scheduler_;
};

// The bearer token: --token-file (a credential file), else --token, else CLEARSKY_TOKEN.
server::WriteAuthorizer write_authorizer(const server::ServerConfig& config) {
  if (!config.token_file.empty())
    return server::WriteAuthorizer(server::read_token_file(config.token_file));
  return server::WriteAuthorizer::from_option_or_environment(config.token,
                                                             std::getenv("CLEARSKY_TOKEN"));
}

// Waits until done is true or the time has passed; true when done.
bool wait_for(const std::atomic<bool>& done, std::chrono::seconds time) {
  const auto deadline = std::chrono::steady_clock::now() + time;
  while (!done) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

void run_server(const server::ServerConfig& config, const std::string& software_version) {
  // Before anything starts: too many connection slots for cpp-httplib's select(2).
  config.check_connection_slots();
  const bool writer = config.role == server::ServerRole::writer;
  // A root that is not a folder is refused here, before anything starts.
  const api::ImportRoots import_roots(config.import_roots);
  // Signals are taken by one thread with sigwait (a handler may not call into the server).
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  // Before any other thread: each thread gets a malloc arena (server/memory/heap_bounds.h).
  spdlog::info("memory: {}", server::bound_heap_arenas());
  // A file size limit (RLIMIT_FSIZE) then fails a write with EFBIG, answered 507 like a full
  // disk, instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);

  const server::WriteAuthorizer auth = write_authorizer(config);
  server::FileTableCache cache(config.cache_dir);
  server::Metrics metrics;
  cache.set_observer([&metrics](bool hit) { metrics.observe_cache_lookup(hit); });

  server::TableStore::Options options;
  options.capacity = config.table_capacity;
  options.memory_budget_bytes = config.table_memory_bytes;
  options.sun_state_memory_bytes = config.sun_state_memory_bytes;
  options.build_rate = config.build_rate;
  options.build_rate_window = std::chrono::seconds(config.build_rate_window_s);
  options.build_wait = std::chrono::milliseconds(config.build_wait_ms);
  options.retry_after_s = config.retry_after_s;
  options.builder_threads = config.builder_threads;
  options.cache = &cache;
  const std::vector<ModelFactory> registered = served_models(config.models);
  // The writer's database is opened before the tables start, so that a bad --db fails at once.
  std::optional<WriterServices> services;
  if (writer) services.emplace(config, import_roots, registered, software_version);
  // A query replica installs no inversion source: every aerosols= id but 0 is unknown there.
  std::optional<AerosolInversionSourceInstalled> aerosol_source;
  if (writer) aerosol_source.emplace(config.db_path);
  server::TableStore tables(registered, options);
  // The writer's workers use the tables: they stop (running evaluations end) before the tables go.
  struct StopServicesFirst {
    std::optional<WriterServices>& services;
    ~StopServicesFirst() { services.reset(); }
  } stop_services_first{services};
  if (services) services->use_models_of(tables);
  tables.set_build_observer([&metrics](const std::string& id, double seconds, bool from_cache) {
    metrics.observe_build(id, seconds, from_cache);
  });
  // Drafts first, then the defaults, or exactly --prebuild (docs/quality-levels.md).
  std::vector<std::pair<const ModelFactory*, ModelConfig>> builds;
  try {
    builds = server::start_builds(tables.factories(), config.prebuild);
    tables.start_builds(builds);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--prebuild", e.what());
  }
  // The day's per-sun states of those configurations, in the background once their tables are
  // ready; stopped before the tables go (docs/tables-and-memory.md "The day's per-sun states").
  server::DaySunStates day_sun_states(tables, builds, &cache);
  if (config.prebuild_three) {
    // The paper's 3-wavelength colour method needs each model on its 3-point grid.
    const ThreeWavelengthRgb three;
    ModelConfig on_three_points;
    on_three_points.wavelengths = three.grid();
    for (const ModelFactory& f : tables.factories()) {
      // Not the 3-point tables of a model whose standard waits for its first use either.
      if (f.standard_on_first_use) continue;
      if (f.descriptor->min_wavelength_nm <= on_three_points.wavelengths[0] &&
          f.descriptor->max_wavelength_nm >= on_three_points.wavelengths[2]) {
        tables.prebuild(f, on_three_points);
      }
    }
  }

  if (writer && !auth.writes_enabled())
    spdlog::warn(
        "no token (--token-file, --token or CLEARSKY_TOKEN): write endpoints are disabled");
  server::HttpServer http(config, tables, metrics);
  if (services) http.add_data_services(services->data(), auth);
  http.set_day_sun_states([&day_sun_states] {
    std::map<std::string, std::pair<std::size_t, std::size_t>> progress;
    for (const auto& [id, p] : day_sun_states.progress()) progress[id] = {p.built, p.total};
    return progress;
  });
  const int port = http.bind();
  spdlog::info(
      "clearsky serving on http://{}:{} (role {}, at most {} workers, {} models, cache {}, "
      "database {})",
      config.host, port, writer ? "writer" : "query", config.worker_threads(), registered.size(),
      config.cache_dir, writer ? config.db_path : std::string("none"));
  if (server::ViewerFiles(config.viewer_dir).enabled())
    spdlog::info("browser viewer at http://{}:{}/ from {}", config.host, port, config.viewer_dir);
  else
    spdlog::info(
        "no browser viewer: {} has no index.html (deploy/build.sh builds it; docs/viewer.md)",
        config.viewer_dir.empty() ? std::string("--viewer-dir") : config.viewer_dir);

  // SIGTERM or SIGINT: the graceful drain of docs/deploy.md "Graceful drain".
  std::atomic<bool> listening_ended{false};
  std::thread signal_thread([&] {
    int received = 0;
    sigwait(&signals, &received);
    if (listening_ended) return;
    spdlog::info("signal {}: draining ({} s not ready, then up to {} s for requests in flight)",
                 received, config.drain_delay_s, config.drain_timeout_s);
    http.begin_drain();
    if (wait_for(listening_ended, std::chrono::seconds(config.drain_delay_s))) return;
    // A signal during start-up: stop() acts only once the server listens.
    while (!http.running() && !listening_ended)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    spdlog::info("drain: no longer accepting connections");
    http.stop();
    if (!wait_for(listening_ended, std::chrono::seconds(config.drain_timeout_s))) {
      const std::size_t cut = http.cut_connections();
      spdlog::warn("drain: {} connections still open after {} s were cut", cut,
                   config.drain_timeout_s);
    }
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
  listening_ended = true;
  done = true;
  progress_thread.join();
  // The signal thread waits for a signal; after a stop from elsewhere, send it one.
  pthread_kill(signal_thread.native_handle(), SIGTERM);
  signal_thread.join();
  spdlog::info("stopped: every connection has ended");
}

// The viewer deploy/build.sh builds: viewer/ next to the executable (build/viewer for
// build/clearsky); empty when the executable's path is unknown.
std::string default_viewer_dir() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return (exe.parent_path() / "viewer").string();
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
  auto role = std::make_shared<std::string>("writer");
  command
      ->add_option("--role", *role,
                   "writer: owns the database (data endpoints, scheduler); query: a replica "
                   "without a database serving the sky endpoints")
      ->check(CLI::IsMember({"writer", "query"}))
      ->capture_default_str();
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
      ->add_option("--sun-state-memory", config->sun_state_memory_bytes,
                   "Bytes of per-sun states kept per configuration of Haber and Nishita96 "
                   "(least recently used dropped beyond)")
      ->capture_default_str();
  command
      ->add_option("--build-rate", config->build_rate,
                   "Table builds one client address may trigger per --build-rate-window-s "
                   "(429 beyond; 0: no limit)")
      ->capture_default_str();
  command
      ->add_option("--build-rate-window-s", config->build_rate_window_s,
                   "The window of --build-rate, s")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      ->add_option("--answer-memory", config->answer_memory_bytes,
                   "Bytes of answer buffers in flight, every worker together (a streamed "
                   "skydome's band, a radiance or RGB answer of 64 KiB or more; 503 beyond)")
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
      ->add_option("--quality", config->quality,
                   "Quality level of sky requests without quality= (docs/quality-levels.md)")
      ->check(CLI::IsMember({"draft", "standard", "reference"}))
      ->capture_default_str();
  command
      ->add_option("--prebuild", config->prebuild,
                   "model:level pairs built at start, e.g. bruneton:standard,haber:draft "
                   "(default: every model's draft, then its standard, but measured_aerosols' "
                   "standard, built on its first use; docs/quality-levels.md)")
      ->delimiter(',');
  command
      ->add_option("--prebuild-three", config->prebuild_three,
                   "Also build the 3-wavelength tables of rgb method=three after start, in the "
                   "background (not measured_aerosols')")
      ->capture_default_str();
  auto* token = command->add_option(
      "--token", config->token,
      "Bearer token of the write endpoints (default: CLEARSKY_TOKEN; none: writes disabled); "
      "prefer --token-file, which keeps it off the command line");
  command
      ->add_option("--token-file", config->token_file,
                   "File holding the bearer token, e.g. a systemd credential (%d/token)")
      ->excludes(token);
  command
      ->add_option("--drain-delay", config->drain_delay_s,
                   "After SIGTERM: s during which /readyz answers 503 and answers close their "
                   "connections, before the listening socket closes")
      ->capture_default_str()
      ->check(CLI::Range(0, 3600));
  command
      ->add_option("--drain-timeout", config->drain_timeout_s,
                   "Then: s requests in flight (streamed skydomes too) have to finish; the rest "
                   "are cut")
      ->capture_default_str()
      ->check(CLI::Range(0, 3600));
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
      ->add_option("--import-root", config->import_roots,
                   "A folder POST /v1/datasets?path= may import from (repeatable; default: none, "
                   "path imports refused)")
      ->allow_extra_args(false);
  command
      ->add_option("--max-entry-bytes", config->max_entry_bytes,
                   "Bytes an import may read from one archive entry or folder file")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--max-import-bytes", config->max_import_bytes,
                   "Bytes an import may read from all its entries together")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--evaluation-queue", config->evaluation_queue,
                   "Evaluations waiting for a worker (503 beyond)")
      ->capture_default_str();
  command
      ->add_option("--cors-origin", config->cors_origins,
                   "An origin browsers may call the API from, e.g. https://example.org "
                   "(repeatable; * for any; default: none)")
      ->allow_extra_args(false);
  config->viewer_dir = default_viewer_dir();
  command
      ->add_option("--viewer-dir", config->viewer_dir,
                   "Folder of the browser viewer served at / (docs/viewer.md); empty: none")
      ->capture_default_str();
  command->callback([command, config, role, software_version] {
    config->role = *role == "query" ? server::ServerRole::query : server::ServerRole::writer;
    // One writer owns the database; a query replica must not open (or create) one.
    if (config->role == server::ServerRole::query && command->get_option("--db")->count() > 0)
      throw CLI::ValidationError("--db", "a query replica (--role query) has no database");
    run_server(*config, software_version);
  });
}

}  // namespace clearsky::cli
