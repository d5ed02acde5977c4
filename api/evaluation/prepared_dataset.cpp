// A stored dataset's captures prepared as the paper did (prepared_dataset.h).
#include "api/evaluation/prepared_dataset.h"

#include <stdexcept>

#include "models/core/parallel.h"
#include "models/evaluation/capture_preparation.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"

namespace clearsky::api {

PreparedDataset load_prepared_dataset(storage::Database& db, const std::string& dataset) {
  const auto found = storage::DatasetRepository(db).find(dataset);
  if (!found) throw std::invalid_argument("no dataset named '" + dataset + "'");
  storage::CaptureRepository capture_repository(db);
  std::vector<storage::StoredCapture> stored = capture_repository.load(found->id);
  if (stored.empty()) throw std::invalid_argument("dataset '" + dataset + "' has no captures");

  PreparedDataset out;
  out.dataset_id = found->id;
  for (auto& s : stored) {
    s.capture.sun_azimuth_estimated_deg = kNotComputed;
    out.capture_ids.push_back(s.id);
    out.captures.push_back(std::move(s.capture));
  }
  std::vector<MeasuredCapture>& captures = out.captures;
  parallel_for(captures.size(), [&](std::size_t i) { prepare_capture(captures[i]); });
  for (const MeasuredCapture& c : captures)
    for (const std::string& step : c.processing_steps)
      out.processing_steps += c.label + ": " + step + "\n";
  storage::Transaction transaction(db);
  for (std::size_t i = 0; i < captures.size(); ++i)
    capture_repository.set_estimated_sun_azimuth(out.capture_ids[i],
                                                 captures[i].sun_azimuth_estimated_deg);
  transaction.commit();
  return out;
}

}  // namespace clearsky::api
