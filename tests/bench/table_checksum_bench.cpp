// The table cache's payload checksum (server/cache/table_checksum.h) over the default Bruneton
// table (254 MB), against the FNV-1a 64 of format version 1 that it replaced: the time a cache
// hit spends verifying the file before the model can serve.
//
// The table is read from ./table_checksum_bench_cache/ (a server FileTableCache), and built
// there once when missing (a Bruneton precomputation, minutes). Run alone with
//   clearsky_bench --benchmark_filter=TableChecksum
#include <benchmark/benchmark.h>

#include <string>

#include "models/bruneton/bruneton.h"
#include "models/core/content_hash.h"
#include "server/cache/file_table_cache.h"
#include "server/cache/table_checksum.h"

namespace clearsky {
namespace {

// The server's disk cache, keeping the payload that the model loads or stores.
class PayloadRecorder : public TableCache {
 public:
  explicit PayloadRecorder(const server::FileTableCache& disk) : disk_(disk) {}
  std::optional<std::string> load(const std::string& key) const override {
    std::optional<std::string> bytes = disk_.load(key);
    if (bytes) payload_ = *bytes;
    return bytes;
  }
  void store(const std::string& key, std::string_view bytes) const override {
    payload_ = std::string(bytes);
    disk_.store(key, bytes);
  }
  const std::string& payload() const { return payload_; }

 private:
  const server::FileTableCache& disk_;
  mutable std::string payload_;
};

const std::string& bruneton_table() {
  static const std::string payload = [] {
    const server::FileTableCache disk("table_checksum_bench_cache");
    const PayloadRecorder recorder(disk);
    PrecomputeContext context;
    context.cache = &recorder;
    (void)BrunetonModel::create(bruneton_descriptor(), ModelConfig{}, context);
    return recorder.payload();
  }();
  return payload;
}

void report(benchmark::State& state, std::size_t bytes) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
  state.counters["table_MB"] = static_cast<double>(bytes) / 1e6;
}

void BM_TableChecksumFnv1a(benchmark::State& state) {
  const std::string& table = bruneton_table();
  for (auto _ : state) benchmark::DoNotOptimize(fnv1a_64(table));
  report(state, table.size());
}
BENCHMARK(BM_TableChecksumFnv1a)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TableChecksumXxh3(benchmark::State& state) {
  const std::string& table = bruneton_table();
  for (auto _ : state) benchmark::DoNotOptimize(server::table_checksum(table));
  report(state, table.size());
}
BENCHMARK(BM_TableChecksumXxh3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace clearsky
