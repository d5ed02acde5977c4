// Tests of /v1/evaluations without a socket (api/evaluation/evaluations_api.h,
// evaluation_pool.h): request checks before queueing, background runs on the bounded pool
// (each worker with its own connection to a database file), listing with filters, one run
// with per-capture RMSE and the history comparison, per-sample errors on request; test models
// whose RMSE is known by hand.
#include "api/evaluation/evaluations_api.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <thread>

#include "api/error/api_error.h"
#include "api/evaluation/evaluation_pool.h"
#include "api/evaluation/evaluation_runner.h"
#include "models/registry.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

// Query parameters from (name, value) pairs.
Parameters query(const std::vector<std::pair<std::string, std::string>>& pairs) {
  Parameters p("GET /test");
  for (const auto& [name, value] : pairs) p.add(name, value);
  return p;
}

double sky(const ViewDirection& v, double nm) {
  return 0.05 + 0.02 * std::sin(v.zenith_rad) * std::cos(v.azimuth_rad - 120.0 * kDegree) +
         1e-5 * (nm - 500);
}

ModelDescriptor with_id(const std::string& id) {
  ModelDescriptor d = testing::test_descriptor();
  d.id = id;
  return d;
}
const ModelDescriptor& exact_d() {
  static const ModelDescriptor d = with_id("exact");
  return d;
}
// The offset model takes the atmosphere's turbidity and alpha (its descriptor lists them).
const ModelDescriptor& offset_d() {
  static const ModelDescriptor d = [] {
    ModelDescriptor m = with_id("offset");
    m.parameters.push_back(
        ParameterSpec{"turbidity", "", "turbidity", 2.53, 1.0, 10.0, false, true});
    m.parameters.push_back(
        ParameterSpec{"alpha", "", "Angstrom alpha", 0.8, 0.0, 4.0, false, true});
    return m;
  }();
  return d;
}
const ModelDescriptor& slow_d() {
  static const ModelDescriptor d = with_id("slow");
  return d;
}

// The offset model's error follows the turbidity parameter (1 mW per unit), so a changed
// parameter changes the RMSE by a known amount.
const std::vector<ModelFactory>& factories() {
  static const std::vector<ModelFactory> f = {
      {&exact_d(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(sky, c, exact_d());
       }},
      {&offset_d(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         const double offset = 1e-3 * c.atmosphere.turbidity;
         return std::make_shared<testing::FunctionModel>(
             [offset](const ViewDirection& v, double nm) { return sky(v, nm) + offset; }, c,
             offset_d());
       }},
      {&slow_d(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         std::this_thread::sleep_for(std::chrono::milliseconds(300));
         return std::make_shared<testing::FunctionModel>(sky, c, slow_d());
       }},
  };
  return f;
}

struct Fixture {
  clearsky::testing::TempDir dir;
  std::filesystem::path file = dir.path / "db.sqlite";
  storage::Database db = storage::open_database(file);
  Fixture() {
    const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
    for (int i = 0; i < 2; ++i) {
      MeasuredCapture c = testing::synthetic_capture(sky, 40.0 + i, 125.0);
      c.label = "capture " + std::to_string(i);
      c.unix_time_utc_s += 900.0 * i;
      storage::CaptureRepository(db).insert(dataset, c, "hash" + std::to_string(i), "test");
    }
  }
  EvaluationPool::OpenDatabase opener() const {
    return [path = file] { return storage::open_database(path); };
  }
};

int status_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const ApiError& e) {
    return e.status();
  }
  return 0;
}

TEST(EvaluationsApi, RequestIsCheckedBeforeQueueing) {
  Fixture f;
  const auto parse = [&](const std::string& body) {
    return parse_evaluation_request(f.db, body, factories(), "t");
  };
  const EvaluationRequest r = parse(R"({"models": ["offset"], "dataset": "synthetic",
                                        "parameters": {"turbidity": 4, "alpha": 1.0}})");
  EXPECT_EQ(r.models, std::vector<std::string>{"offset"});
  EXPECT_EQ(r.parameters, nlohmann::json({{"turbidity", 4}, {"alpha", 1.0}}));
  const ModelConfig offset_config = config_for_model(offset_d(), r.parameters);
  EXPECT_DOUBLE_EQ(offset_config.atmosphere.turbidity, 4.0);
  EXPECT_DOUBLE_EQ(offset_config.atmosphere.angstrom_alpha, 1.0);
  EXPECT_EQ(parse(R"({"dataset": "synthetic"})").models, std::vector<std::string>{"all"});
  EXPECT_EQ(status_of([&] { parse("{"); }), 400);
  EXPECT_EQ(status_of([&] { parse(R"({"models": "all"})"); }), 400);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "nope"})"); }), 404);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "synthetic", "models": ["nishita2042"]})"); }),
            404);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "synthetic", "models": []})"); }), 400);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "synthetic", "colour": 1})"); }), 400);
  EXPECT_EQ(
      status_of([&] { parse(R"({"dataset": "synthetic", "parameters": {"turbidity": "x"}})"); }),
      400);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "synthetic", "parameters": {"beta": -1}})"); }),
            400);
  EXPECT_EQ(status_of([&] { parse(R"({"dataset": "synthetic", "parameters": {"sparkle": 1}})"); }),
            400);
}

// Model options travel in "parameters" (e.g. Nishita93's study_viewer_sample): each applies to
// the requested models that list it, is range-checked before queueing, and is stored with the
// runs of those models only.
TEST(EvaluationsApi, ModelOptionsApplyToTheModelsThatListThem) {
  static const ModelDescriptor gain_d = [] {
    ModelDescriptor d = with_id("gain");
    d.parameters.push_back(
        ParameterSpec{"gain", "", "radiance factor", 1.0, 0.5, 4.0, false, false});
    return d;
  }();
  static const std::vector<ModelFactory> models = {
      factories()[0],
      {&gain_d,
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         const double gain = option_or_default(gain_d, c, "gain");
         return std::make_shared<testing::FunctionModel>(
             [gain](const ViewDirection& v, double nm) { return gain * sky(v, nm); }, c, gain_d);
       }}};
  Fixture f;
  const auto parse = [&](const std::string& body) {
    return parse_evaluation_request(f.db, body, models, "t");
  };
  const EvaluationRequest r =
      parse(R"({"models": ["exact", "gain"], "dataset": "synthetic", "parameters": {"gain": 2}})");
  EXPECT_EQ(r.parameters.at("gain"), 2);
  EXPECT_EQ(status_of([&] {
              parse(R"({"models": ["exact"], "dataset": "synthetic", "parameters": {"gain": 2}})");
            }),
            400);
  EXPECT_EQ(status_of([&] {
              parse(R"({"models": ["gain"], "dataset": "synthetic", "parameters": {"gain": 9}})");
            }),
            400);

  const EvaluationReport report = run_evaluation(f.db, r, models);
  ASSERT_EQ(report.models.size(), 2u);
  storage::EvaluationRunRepository runs(f.db);
  const auto exact = runs.get(report.models[0].run_id);
  const auto gain = runs.get(report.models[1].run_id);
  ASSERT_TRUE(exact && gain);
  EXPECT_EQ(exact->parameters.find("gain"), std::string::npos) << exact->parameters;
  EXPECT_EQ(exact->configuration.find("gain"), std::string::npos) << exact->configuration;
  EXPECT_EQ(nlohmann::json::parse(gain->parameters), nlohmann::json({{"gain", 2}}));
  EXPECT_NE(gain->configuration.find(";gain=2"), std::string::npos) << gain->configuration;
  EXPECT_NEAR(report.models[0].result.rmse, 0.0, 1e-9);
  EXPECT_GT(report.models[1].result.rmse, 10.0);  // twice the sky: tens of mW/(m2.sr.nm)
}

// The rule of docs/data-api.md "Evaluation parameters": a parameter applies to the requested
// models whose descriptor lists it, only to them, and is refused (400 naming it) when none
// of them lists it, atmosphere parameters as model options.
TEST(EvaluationsApi, AParameterAppliesOnlyToTheModelsThatListIt) {
  Fixture f;
  const auto parse = [&](const std::string& body) {
    return parse_evaluation_request(f.db, body, factories(), "t");
  };
  try {
    parse(R"({"models": ["exact"], "dataset": "synthetic", "parameters": {"turbidity": 3}})");
    ADD_FAILURE() << "turbidity accepted for a model that does not take it";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "turbidity");
    EXPECT_NE(std::string(e.what()).find("exact"), std::string::npos) << e.what();
  }
  // Within the range of the model that takes it.
  EXPECT_EQ(status_of([&] {
              parse(R"({"models": ["offset"], "dataset": "synthetic",
                        "parameters": {"turbidity": 11}})");
            }),
            400);
  // Two models, one taking it: accepted, applied and recorded on that model's run only.
  const EvaluationRequest r = parse(
      R"({"models": ["exact", "offset"], "dataset": "synthetic", "parameters": {"turbidity": 3}})");
  const EvaluationReport report = run_evaluation(f.db, r, factories());
  ASSERT_EQ(report.models.size(), 2u);
  EXPECT_NEAR(report.models[1].result.rmse, 3.0, 1e-9);
  const auto exact = show_evaluation(f.db, report.models[0].run_id);
  const auto offset = show_evaluation(f.db, report.models[1].run_id);
  EXPECT_EQ(exact["parameters"], nlohmann::ordered_json::object());
  EXPECT_EQ(offset["parameters"], nlohmann::ordered_json({{"turbidity", 3}}));
  const auto stored = storage::EvaluationRunRepository(f.db).get(report.models[0].run_id);
  EXPECT_EQ(stored->configuration, ModelConfig{}.canonical_string());
}

// The registered models: Bruneton lists no turbidity (its aerosols are alpha and beta),
// Preetham does (from 2). Bruneton's configuration, hence its cache key and tables, is the
// default one whatever turbidity another requested model gets.
TEST(EvaluationsApi, TurbidityIsRefusedForBrunetonAndAppliedToPreetham) {
  const ModelFactory* bruneton = find_model("bruneton");
  const ModelFactory* preetham = find_model("preetham");
  ASSERT_TRUE(bruneton && preetham);
  const std::vector<const ModelFactory*> both = {bruneton, preetham};
  const std::vector<const ModelFactory*> alone = {bruneton};
  const nlohmann::json turbid = {{"turbidity", 3}};
  try {
    parse_evaluation_parameters(turbid, alone);
    ADD_FAILURE() << "turbidity accepted for Bruneton alone";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "turbidity");
  }
  EXPECT_EQ(parse_evaluation_parameters(turbid, both), turbid);
  EXPECT_EQ(config_for_model(*bruneton->descriptor, turbid).canonical_string(),
            ModelConfig{}.canonical_string());
  EXPECT_EQ(parameters_for_model(*bruneton->descriptor, turbid), nlohmann::json::object());
  EXPECT_DOUBLE_EQ(config_for_model(*preetham->descriptor, turbid).atmosphere.turbidity, 3.0);
  // Preetham's own range, as the sky endpoints check it: 1.5 is a valid atmosphere turbidity
  // but not a Preetham one.
  EXPECT_EQ(status_of([&] { parse_evaluation_parameters({{"turbidity", 1.5}}, both); }), 400);
  // Alpha is Bruneton's, not Preetham's: applied to Bruneton only.
  const nlohmann::json alpha = {{"alpha", 1.3}};
  EXPECT_EQ(parse_evaluation_parameters(alpha, both), alpha);
  EXPECT_EQ(config_for_model(*preetham->descriptor, alpha).canonical_string(),
            ModelConfig{}.canonical_string());
  EXPECT_DOUBLE_EQ(config_for_model(*bruneton->descriptor, alpha).atmosphere.angstrom_alpha, 1.3);
  EXPECT_EQ(status_of([&] { parse_evaluation_parameters({{"sparkle", 1}}, both); }), 400);
}

// Parameters come back as the user gave them (not 0.80000000000000004), and the history
// compares by configuration: a parameter given at its default is like leaving it out.
TEST(EvaluationsApi, ParametersAreReturnedAsGivenAndHistoryComparesConfigurations) {
  Fixture f;
  const auto run = [&](const std::string& body) {
    const EvaluationReport report =
        run_evaluation(f.db, parse_evaluation_request(f.db, body, factories(), "1"), factories());
    return show_evaluation(f.db, report.models.at(0).run_id);
  };
  const auto plain = run(R"({"models": ["offset"], "dataset": "synthetic"})");
  const auto given = run(
      R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"turbidity": 2.53, "alpha": 0.8}})");
  EXPECT_EQ(given["parameters"].dump(), R"({"alpha":0.8,"turbidity":2.53})");
  EXPECT_EQ(given["history"]["previous_run"], plain["id"]);
  EXPECT_EQ(given["history"]["rmse_changed"], false);
  const auto other =
      run(R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"alpha": 1.3}})");
  EXPECT_EQ(other["parameters"].dump(), R"({"alpha":1.3})");
  EXPECT_TRUE(other["history"]["previous_run"].is_null());
}

// A capture whose sun the model cannot answer (95 degrees, the test models stop at 90) never
// fails the run: it is unanswered and counted, the RMSE states the samples it covers, the
// history compares only runs over the same samples with the same handling, and
// "out_of_domain": "clamp" evaluates the model at its largest sun zenith instead.
TEST(EvaluationsApi, SamplesTheModelCannotAnswerAreExcludedOrClampedAndCounted) {
  Fixture f;
  const auto run = [&](const std::string& body) {
    const EvaluationReport report =
        run_evaluation(f.db, parse_evaluation_request(f.db, body, factories(), "1"), factories());
    return show_evaluation(f.db, report.models.at(0).run_id);
  };
  const std::string exclude = R"({"models": ["offset"], "dataset": "synthetic"})";
  const auto before = run(exclude);
  EXPECT_EQ(before["samples_compared"], 162);
  {
    MeasuredCapture low = testing::synthetic_capture(sky, 95.0, 125.0);
    low.label = "capture low";
    low.unix_time_utc_s += 1800.0;
    storage::CaptureRepository(f.db).insert(storage::DatasetRepository(f.db).find("synthetic")->id,
                                            low, "hash-low", "test");
  }
  const auto excluded = run(exclude);
  EXPECT_EQ(excluded["status"], "succeeded");
  EXPECT_EQ(excluded["out_of_domain"], "exclude");
  EXPECT_EQ(excluded["parameters"].dump(), "{}");
  EXPECT_EQ(excluded["samples_compared"], 162);
  EXPECT_EQ(excluded["samples_excluded"], 81);
  EXPECT_EQ(excluded["captures_unanswered"], 1);
  EXPECT_NEAR(excluded["rmse"].get<double>(), before["rmse"].get<double>(), 1e-12);
  ASSERT_EQ(excluded["captures"].size(), 3u);
  const auto& low = excluded["captures"][2];
  EXPECT_EQ(low["label"], "capture low");
  EXPECT_TRUE(low["rmse"].is_null());
  EXPECT_EQ(low["samples_compared"], 0);
  ASSERT_EQ(low["excluded"].size(), 1u);
  EXPECT_EQ(low["excluded"][0]["reason"], "sun_below_horizon_unsupported");
  EXPECT_EQ(low["excluded"][0]["count"], 81);
  EXPECT_EQ(low["excluded"][0]["samples"].size(), 81u);
  // Not over the same samples as the run before the low capture (a capture more, unanswered).
  EXPECT_TRUE(excluded["history"]["previous_run"].is_null());
  EXPECT_EQ(run(exclude)["history"]["previous_run"], excluded["id"]);

  const std::string clamp_body =
      R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"out_of_domain": "clamp"}})";
  const auto clamped = run(clamp_body);
  EXPECT_EQ(clamped["parameters"].dump(), R"({"out_of_domain":"clamp"})");
  EXPECT_EQ(clamped["out_of_domain"], "clamp");
  EXPECT_EQ(clamped["samples_compared"], 243);
  EXPECT_EQ(clamped["samples_clamped"], 81);
  EXPECT_EQ(clamped["captures_unanswered"], 0);
  EXPECT_DOUBLE_EQ(clamped["captures"][2]["sun_zenith"].get<double>(), 90.0);
  EXPECT_EQ(clamped["captures"][2]["clamped"][0]["reason"], "sun_below_horizon_unsupported");
  EXPECT_TRUE(clamped["history"]["previous_run"].is_null());  // excluded runs are not alike
  EXPECT_EQ(run(clamp_body)["history"]["previous_run"], clamped["id"]);

  // Any other value is refused before queueing, naming the parameter.
  try {
    parse_evaluation_request(
        f.db,
        R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"out_of_domain": "drop"}})",
        factories(), "1");
    ADD_FAILURE() << "accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "out_of_domain");
  }
  // The list states what each run's RMSE covers.
  EXPECT_EQ(list_evaluations(f.db, {}).items.at(0)["samples_compared"], 243);
}

// A list is filtered in SQL, then cut into pages of `limit` by id: every run once, newest
// first, and the cursor of the last page absent.
TEST(EvaluationsApi, ListsArePagedAfterFiltering) {
  Fixture f;
  std::vector<std::int64_t> offsets;
  for (int i = 0; i < 5; ++i) {
    const EvaluationReport report = run_evaluation(
        f.db,
        parse_evaluation_request(f.db, R"({"models": ["offset", "exact"], "dataset": "synthetic"})",
                                 factories(), "1"),
        factories());
    offsets.insert(offsets.begin(), report.models[0].run_id);  // newest first
  }
  EvaluationFilter only_offset = parse_evaluation_filter(query({{"model", "offset"}}));
  std::vector<std::int64_t> seen;
  only_offset.page = {2, std::nullopt};
  int pages = 0;
  for (;;) {
    const ListPage listed = list_evaluations(f.db, only_offset);
    ++pages;
    EXPECT_LE(listed.items.size(), 2u);
    for (const auto& item : listed.items) {
      EXPECT_EQ(item["model"], "offset");
      seen.push_back(item["id"].get<std::int64_t>());
    }
    if (!listed.next_cursor) break;
    EXPECT_EQ(listed.limit, 2);
    only_offset.page.cursor = listed.next_cursor;
  }
  EXPECT_EQ(pages, 3);
  EXPECT_EQ(seen, offsets);
  // Exactly one page: no next cursor.
  only_offset.page = {5, std::nullopt};
  EXPECT_FALSE(list_evaluations(f.db, only_offset).next_cursor);
  only_offset.page = {2, std::string("nonsense")};
  EXPECT_EQ(status_of([&] { list_evaluations(f.db, only_offset); }), 400);
  const EvaluationFilter paged = parse_evaluation_filter(query({{"limit", "2"}, {"cursor", "x"}}));
  EXPECT_EQ(paged.page.limit, 2);
  EXPECT_EQ(paged.page.cursor, "x");
  EXPECT_EQ(status_of([&] { parse_evaluation_filter(query({{"limit", "1001"}})); }), 400);
}

// GET /v1/evaluations/tickets/{ticket} lists each model's run as soon as it starts.
TEST(EvaluationPool, TicketListsEachRunAsItStarts) {
  static std::promise<void> release;
  static std::shared_future<void> released = release.get_future().share();
  static const ModelDescriptor gated_d = with_id("gated");
  static const std::vector<ModelFactory> models = {
      {&gated_d,
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         released.wait();
         return std::make_shared<testing::FunctionModel>(sky, c, gated_d);
       }},
      factories()[0]};
  Fixture f;
  EvaluationPool pool(f.opener(), models, {1, 4, 1});
  const std::int64_t t = pool.submit(parse_evaluation_request(
      f.db, R"({"models": ["gated", "exact"], "dataset": "synthetic"})", models, "1"));
  // The gated model's precomputation waits: its run is listed, running, before it ends.
  TicketState state;
  for (int i = 0; i < 3000; ++i) {
    state = *pool.ticket(t);
    if (!state.runs.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(state.runs.size(), 1u);
  EXPECT_EQ(state.status, "running");
  EXPECT_EQ(state.runs[0].model, "gated");
  EXPECT_EQ(state.runs[0].status, "running");
  const auto json = ticket_to_json(state);
  EXPECT_EQ(json["runs"], nlohmann::ordered_json::array({state.runs[0].id}));
  EXPECT_EQ(json["models"][0]["status"], "running");
  // The model still to run is listed from the start, queued, without a run.
  ASSERT_EQ(state.models.size(), 2u);
  EXPECT_EQ(json["models"][1]["model"], "exact");
  EXPECT_EQ(json["models"][1]["status"], "queued");
  EXPECT_TRUE(json["models"][1]["run"].is_null());
  EXPECT_EQ(json["dataset"], "synthetic");
  EXPECT_TRUE(json["finished"].is_null());
  EXPECT_EQ(show_evaluation(f.db, state.runs[0].id)["status"], "running");
  release.set_value();
  pool.wait_idle();
  state = *pool.ticket(t);
  EXPECT_EQ(state.status, "succeeded");
  ASSERT_EQ(state.runs.size(), 2u);
  EXPECT_EQ(state.runs[1].model, "exact");
  for (const TicketRun& run : state.runs) EXPECT_EQ(run.status, "succeeded");
  EXPECT_EQ(state.run_ids, (std::vector<std::int64_t>{state.runs[0].id, state.runs[1].id}));
}

TEST(EvaluationsApi, BackgroundRunsAreStoredListedAndComparedWithHistory) {
  Fixture f;
  EvaluationPool pool(f.opener(), factories(), {1, 4, 1});
  const auto submit = [&](const std::string& body) {
    return pool.submit(parse_evaluation_request(f.db, body, factories(), "9.9"));
  };
  const std::int64_t first = submit(R"({"models": ["offset", "exact"], "dataset": "synthetic"})");
  const std::int64_t second = submit(R"({"models": ["offset"], "dataset": "synthetic"})");
  const std::int64_t third =
      submit(R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"turbidity": 3}})");
  const std::int64_t fourth =
      submit(R"({"models": ["offset"], "dataset": "synthetic", "parameters": {"turbidity": 4}})");
  pool.wait_idle();
  for (std::int64_t t : {first, second, third, fourth})
    ASSERT_EQ(pool.ticket(t)->status, "succeeded");
  ASSERT_EQ(pool.ticket(first)->run_ids.size(), 2u);

  // The default turbidity 2.53: RMSE 2.53 mW/(m2.sr.nm).
  const auto run = show_evaluation(f.db, pool.ticket(first)->run_ids[0]);
  EXPECT_EQ(run["model"], "offset");
  EXPECT_EQ(run["dataset"], "synthetic");
  EXPECT_EQ(run["status"], "succeeded");
  EXPECT_EQ(run["software_version"], "9.9");
  EXPECT_NEAR(run["rmse"].get<double>(), 2.53, 1e-9);
  ASSERT_EQ(run["captures"].size(), 2u);
  EXPECT_EQ(run["captures"][1]["label"], "capture 1");
  EXPECT_DOUBLE_EQ(run["captures"][1]["sun_zenith"].get<double>(), 41.0);
  EXPECT_NEAR(run["captures"][0]["rmse"].get<double>(), 2.53, 1e-9);
  EXPECT_EQ(run["captures"][0]["values_compared"], 81 * 31);
  EXPECT_TRUE(run["timings"]["precompute_seconds"].is_number());
  EXPECT_EQ(run["parameters"], nlohmann::ordered_json::object());
  EXPECT_TRUE(run["history"]["previous_run"].is_null());

  // Same model and parameters: unchanged against the first run.
  const auto again = show_evaluation(f.db, pool.ticket(second)->run_ids[0]);
  EXPECT_EQ(again["history"]["previous_run"], run["id"]);
  EXPECT_EQ(again["history"]["rmse_changed"], false);
  // Turbidity 3: other parameters, so no history; turbidity 4 compares with... nothing either.
  const auto t3 = show_evaluation(f.db, pool.ticket(third)->run_ids[0]);
  EXPECT_NEAR(t3["rmse"].get<double>(), 3.0, 1e-9);
  EXPECT_TRUE(t3["history"]["previous_run"].is_null());

  // Lists, newest first, with filters.
  EXPECT_EQ(list_evaluations(f.db, {}).items.size(), 5u);
  EXPECT_EQ(
      list_evaluations(f.db, parse_evaluation_filter(query({{"model", "exact"}}))).items.size(),
      1u);
  EXPECT_EQ(list_evaluations(f.db, parse_evaluation_filter(
                                       query({{"model", "offset"}, {"dataset", "synthetic"}})))
                .items.size(),
            4u);
  EXPECT_EQ(
      list_evaluations(f.db, parse_evaluation_filter(query({{"since", "2000-01-01T00:00:00Z"}})))
          .items.size(),
      5u);
  EXPECT_EQ(
      list_evaluations(f.db, parse_evaluation_filter(query({{"until", "2000-01-01T00:00:00Z"}})))
          .items.size(),
      0u);
  EXPECT_EQ(
      list_evaluations(f.db, parse_evaluation_filter(query({{"status", "failed"}}))).items.size(),
      0u);
  const auto newest = list_evaluations(f.db, {}).items[0];
  EXPECT_EQ(newest["id"], pool.ticket(fourth)->run_ids[0]);
  EXPECT_NEAR(newest["rmse"].get<double>(), 4.0, 1e-9);
  EXPECT_EQ(status_of([&] { parse_evaluation_filter(query({{"since", "yesterday"}})); }), 400);
  EXPECT_EQ(status_of([&] { parse_evaluation_filter(query({{"colour", "red"}})); }), 400);
  EXPECT_EQ(status_of([&] {
              list_evaluations(f.db, parse_evaluation_filter(query({{"dataset", "x"}})));
            }),
            404);
  EXPECT_EQ(status_of([&] { show_evaluation(f.db, 999); }), 404);
  EXPECT_EQ(status_of([&] { parse_id("12a", "id"); }), 400);
}

TEST(EvaluationsApi, RmseChangeAgainstHistoryIsReported) {
  Fixture f;
  EvaluationPool pool(f.opener(), factories(), {1, 4, 1});
  const std::string body = R"({"models": ["exact"], "dataset": "synthetic"})";
  const std::int64_t before = pool.submit(parse_evaluation_request(f.db, body, factories(), "1"));
  pool.wait_idle();
  // The measurements change (a capture re-imported with brighter spectra): the same model and
  // parameters now give another RMSE.
  {
    storage::Transaction t(f.db);
    f.db.execute("DELETE FROM captures WHERE label = 'capture 1'");
    MeasuredCapture c = testing::synthetic_capture(
        [](const ViewDirection& v, double nm) { return sky(v, nm) + 0.002; }, 41.0, 125.0);
    c.label = "capture 1";
    storage::CaptureRepository(f.db).insert(storage::DatasetRepository(f.db).find("synthetic")->id,
                                            c, "hash-new", "test");
    t.commit();
  }
  const std::int64_t after = pool.submit(parse_evaluation_request(f.db, body, factories(), "1"));
  pool.wait_idle();
  const auto run = show_evaluation(f.db, pool.ticket(after)->run_ids[0]);
  EXPECT_EQ(run["history"]["previous_run"], pool.ticket(before)->run_ids[0]);
  EXPECT_NEAR(run["history"]["previous_rmse"].get<double>(), 0.0, 1e-9);
  // Per capture 0 and 2; total sqrt((0 + 4) / 2).
  EXPECT_NEAR(run["rmse"].get<double>(), std::sqrt(2.0), 1e-9);
  EXPECT_EQ(run["history"]["rmse_changed"], true);
}

// Per-sample errors on request: the default answer is unchanged; samples=true adds per-capture
// samples whose RMSE recomputes the capture's and whose bias has the model's sign; spectra adds
// the errors at the run's wavelengths; capture= keeps one capture.
TEST(EvaluationsApi, PerSampleErrorsOnRequest) {
  Fixture f;
  EvaluationPool pool(f.opener(), factories(), {1, 4, 1});
  const std::int64_t t = pool.submit(parse_evaluation_request(
      f.db, R"({"models": ["offset"], "dataset": "synthetic"})", factories(), "1"));
  pool.wait_idle();
  ASSERT_EQ(pool.ticket(t)->status, "succeeded");
  const std::int64_t id = pool.ticket(t)->run_ids[0];
  const auto options = [](std::vector<std::pair<std::string, std::string>> query) {
    return parse_show_evaluation_options(clearsky::api::query(query));
  };

  const auto plain = show_evaluation(f.db, id);
  EXPECT_FALSE(plain.contains("wavelengths_nm"));
  EXPECT_FALSE(plain["captures"][0].contains("samples"));
  EXPECT_EQ(show_evaluation(f.db, id, options({{"samples", "false"}})), plain);

  const auto summary = show_evaluation(f.db, id, options({{"samples", "true"}}));
  EXPECT_FALSE(summary.contains("wavelengths_nm"));
  ASSERT_EQ(summary["captures"].size(), 2u);
  for (const auto& capture : summary["captures"]) {
    ASSERT_EQ(capture["samples"].size(), 81u);
    double squares = 0;
    for (const auto& sample : capture["samples"]) {
      EXPECT_FALSE(sample.contains("errors"));
      // The offset model is 2.53 mW/(m2.sr.nm) too bright everywhere (default turbidity).
      EXPECT_NEAR(sample["bias"].get<double>(), 2.53, 1e-9);
      squares += std::pow(sample["rmse"].get<double>(), 2);
    }
    EXPECT_NEAR(std::sqrt(squares / 81.0) / capture["rmse"].get<double>(), 1.0, 1e-9);
    EXPECT_EQ(capture["samples"][0]["index"], 0);
    EXPECT_EQ(capture["samples"][0]["view_zenith"], 0.0);
    EXPECT_EQ(capture["samples"][80]["index"], 80);
  }

  const auto spectra = show_evaluation(f.db, id, options({{"samples", "spectra"}}));
  ASSERT_EQ(spectra["wavelengths_nm"].size(), 31u);
  EXPECT_EQ(spectra["wavelengths_nm"][0], 360.0);
  EXPECT_EQ(spectra["wavelengths_nm"][30], 712.5);
  const auto& errors = spectra["captures"][1]["samples"][40]["errors"];
  ASSERT_EQ(errors.size(), 31u);
  for (const auto& e : errors) EXPECT_NEAR(e.get<double>(), 2.53, 1e-5);  // float32
  EXPECT_EQ(spectra["captures"][1]["samples"][40]["rmse"],
            summary["captures"][1]["samples"][40]["rmse"]);

  const auto one =
      show_evaluation(f.db, id, options({{"samples", "true"}, {"capture", "capture 1"}}));
  ASSERT_EQ(one["captures"].size(), 1u);
  EXPECT_EQ(one["captures"][0]["label"], "capture 1");
  EXPECT_EQ(one["captures"][0]["samples"], summary["captures"][1]["samples"]);
  EXPECT_EQ(status_of([&] {
              show_evaluation(f.db, id, options({{"capture", "capture 9"}}));
            }),
            404);
  EXPECT_EQ(status_of([&] { options({{"samples", "maybe"}}); }), 400);
  EXPECT_EQ(status_of([&] { options({{"sample", "true"}}); }), 400);

  // A run stored without per-sample errors (as before schema version 2): explicit nulls.
  storage::EvaluationRunRepository runs(f.db);
  storage::NewRun old;
  old.dataset_id = storage::DatasetRepository(f.db).find("synthetic")->id;
  old.model_id = "offset";
  old.model_version = std::string("1");
  const std::int64_t old_id = runs.start(old);
  storage::RunCaptureResult result;
  result.capture_id = storage::CaptureRepository(f.db).load(old.dataset_id)[0].id;
  result.rmse = 2.53;
  runs.finish(old_id, 2.53, 0, 0, "", {result});
  const auto old_run = show_evaluation(f.db, old_id, options({{"samples", "spectra"}}));
  EXPECT_TRUE(old_run["wavelengths_nm"].is_null());
  ASSERT_EQ(old_run["captures"].size(), 1u);
  EXPECT_TRUE(old_run["captures"][0]["samples"].is_null());
}

TEST(EvaluationPool, FullQueueIs503AndWorkersAreBounded) {
  Fixture f;
  EvaluationPool pool(f.opener(), factories(), {1, 1, 1});
  const std::string body = R"({"models": ["slow"], "dataset": "synthetic"})";
  const std::int64_t a = pool.submit(parse_evaluation_request(f.db, body, factories(), "1"));
  // Wait until the single worker holds the first one, then fill the one queue slot.
  for (int i = 0; i < 200 && pool.ticket(a)->status == "queued"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const std::int64_t b = pool.submit(parse_evaluation_request(f.db, body, factories(), "1"));
  EXPECT_EQ(pool.ticket(b)->status, "queued");
  EXPECT_EQ(status_of([&] { pool.submit(parse_evaluation_request(f.db, body, factories(), "1")); }),
            503);
  pool.wait_idle();
  EXPECT_EQ(pool.ticket(b)->status, "succeeded");
  // One worker: the two runs did not overlap.
  const auto first = show_evaluation(f.db, pool.ticket(a)->run_ids[0]);
  const auto second = show_evaluation(f.db, pool.ticket(b)->run_ids[0]);
  EXPECT_LE(first["finished"].get<std::string>(), second["started"].get<std::string>());
}

TEST(EvaluationPool, FailedRunIsReportedOnTheTicket) {
  Fixture f;
  EvaluationPool pool(f.opener(), factories(), {1, 4, 1});
  EvaluationRequest r = parse_evaluation_request(
      f.db, R"({"models": ["exact"], "dataset": "synthetic"})", factories(), "1");
  f.db.execute("DELETE FROM captures");
  std::atomic<bool> called{false};
  const std::int64_t t =
      pool.submit(r, [&](const TicketState& s) { called = s.status == "failed"; });
  pool.wait_idle();
  EXPECT_TRUE(called);
  EXPECT_EQ(pool.ticket(t)->status, "failed");
  EXPECT_NE(pool.ticket(t)->error.find("no captures"), std::string::npos);
  EXPECT_EQ(ticket_to_json(*pool.ticket(t))["status"], "failed");
}

// A failure skips the models the ticket had still queued, with the reason.
TEST(EvaluationPool, AFailedModelSkipsTheModelsAfterIt) {
  static const ModelDescriptor broken_d = with_id("broken");
  static const std::vector<ModelFactory> models = {
      {&broken_d,
       [](const ModelConfig&, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         throw std::runtime_error("precomputation failed");
       }},
      factories()[0]};
  Fixture f;
  EvaluationPool pool(f.opener(), models, {1, 4, 1});
  const std::int64_t t = pool.submit(parse_evaluation_request(
      f.db, R"({"models": ["broken", "exact"], "dataset": "synthetic"})", models, "1"));
  pool.wait_idle();
  const auto json = ticket_to_json(*pool.ticket(t));
  EXPECT_EQ(json["status"], "failed");
  ASSERT_EQ(json["models"].size(), 2u) << json.dump();
  EXPECT_EQ(json["models"][0]["status"], "failed");
  EXPECT_FALSE(json["models"][0]["run"].is_null());
  EXPECT_EQ(json["models"][1]["model"], "exact");
  EXPECT_EQ(json["models"][1]["status"], "skipped");
  EXPECT_TRUE(json["models"][1]["run"].is_null());
  EXPECT_NE(json["models"][1]["error"].get<std::string>().find("not run"), std::string::npos);
  EXPECT_FALSE(json["finished"].is_null());
}

// Tickets are stored: a pool of a later process reads them, and its ids go on.
TEST(EvaluationPool, TicketsOutliveThePoolAndTheirIdsAreNotReused) {
  Fixture f;
  const std::string body = R"({"models": ["exact", "offset"], "dataset": "synthetic"})";
  std::int64_t first = 0;
  {
    EvaluationPool pool(f.opener(), factories(), {1, 4, 1});
    first = pool.submit(parse_evaluation_request(f.db, body, factories(), "1"));
    pool.wait_idle();
  }
  EvaluationPool later(f.opener(), factories(), {1, 4, 1});
  const auto kept = later.ticket(first);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->status, "succeeded");
  EXPECT_EQ(kept->run_ids.size(), 2u);
  EXPECT_EQ(interrupt_unfinished_tickets(f.db), 0);
  const std::int64_t second = later.submit(parse_evaluation_request(f.db, body, factories(), "1"));
  EXPECT_GT(second, first);
  later.wait_idle();
  EXPECT_EQ(later.ticket(second)->status, "succeeded");
}

}  // namespace
}  // namespace clearsky::api
