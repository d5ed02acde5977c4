// Bruneton 2008 and Elek 2010 against the 15 public captures of 2013-05-27 (Kider et al.
// 2014): the study's code scores 11.34 mW/(m2.sr.nm) for both (models/bruneton/README.md); we
// require the same within 3%. The tables are precomputed once at the paper's resolution on
// the paper's 40 wavelengths; Elek, identical on that grid, loads them from an in-memory
// cache instead of precomputing them again.
#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "models/bruneton/bruneton.h"
#include "models/evaluation/evaluate_model.h"
#include "models/registry.h"
#include "tests/support/public_captures.h"
#include "tests/support/shared_data.h"

namespace clearsky {
namespace {

class MemoryCache : public TableCache {
 public:
  std::optional<std::string> load(const std::string& key) const override {
    std::lock_guard lock(mutex_);
    auto it = blobs_.find(key);
    if (it == blobs_.end()) return std::nullopt;
    return it->second;
  }
  void store(const std::string& key, std::string_view bytes) const override {
    std::lock_guard lock(mutex_);
    blobs_[key] = std::string(bytes);
  }

 private:
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::string> blobs_;
};

constexpr double kStudyRmse = 11.34;

TEST(BrunetonElekAccuracy, PaperRmseOnThe15PublicCaptures) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  MemoryCache cache;
  EvaluationOptions options;
  options.context.cache = &cache;
  const auto& captures = testing::public_captures();

  const EvaluationResult bruneton =
      evaluate_model(*find_model("bruneton"), ModelConfig{}, captures, options);
  RecordProperty("bruneton_rmse", std::to_string(bruneton.rmse));
  RecordProperty("bruneton_precompute_seconds", std::to_string(bruneton.precompute_seconds));
  RecordProperty("bruneton_evaluate_seconds", std::to_string(bruneton.evaluate_seconds));
  EXPECT_NEAR(bruneton.rmse, kStudyRmse, 0.03 * kStudyRmse);
  ASSERT_EQ(bruneton.captures.size(), 15u);
  // The captures the paper's figure details (10:15 and 11:15).
  RecordProperty("bruneton_rmse_10h15", std::to_string(bruneton.captures[3].rmse));
  RecordProperty("bruneton_rmse_11h15", std::to_string(bruneton.captures[7].rmse));

  const EvaluationResult elek =
      evaluate_model(*find_model("elek"), ModelConfig{}, captures, options);
  RecordProperty("elek_rmse", std::to_string(elek.rmse));
  RecordProperty("elek_precompute_seconds", std::to_string(elek.precompute_seconds));
  EXPECT_NEAR(elek.rmse, kStudyRmse, 0.03 * kStudyRmse);
  // Identical on the paper's grid, capture by capture.
  for (std::size_t i = 0; i < captures.size(); ++i)
    EXPECT_EQ(elek.captures[i].rmse, bruneton.captures[i].rmse) << i;
}

// The extended sun range (max_sun_zenith_deg, models/bruneton/README.md): the same number of
// sun texels spread from the zenith to 110 degrees instead of 101.39, fewer of them near the
// horizon. The captures keep the study's accuracy within 3%: measured 11.3304 at 110 degrees
// (11.3237 at 120, not repeated here to keep the suite short; the default gives 11.3331), and
// Elek, loading the same tables, the same.
TEST(BrunetonElekAccuracy, ExtendedSunRangeKeepsThePaperRmse) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  MemoryCache cache;
  EvaluationOptions options;
  options.context.cache = &cache;
  const auto& captures = testing::public_captures();
  ModelConfig config;
  config.options["max_sun_zenith_deg"] = 110.0;
  const EvaluationResult bruneton =
      evaluate_model(*find_model("bruneton"), config, captures, options);
  RecordProperty("bruneton_rmse_110", std::to_string(bruneton.rmse));
  RecordProperty("bruneton_precompute_seconds_110", std::to_string(bruneton.precompute_seconds));
  EXPECT_NEAR(bruneton.rmse, kStudyRmse, 0.03 * kStudyRmse);
  const EvaluationResult elek = evaluate_model(*find_model("elek"), config, captures, options);
  RecordProperty("elek_rmse_110", std::to_string(elek.rmse));
  EXPECT_EQ(elek.rmse, bruneton.rmse);
}

}  // namespace
}  // namespace clearsky
