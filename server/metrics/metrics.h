// Prometheus metrics of the server (prometheus-cpp, text exposition at GET /metrics):
//  - clearsky_http_requests_total{endpoint, model, status}
//  - clearsky_http_request_duration_seconds{endpoint, model} (histogram)
//  - clearsky_table_bytes{model}: memory of the ready tables (refreshed at each scrape)
//  - clearsky_table_cache_lookups_total{result="hit"|"miss"}: disk table cache
//  - clearsky_table_build_seconds{model, source}: last build / cache-load time
//  - clearsky_answer_memory_bytes{state="reserved"|"limit"}: answer buffers in flight and their
//    budget (api/http/answer_memory_budget.h; refreshed at each scrape)
// Endpoint labels are the fixed route paths ("other" for anything else), so the label set
// stays bounded. Thread-safe.
#pragma once

#include <prometheus/counter.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace clearsky::server {

class Metrics {
 public:
  Metrics();
  void observe_request(const std::string& endpoint, const std::string& model, int status,
                       double seconds);
  void observe_cache_lookup(bool hit);
  void observe_build(const std::string& model, double seconds, bool from_cache);
  void observe_answer_memory(std::size_t reserved_bytes, std::size_t limit_bytes);
  // The text exposition, with the table memory gauges set from table_bytes first.
  std::string scrape(const std::map<std::string, std::size_t>& table_bytes);

 private:
  std::shared_ptr<prometheus::Registry> registry_;
  prometheus::Family<prometheus::Counter>* requests_;
  prometheus::Family<prometheus::Histogram>* durations_;
  prometheus::Family<prometheus::Gauge>* table_bytes_;
  prometheus::Family<prometheus::Counter>* cache_lookups_;
  prometheus::Family<prometheus::Gauge>* build_seconds_;
  prometheus::Family<prometheus::Gauge>* answer_memory_;

  // The series of each (endpoint, model, status) seen so far: prometheus-cpp's Family::Add
  // builds and compares a label map on every call, which cost more than the rest of a cheap
  // request's bookkeeping. The label set is bounded (see above), and so is this map.
  struct RequestSeries {
    prometheus::Counter* requests;
    prometheus::Histogram* duration;
  };
  std::mutex series_mutex_;
  std::unordered_map<std::string, RequestSeries> request_series_;
};

}  // namespace clearsky::server
