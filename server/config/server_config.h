// The server's configuration: command-line options of `clearsky serve` (or the same keys in its
// --config file), with the limits the HTTP layer enforces (docs/conventions.md "One HTTP
// boundary").
//
// clang-format off
// | option               | unit  | default         | meaning                                                                               |
// |----------------------|-------|-----------------|---------------------------------------------------------------------------------------|
// | host, port           |       | 127.0.0.1, 8080 | where to listen (port 0: any free port)                                               |
// | role                 |       | writer          | writer: owns the database (data endpoints, scheduler); query: no database (sky only)  |
// | db                   | path  | var/clearsky.db | SQLite database (its parent directory is created); not with role query                |
// | cache_dir            | path  | var/cache       | disk cache of model tables                                                            |
// | threads              |       | 0               | most HTTP workers (started on demand, a worker per open connection); 0: 512           |
// | max_queued           |       | 256             | accepted connections waiting for a worker (the acceptor waits beyond)                 |
// | listen_backlog       |       | 4096            | connections the kernel holds before accept (listen(2), capped by net.core.somaxconn)  |
// | payload_max_bytes    | byte  | 8 MiB           | request body limit (413 beyond)                                                       |
// | read/write_timeout_s | s     | 10 / 30         | longest wait for one read / one blocked write                                         |
// | request_head_timeout_s | s   | 10              | a request head (line and headers) must arrive whole within this (slowloris)            |
// | min_send_rate_bytes  | B/s   | 4096            | an answer slower than this on average (after the grace) is cut (slow readers); 0: off |
// | send_rate_grace_s    | s     | 10              | time an answer has before min_send_rate_bytes applies                                 |
// | keep_alive_max_count |       | 1000            | requests per keep-alive connection                                                    |
// | keep_alive_timeout_s | s     | 5               | idle keep-alive connection lifetime                                                   |
// | max_views            |       | 10000           | views per radiance/rgb batch (413 beyond)                                             |
// | max_wavelengths      |       | 2000            | wavelengths per request (413 beyond)                                                  |
// | max_skydome_size     | pixel | 4096            | skydome size limit (413 beyond)                                                       |
// | table_capacity       |       | 16              | non-default table configurations kept / pending                                       |
// | build_wait_ms        | ms    | 2000            | how long a request waits for a table or per-sun build before 503                      |
// | retry_after_s        | s     | 5               | Retry-After of a 503                                                                  |
// | table_memory_bytes   | byte  | 1 GiB           | tables kept or being built, defaults included (503 beyond)                            |
// | sun_state_memory_bytes | byte | 256 MiB        | per-sun states kept per configuration of Haber and Nishita96 (LRU beyond)             |
// | build_rate           |       | 30              | table builds one client address may trigger per build_rate_window_s (429 beyond); 0: off |
// | build_rate_window_s  | s     | 60              | the window of build_rate                                                              |
// | answer_memory_bytes  | byte  | 256 MiB         | answer buffers in flight, every worker together (a skydome's band; 503 beyond)        |
// | builder_threads      |       | 1               | concurrent builds of the tables queued at start                                       |
// | token                |       | (none)          | bearer token of the write endpoints; none: CLEARSKY_TOKEN, else writes off            |
// | token_file           | path  | (none)          | file holding the token (systemd LoadCredential=); instead of token                    |
// | drain_delay_s        | s     | 0               | after SIGTERM, /readyz answers 503 and every answer closes its connection this long    |
// |                      |       |                 | before the listening socket closes (load balancers see the replica leave)             |
// | drain_timeout_s      | s     | 30              | then requests in flight (streamed skydomes included) have this long; the rest are cut |
// | models               |       | (all)           | serve only these model ids                                                            |
// | max_upload_bytes     | byte  | 1 GiB           | dataset upload limit (413 beyond); other routes: payload_max_bytes                    |
// | import_workers       |       | 1               | background import threads (never HTTP workers)                                        |
// | import_queue         |       | 8               | imports waiting for a worker (503 beyond)                                             |
// | import_roots         | path  | (none)          | folders path= imports may read (repeatable --import-root); none: path imports refused |
// | max_entry_bytes      | byte  | 16 MiB          | bytes read from one archive entry or folder file of an import (import fails, 413)     |
// | max_import_bytes     | byte  | 256 MiB         | bytes read from all the entries of one import (import fails, 413)                     |
// | evaluation_workers   |       | min(2, cores)   | background evaluation threads (never HTTP workers)                                    |
// | evaluation_queue     |       | 16              | evaluations waiting for a worker (503 beyond)                                         |
// | cors_origins         |       | (none)          | origins browsers may call the API from ("*": any; docs/http-api.md)                   |
// | viewer_dir           | path  | viewer/ by the executable | the browser viewer served at / (docs/viewer.md); empty or no index.html: none |
// | prebuild_three       |       | true            | also build each model on the 3-wavelength grid of rgb method=three                    |
// | quality              |       | standard        | the quality level of sky requests without quality= (draft, standard, reference)       |
// | prebuild             |       | (defaults)      | model:level pairs built at start (docs/quality-levels.md); empty: each default + drafts |
// threads + max_queued is at most 896: cpp-httplib 0.11.4 as Debian builds it uses select(2)
// and answers 500 on a connection whose descriptor is 1024 or more (docs/deployment.md).
// clang-format on
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace clearsky::server {

// What a server instance is for (docs/deploy.md "Roles"): one writer owns the SQLite database;
// query replicas serve the sky endpoints from the shared table cache and have no database.
enum class ServerRole { writer, query };

// Two evaluation workers where the machine has two cores or more (a job and a user's
// evaluation, or two models' runs, at once), one on a single core.
inline unsigned default_evaluation_workers() {
  return std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
}

struct ServerConfig {
  std::string host = "127.0.0.1";
  int port = 8080;
  ServerRole role = ServerRole::writer;
  std::string db_path = "var/clearsky.db";
  std::string cache_dir = "var/cache";
  std::vector<std::string> models;  // empty: every registered model
  unsigned threads = 0;
  std::size_t max_queued = 256;
  int listen_backlog = 4096;
  std::size_t payload_max_bytes = 8u << 20;
  std::size_t max_upload_bytes = std::size_t{1} << 30;
  int read_timeout_s = 10;
  int write_timeout_s = 30;
  int request_head_timeout_s = 10;
  std::size_t min_send_rate_bytes = 4096;
  int send_rate_grace_s = 10;
  std::size_t keep_alive_max_count = 1000;
  int keep_alive_timeout_s = 5;
  std::size_t max_views = 10000;
  std::size_t max_wavelengths = 2000;
  int max_skydome_size = 4096;
  std::size_t table_capacity = 16;
  std::size_t table_memory_bytes = std::size_t{1} << 30;
  std::size_t sun_state_memory_bytes = std::size_t{256} << 20;
  std::size_t build_rate = 30;
  int build_rate_window_s = 60;
  std::size_t answer_memory_bytes = std::size_t{256} << 20;
  int build_wait_ms = 2000;
  int retry_after_s = 5;
  unsigned builder_threads = 1;
  bool prebuild_three = true;
  std::string quality = "standard";
  std::vector<std::string> prebuild;  // "model:level"; empty: docs/quality-levels.md
  std::string token;
  std::string token_file;  // empty: none
  int drain_delay_s = 0;
  int drain_timeout_s = 30;
  unsigned evaluation_workers = default_evaluation_workers();
  std::size_t evaluation_queue = 16;
  unsigned import_workers = 1;
  std::size_t import_queue = 8;
  std::vector<std::string> import_roots;  // empty: path imports refused
  std::int64_t max_entry_bytes = std::int64_t{16} << 20;
  std::int64_t max_import_bytes = std::int64_t{256} << 20;
  std::vector<std::string> cors_origins;  // empty: no cross-origin access
  // The browser viewer's folder; empty: none (clearsky serve's default: viewer/ next to the
  // executable, where deploy/build.sh builds it).
  std::string viewer_dir;

  // The most workers threads resolves to.
  unsigned worker_threads() const;
  // Throws std::invalid_argument when threads + max_queued could give a connection a descriptor
  // cpp-httplib cannot serve (the connection slots must stay below FD_SETSIZE).
  void check_connection_slots() const;
  // The largest body any route reads: cpp-httplib's (single) payload limit.
  std::size_t body_limit_bytes() const;
};

}  // namespace clearsky::server
