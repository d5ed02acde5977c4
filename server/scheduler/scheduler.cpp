// Scheduled evaluation jobs (scheduler.h).
#include "server/scheduler/scheduler.h"

#include <spdlog/spdlog.h>

#include <chrono>

#include "api/error/api_error.h"
#include "api/jobs/cron_schedule.h"
#include "api/jobs/job_refit.h"
#include "api/jobs/jobs_api.h"
#include "api/parse/iso8601_time.h"
#include "storage/repositories/job_repository.h"

namespace clearsky::server {

Scheduler::Scheduler(api::EvaluationPool::OpenDatabase open_database, api::EvaluationPool& pool,
                     std::string software_version)
    : open_database_(std::move(open_database)),
      pool_(pool),
      software_version_(std::move(software_version)),
      fits_(open_database_, api::WorkerPoolOptions{.workers = 1, .task_noun = "job fits"}) {}

Scheduler::~Scheduler() {
  stop();
  cancel_fits_ = true;
  fits_.stop();
}

void Scheduler::wait_for_fits() { fits_.wait_idle(); }

void Scheduler::leave_in_flight(std::int64_t job_id) {
  std::lock_guard lock(in_flight_->mutex);
  in_flight_->jobs.erase(job_id);
}

void Scheduler::submit_evaluation(api::EvaluationRequest request, const storage::JobRecord& job) {
  const std::int64_t job_id = job.id;
  const std::string name = job.name;
  pool_.submit(std::move(request),
               [in_flight = in_flight_, job_id, name](const api::TicketState& done) {
                 if (done.status != "succeeded")
                   spdlog::error("job {} ({}): evaluation failed: {}", job_id, name, done.error);
                 std::lock_guard lock(in_flight->mutex);
                 in_flight->jobs.erase(job_id);
               });
}

void Scheduler::refit_then_evaluate(storage::Database& db, const storage::JobRecord& job,
                                    const api::FitRequest& fit) {
  const std::int64_t fit_id = api::record_queued_fit(db, fit);
  storage::JobRepository(db).set_last_fit(job.id, fit_id);
  api::run_fit(db, fit, fit_id);
  spdlog::info("job {} ({}): fit {} succeeded; evaluating with it", job.id, job.name, fit_id);
  submit_evaluation(api::job_evaluation_request(db, job, software_version_, fit_id), job);
}

std::set<std::int64_t> Scheduler::in_flight() const {
  std::lock_guard lock(in_flight_->mutex);
  return in_flight_->jobs;
}

TickReport Scheduler::tick(std::int64_t now_unix_s) {
  if (!db_) db_.emplace(open_database_());
  storage::Database& db = *db_;
  storage::JobRepository jobs(db);
  TickReport report;
  for (const storage::JobRecord& job : jobs.list()) {
    if (job.paused) continue;
    std::optional<api::CronSchedule> schedule;
    try {
      schedule = api::CronSchedule::parse(job.schedule);
    } catch (const std::invalid_argument& e) {
      spdlog::error("job {} ({}): {}", job.id, job.name, e.what());
      continue;
    }
    const auto next = schedule->next_after(now_unix_s);
    const std::optional<std::string> next_text =
        next ? std::optional<std::string>(api::job_time_text(*next)) : std::nullopt;
    if (!job.next_run_utc) {
      jobs.set_next_run(job.id, next_text);
      continue;
    }
    double due_s = 0;
    try {
      due_s = api::parse_iso8601_time(*job.next_run_utc, "next_run").unix_time_utc_s;
    } catch (const api::ApiError& e) {
      // A next run this program cannot read is replaced, not run.
      spdlog::error("job {} ({}): next run '{}': {}; recomputed", job.id, job.name,
                    *job.next_run_utc, e.what());
      jobs.set_next_run(job.id, next_text);
      continue;
    }
    if (due_s > static_cast<double>(now_unix_s)) continue;
    {
      std::lock_guard lock(in_flight_->mutex);
      if (in_flight_->jobs.count(job.id) > 0) {
        // Still running from an earlier occurrence: this one is skipped, not queued behind it,
        // and counted on the job (GET /v1/jobs/{id}: skipped_count, last_skipped).
        jobs.record_skip(job.id, api::job_time_text(now_unix_s), next_text);
        spdlog::warn("job {} ({}): due at {} while its previous run is still going; skipped",
                     job.id, job.name, *job.next_run_utc);
        ++report.skipped_running;
        continue;
      }
    }
    // Claimed before it is queued: a crash after this point loses this run (it is not repeated
    // after restart), a crash before it runs it once after restart.
    if (!jobs.claim_run(job.id, *job.next_run_utc, api::job_time_text(now_unix_s), next_text))
      continue;
    try {
      if (job.refit.empty()) {
        api::EvaluationRequest request = api::job_evaluation_request(db, job, software_version_);
        {
          std::lock_guard lock(in_flight_->mutex);
          in_flight_->jobs.insert(job.id);
        }
        submit_evaluation(std::move(request), job);
      } else {
        api::FitRequest fit =
            api::job_fit_request(db, job, api::job_dataset_name(db, job), software_version_);
        fit.cancel = &cancel_fits_;
        {
          std::lock_guard lock(in_flight_->mutex);
          in_flight_->jobs.insert(job.id);
        }
        const std::int64_t job_id = job.id;
        const std::string name = job.name;
        api::WorkerTask task;
        task.run = [this, job, fit](storage::Database& worker_db) {
          refit_then_evaluate(worker_db, job, fit);
        };
        task.failed = [this, job_id, name](const std::string& error) {
          spdlog::error("job {} ({}): fit failed, nothing evaluated: {}", job_id, name, error);
          leave_in_flight(job_id);
        };
        task.dropped = [this, job_id] { leave_in_flight(job_id); };
        fits_.submit(std::move(task));
      }
      spdlog::info("job {} ({}): started; next run {}", job.id, job.name,
                   next_text.value_or("never"));
      ++report.started;
    } catch (const std::exception& e) {
      {
        std::lock_guard lock(in_flight_->mutex);
        in_flight_->jobs.erase(job.id);
      }
      spdlog::error("job {} ({}): cannot start: {}", job.id, job.name, e.what());
      ++report.failed_to_start;
    }
  }
  return report;
}

void Scheduler::start() {
  stop();
  {
    std::lock_guard lock(mutex_);
    stopping_ = false;
  }
  thread_ = std::thread([this] {
    using namespace std::chrono;
    for (;;) {
      const std::int64_t now =
          duration_cast<seconds>(system_clock::now().time_since_epoch()).count();
      try {
        tick(now);
      } catch (const std::exception& e) {
        spdlog::error("scheduler: {}", e.what());
      }
      const auto wake = system_clock::time_point(seconds((now / 60 + 1) * 60));
      std::unique_lock lock(mutex_);
      if (stop_signal_.wait_until(lock, wake, [this] { return stopping_; })) return;
    }
  });
}

void Scheduler::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_signal_.notify_all();
  if (thread_.joinable()) thread_.join();
}

}  // namespace clearsky::server
