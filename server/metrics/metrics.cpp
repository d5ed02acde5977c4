// Metric families and their exposition.
#include "server/metrics/metrics.h"

#include <prometheus/text_serializer.h>

namespace clearsky::server {

Metrics::Metrics()
    : registry_(std::make_shared<prometheus::Registry>()),
      requests_(&prometheus::BuildCounter()
                     .Name("clearsky_http_requests_total")
                     .Help("HTTP requests by endpoint, model and status")
                     .Register(*registry_)),
      durations_(&prometheus::BuildHistogram()
                      .Name("clearsky_http_request_duration_seconds")
                      .Help("HTTP request latency (to the last byte) by endpoint and model")
                      .Register(*registry_)),
      table_bytes_(&prometheus::BuildGauge()
                        .Name("clearsky_table_bytes")
                        .Help("Memory held by ready model tables")
                        .Register(*registry_)),
      cache_lookups_(&prometheus::BuildCounter()
                          .Name("clearsky_table_cache_lookups_total")
                          .Help("Disk table cache lookups by result")
                          .Register(*registry_)),
      build_seconds_(
          &prometheus::BuildGauge()
               .Name("clearsky_table_build_seconds")
               .Help("Duration of the last table build or cache load by model and source")
               .Register(*registry_)),
      answer_memory_(&prometheus::BuildGauge()
                          .Name("clearsky_answer_memory_bytes")
                          .Help("Answer buffers in flight (reserved) and their budget (limit)")
                          .Register(*registry_)) {}

void Metrics::observe_request(const std::string& endpoint, const std::string& model, int status,
                              double seconds) {
  std::string key = endpoint;
  key += '\0';
  key += model;
  key += '\0';
  key += std::to_string(status);
  RequestSeries series{};
  {
    std::lock_guard lock(series_mutex_);
    auto found = request_series_.find(key);
    if (found == request_series_.end()) {
      const std::string model_label = model.empty() ? "none" : model;
      static const prometheus::Histogram::BucketBoundaries kBuckets = {
          0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0};
      const RequestSeries created{
          &requests_->Add(
              {{"endpoint", endpoint}, {"model", model_label}, {"status", std::to_string(status)}}),
          &durations_->Add({{"endpoint", endpoint}, {"model", model_label}}, kBuckets)};
      found = request_series_.emplace(std::move(key), created).first;
    }
    series = found->second;
  }
  series.requests->Increment();
  series.duration->Observe(seconds);
}

void Metrics::observe_cache_lookup(bool hit) {
  cache_lookups_->Add({{"result", hit ? "hit" : "miss"}}).Increment();
}

void Metrics::observe_build(const std::string& model, double seconds, bool from_cache) {
  build_seconds_->Add({{"model", model}, {"source", from_cache ? "cache" : "built"}}).Set(seconds);
}

void Metrics::observe_answer_memory(std::size_t reserved_bytes, std::size_t limit_bytes) {
  answer_memory_->Add({{"state", "reserved"}}).Set(static_cast<double>(reserved_bytes));
  answer_memory_->Add({{"state", "limit"}}).Set(static_cast<double>(limit_bytes));
}

std::string Metrics::scrape(const std::map<std::string, std::size_t>& table_bytes) {
  for (const auto& [model, bytes] : table_bytes)
    table_bytes_->Add({{"model", model}}).Set(static_cast<double>(bytes));
  return prometheus::TextSerializer().Serialize(registry_->Collect());
}

}  // namespace clearsky::server
