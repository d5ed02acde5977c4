// Finding the stored fit a request names (api/fits/stored_fit_values.h, docs/fits.md "Using a
// fit") in a real SQLite database: by id, latest and latest:DATASET (the newest succeeded fit of
// the model, on that dataset), and every refusal naming fit: an unreadable reference (400), an
// unknown id or no such fit (404), a fit not succeeded or of another model (409).
#include "api/fits/stored_fit_values.h"

#include <gtest/gtest.h>

#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/stored_fit.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

using clearsky::testing::store_fit;

const ModelDescriptor& preetham() { return *find_model("preetham")->descriptor; }
const ModelDescriptor& hosek() { return *find_model("hosek")->descriptor; }

class StoredFitValues : public ::testing::Test {
 protected:
  void SetUp() override {
    a = storage::DatasetRepository(db).find_or_create("a", "kider2014");
    b = storage::DatasetRepository(db).find_or_create("b", "kider2014");
  }
  AppliedFit find(const std::string& reference, const ModelDescriptor& descriptor) {
    return find_applied_fit(db, parse_fit_reference(reference), descriptor);
  }
  // The status and code of the refusal of find, naming fit.
  std::pair<int, std::string> refusal(const std::string& reference,
                                      const ModelDescriptor& descriptor) {
    try {
      find(reference, descriptor);
    } catch (const ApiError& e) {
      EXPECT_EQ(e.parameter(), "fit") << e.what();
      return {e.status(), e.code()};
    }
    return {0, ""};
  }
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  std::int64_t a = 0, b = 0;
};

TEST_F(StoredFitValues, AnIdAnswersThatFitsValuesInTheOrderOfItsFreeParameters) {
  const std::int64_t id = store_fit(db, a, "hosek", {{"turbidity", 2.875}, {"albedo", 0.0}});
  const AppliedFit fit = find(std::to_string(id), hosek());
  EXPECT_EQ(fit.id, id);
  EXPECT_EQ(fit.model_id, "hosek");
  EXPECT_EQ(fit.dataset, "a");
  EXPECT_FALSE(fit.latest);
  const std::vector<std::pair<std::string, double>> expected = {{"turbidity", 2.875},
                                                                {"albedo", 0.0}};
  EXPECT_EQ(fit.values, expected);
}

TEST_F(StoredFitValues, LatestIsTheNewestSucceededFitOfTheModelOnTheDatasetWhenNamed) {
  const std::int64_t older = store_fit(db, a, "preetham", {{"turbidity", 2.1}});
  const std::int64_t on_b = store_fit(db, b, "preetham", {{"turbidity", 2.2}});
  store_fit(db, a, "hosek", {{"turbidity", 4.0}});                // another model
  store_fit(db, a, "preetham", {{"turbidity", 9.0}}, "failed");   // not succeeded
  store_fit(db, a, "preetham", {{"turbidity", 9.0}}, "running");  // not yet
  EXPECT_EQ(find("latest", preetham()).id, on_b);
  EXPECT_TRUE(find("latest", preetham()).latest);
  EXPECT_EQ(find("latest:a", preetham()).id, older);
  EXPECT_EQ(find("latest:a", preetham()).values[0].second, 2.1);
  EXPECT_EQ(find("latest:b", preetham()).id, on_b);
}

TEST_F(StoredFitValues, EveryRefusalNamesFit) {
  const std::int64_t running = store_fit(db, a, "preetham", {{"turbidity", 3.0}}, "running");
  const std::int64_t failed = store_fit(db, a, "preetham", {{"turbidity", 3.0}}, "failed");
  const std::int64_t of_hosek = store_fit(db, a, "hosek", {{"turbidity", 3.0}});
  EXPECT_EQ(refusal("999", preetham()), std::make_pair(404, std::string("unknown_fit")));
  EXPECT_EQ(refusal("latest", preetham()), std::make_pair(404, std::string("unknown_fit")));
  EXPECT_EQ(refusal("latest:b", hosek()), std::make_pair(404, std::string("unknown_fit")));
  EXPECT_EQ(refusal("latest:nope", hosek()), std::make_pair(404, std::string("unknown_fit")));
  EXPECT_EQ(refusal(std::to_string(running), preetham()),
            std::make_pair(409, std::string("fit_not_succeeded")));
  EXPECT_EQ(refusal(std::to_string(failed), preetham()),
            std::make_pair(409, std::string("fit_not_succeeded")));
  EXPECT_EQ(refusal(std::to_string(of_hosek), preetham()),
            std::make_pair(409, std::string("fit_model_mismatch")));
  for (const char* text : {"", "0", "-1", "1.5", "12abc", "latest:", "Latest", "newest"}) {
    try {
      parse_fit_reference(text);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << text;
      EXPECT_EQ(e.parameter(), "fit") << text;
    }
  }
}

TEST_F(StoredFitValues, AServerWithoutADatabaseAnswersNoDatabaseNamingFit) {
  const clearsky::testing::SynchronousProvider models{
      std::vector<ModelFactory>(registered_models().begin(), registered_models().end())};
  const ApiContext context{models, Limits{}};
  const FitLookup lookup = stored_fit_lookup(context);
  try {
    lookup("1", preetham());
    ADD_FAILURE() << "a lookup without a database answered";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 404);
    EXPECT_EQ(e.code(), "no_database");
    EXPECT_EQ(e.parameter(), "fit");
  }
}

}  // namespace
}  // namespace clearsky::api
