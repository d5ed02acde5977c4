// The data methods of clearsky::client::Client against a real `clearsky serve` with a token:
// a Kider et al. 2014 capture uploaded with progress and imported, the dataset read, an
// evaluation created and followed through its ticket to its run, the job lifecycle with
// paging, deletions, and the writes refused without the token (401).
#include <clearsky/client/client.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/clients/cpp/client_server.h"
#include "tests/support/shared_data.h"

namespace clearsky::client {
namespace {

const char* kArchive = "kider2014/2013-05-27/RADIANCE/2013-05-27___12.00.00.7z";

class DataClient : public ::testing::Test {
 protected:
  void SetUp() override {
    server_ = std::make_unique<testing::ClientServer>(std::vector<std::string>{}, "preetham");
    ASSERT_GT(server_->port(), 0) << server_->log();
  }
  // The capture uploaded and imported into `name`.
  ImportState imported(const std::string& name) {
    DatasetUpload upload;
    upload.name = name;
    upload.archive = clearsky::testing::shared_data_dir() / kArchive;
    std::uint64_t last_sent = 0;
    std::uint64_t total = 0;
    int calls = 0;
    const ImportState queued =
        server_->client().upload_dataset(upload, [&](std::uint64_t sent, std::uint64_t all) {
          EXPECT_GE(sent, last_sent);
          last_sent = sent;
          total = all;
          ++calls;
          return true;
        });
    EXPECT_EQ(total, std::filesystem::file_size(upload.archive));
    EXPECT_EQ(last_sent, total);
    EXPECT_GT(calls, 1);  // 1.4 MB in 64 KiB pieces
    EXPECT_EQ(queued.dataset, name);
    EXPECT_EQ(queued.source, "upload");
    EXPECT_EQ(queued.upload_bytes, static_cast<std::int64_t>(total));
    return server_->client().wait_for_import(queued.id);
  }
  std::unique_ptr<testing::ClientServer> server_;
};

TEST_F(DataClient, UploadImportEvaluateAndDelete) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  const Client client = server_->client();
  const ImportState done = imported("noon");
  ASSERT_EQ(done.status, "succeeded") << (done.error ? done.error->message : "");
  ASSERT_TRUE(done.report.has_value());
  EXPECT_EQ(done.report->added.size(), 1u);
  EXPECT_EQ(done.progress.samples_added, 81);
  EXPECT_EQ(client.import_state(done.id).status, "succeeded");
  ImportFilter succeeded;
  succeeded.status = "succeeded";
  ASSERT_EQ(client.imports(succeeded).items.size(), 1u);

  const auto datasets = client.datasets();
  ASSERT_EQ(datasets.items.size(), 1u);
  EXPECT_EQ(datasets.items[0].name, "noon");
  EXPECT_EQ(datasets.items[0].samples, 81);
  EXPECT_FALSE(datasets.next_cursor.has_value());
  const Dataset noon = client.dataset("noon");
  ASSERT_EQ(noon.captures.size(), 1u);
  EXPECT_EQ(noon.captures[0].sample_count, 81);
  EXPECT_TRUE(noon.captures[0].samples.empty());
  DatasetQuery one_capture;
  one_capture.capture = noon.captures[0].label;
  const Dataset spectra = client.dataset("noon", one_capture);
  ASSERT_EQ(spectra.captures.size(), 1u);
  ASSERT_EQ(spectra.captures[0].samples.size(), 81u);
  EXPECT_FALSE(spectra.captures[0].samples[0].radiance_w_m2_sr_nm.empty());

  EvaluationRequest evaluation;
  evaluation.dataset = "noon";
  evaluation.models = {"preetham"};
  evaluation.parameters["turbidity"] = 3.0;
  const EvaluationTicket queued = client.create_evaluation(evaluation);
  EXPECT_EQ(queued.dataset, "noon");
  const EvaluationTicket finished = client.wait_for_ticket(queued.ticket);
  ASSERT_EQ(finished.status, "succeeded") << finished.error.value_or("");
  ASSERT_EQ(finished.runs.size(), 1u);
  const Evaluation run = client.evaluation(finished.runs[0]);
  EXPECT_EQ(run.model, "preetham");
  EXPECT_EQ(run.status, "succeeded");
  ASSERT_TRUE(run.rmse_mw_m2_sr_nm.has_value());
  EXPECT_GT(*run.rmse_mw_m2_sr_nm, 0);
  ASSERT_EQ(run.parameters.count("turbidity"), 1u);
  EXPECT_DOUBLE_EQ(std::get<double>(run.parameters.at("turbidity")), 3.0);
  ASSERT_EQ(run.captures.size(), 1u);
  EXPECT_TRUE(run.timings.is_object());
  EvaluationFilter by_model;
  by_model.model = "preetham";
  const auto runs = client.evaluations(by_model);
  ASSERT_EQ(runs.items.size(), 1u);
  EXPECT_EQ(runs.items[0].id, run.id);

  EXPECT_EQ(client.delete_dataset("noon"), "noon");
  EXPECT_TRUE(client.datasets().items.empty());
  try {
    client.dataset("noon");
    FAIL() << "a deleted dataset was found";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 404);
  }
}

TEST_F(DataClient, JobLifecycleWithPaging) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  const Client client = server_->client();
  ASSERT_EQ(imported("noon").status, "succeeded");

  JobRequest request;
  request.schedule = "0 3 * * *";
  request.dataset = "noon";
  request.models = {"preetham"};
  request.parameters["turbidity"] = 3.0;
  request.name = "nightly";
  const Job nightly = client.create_job(request);
  EXPECT_EQ(nightly.name, "nightly");
  EXPECT_FALSE(nightly.paused);
  EXPECT_TRUE(nightly.next_run.has_value());
  request.name = "weekly";
  request.schedule = "0 4 * * 1";
  request.models.clear();  // "all"
  const Job weekly = client.create_job(request);
  EXPECT_TRUE(weekly.models.empty());

  PageRequest first;
  first.limit = 1;
  const Page<Job> page = client.jobs(first);
  ASSERT_EQ(page.items.size(), 1u);
  EXPECT_EQ(page.items[0].name, "nightly");  // by name
  ASSERT_TRUE(page.next_cursor.has_value());
  PageRequest second = first;
  second.cursor = page.next_cursor;
  const Page<Job> rest = client.jobs(second);
  ASSERT_EQ(rest.items.size(), 1u);
  EXPECT_EQ(rest.items[0].name, "weekly");
  EXPECT_FALSE(rest.next_cursor.has_value());

  EXPECT_TRUE(client.pause_job(nightly.id).paused);
  EXPECT_TRUE(client.job(nightly.id).paused);
  EXPECT_FALSE(client.resume_job(nightly.id).paused);

  // A name already taken: 409 naming it.
  request.name = "nightly";
  try {
    client.create_job(request);
    FAIL() << "a job name was taken twice";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 409) << e.what();
    EXPECT_EQ(e.parameter(), "name") << e.what();
  }

  EXPECT_EQ(client.delete_job(nightly.id), nightly.id);
  EXPECT_EQ(client.jobs().items.size(), 1u);
  try {
    client.job(nightly.id);
    FAIL() << "a deleted job was found";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 404);
    EXPECT_EQ(e.parameter(), "id") << e.what();
  }
}

TEST_F(DataClient, WritesWithoutTheTokenAre401) {
  const Client anonymous = server_->client(false);
  JobRequest request;
  request.name = "j";
  request.schedule = "0 3 * * *";
  request.dataset = "noon";
  try {
    anonymous.create_job(request);
    FAIL() << "a write without the token was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 401);
    EXPECT_EQ(e.code(), "unauthorized");
    EXPECT_EQ(e.parameter(), "Authorization");
  }
  try {
    anonymous.delete_dataset("noon");
    FAIL() << "a delete without the token was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 401);
  }
  // Reads stay open.
  EXPECT_TRUE(anonymous.jobs().items.empty());
}

TEST_F(DataClient, AnUploadCancelledByItsProgressCallbackIsAnError) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  DatasetUpload upload;
  upload.name = "cancelled";
  upload.archive = clearsky::testing::shared_data_dir() / kArchive;
  try {
    server_->client().upload_dataset(
        upload, [](std::uint64_t sent, std::uint64_t) { return sent < 200000; });
    FAIL() << "the upload was not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), "cancelled") << e.what();
  }
  EXPECT_TRUE(server_->client().datasets().items.empty());
}

// An AERONET inversion uploaded from the repository's file, read back one by one and in the
// list; a file the server's reader refuses is a 400 naming the body.
TEST_F(DataClient, AerosolInversionsUploadedAndRead) {
  // The repository's root from this file's path (CMake compiles it by its absolute path).
  const std::filesystem::path root =
      std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().parent_path();
  const std::filesystem::path pfn = root / "models/data/aeronet/130527_130527_Egbert.pfn";
  const AerosolInversion stored = server_->client().upload_aerosols("egbert", pfn);
  EXPECT_EQ(stored.site, "Egbert");
  EXPECT_EQ(stored.retrieval_count, 5);
  ASSERT_EQ(stored.retrievals.size(), 5u);
  EXPECT_EQ(stored.retrievals[0].time_utc, "11:19:04");
  EXPECT_EQ(stored.retrievals[0].aod.size(), stored.wavelengths_nm.size());
  const AerosolInversion read = server_->client().aerosol_inversion(stored.id);
  EXPECT_EQ(read.content_hash, stored.content_hash);
  const Page<AerosolInversion> list = server_->client().aerosol_inversions();
  ASSERT_EQ(list.items.size(), 1u);
  EXPECT_TRUE(list.items[0].retrievals.empty());
  const std::filesystem::path garbage = std::filesystem::temp_directory_path() / "not.pfn";
  {
    std::ofstream out(garbage);
    out << "not an inversion\n";
  }
  try {
    server_->client().upload_aerosols("bad", garbage);
    FAIL() << "a file that is not an inversion was stored";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "body") << e.what();
  }
  std::filesystem::remove(garbage);
}

TEST_F(DataClient, AnUnknownImportIs404NamingTheId) {
  try {
    server_->client().import_state(12345);
    FAIL() << "import 12345 was found";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 404);
    EXPECT_EQ(e.parameter(), "id") << e.what();
  }
}

// Fits: created with the token on an imported capture, followed to success, read back and
// listed; the fitted turbidity lies within the bounds and lowers the RMSE; an unknown fit is a
// 404 naming its id.
TEST_F(DataClient, FitLifecycle) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  const Client client = server_->client();
  ASSERT_EQ(imported("noon").status, "succeeded");
  FitRequest request;
  request.dataset = "noon";
  request.model = "preetham";
  request.free = {"turbidity"};
  request.bounds["turbidity"] = {2.0, 6.0};
  const Fit queued = client.create_fit(request);
  EXPECT_EQ(queued.dataset, "noon");
  EXPECT_EQ(queued.model, "preetham");
  const Fit done = client.wait_for_fit(queued.id);
  EXPECT_EQ(done.status, "succeeded");
  ASSERT_EQ(done.values.count("turbidity"), 1u);
  EXPECT_GE(done.values.at("turbidity"), 2.0);
  EXPECT_LE(done.values.at("turbidity"), 6.0);
  ASSERT_TRUE(done.rmse_before && done.rmse_after);
  EXPECT_LE(*done.rmse_after, *done.rmse_before);
  EXPECT_TRUE(done.finished.has_value());
  EXPECT_EQ(client.fit(queued.id).values, done.values);
  // The fit in use: a sky query with fit=ID answers as the fitted turbidity given explicitly,
  // and says which fit; fit=latest is the same fit here.
  RadianceRequest by_fit;
  by_fit.model = "preetham";
  by_fit.sun = SunAngles{30, 135};
  by_fit.view = ViewDirection{45, 0};
  by_fit.wavelengths_nm = {450, 550};
  by_fit.fit = std::to_string(queued.id);
  RadianceRequest given = by_fit;
  given.fit.reset();
  given.parameters["turbidity"] = done.values.at("turbidity");
  const RadianceResult fitted = client.radiance(by_fit);
  ASSERT_TRUE(fitted.fit.has_value());
  EXPECT_EQ(fitted.fit->id, queued.id);
  EXPECT_EQ(fitted.fit->dataset, "noon");
  EXPECT_EQ(fitted.fit->parameters, done.values);
  EXPECT_EQ(fitted.samples[0].radiance_w_m2_sr_nm,
            client.radiance(given).samples[0].radiance_w_m2_sr_nm);
  SkyMatrixRequest matrix;
  matrix.model = "preetham";
  matrix.latitude = "42.444";
  matrix.longitude = "-76.5";
  matrix.start = "2013-05-27T11:00:00-04:00";
  matrix.end = "2013-05-27T12:00:00-04:00";
  matrix.output = "luminance";
  matrix.fit = "latest";
  const SkyMatrixResult day = client.sky_matrix(matrix);
  ASSERT_TRUE(day.fit.has_value());
  EXPECT_EQ(day.fit->id, queued.id);
  const Page<Fit> listed = client.fits();
  ASSERT_EQ(listed.items.size(), 1u);
  EXPECT_EQ(listed.items[0].id, queued.id);
  try {
    client.fit(queued.id + 1000);
    FAIL() << "an unknown fit was answered";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 404);
  }
}

}  // namespace
}  // namespace clearsky::client
