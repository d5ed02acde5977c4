// SCHED_IDLE for background table work (background_priority.h).
#include "server/tables/background_priority.h"

#include <spdlog/spdlog.h>

#include <exception>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#endif

namespace clearsky::server {

bool lower_this_thread_to_idle_priority() {
#if defined(__linux__)
  const sched_param param{};  // SCHED_IDLE takes priority 0
  if (::sched_setscheduler(0, SCHED_IDLE, &param) == 0) return true;
  spdlog::warn(
      "background work: cannot set SCHED_IDLE on its thread; it runs at the normal "
      "priority");
#endif
  return false;
}

void run_at_idle_priority(const std::function<void()>& work) {
  std::exception_ptr error;
  std::thread thread([&] {
    lower_this_thread_to_idle_priority();
    try {
      work();
    } catch (...) {
      error = std::current_exception();
    }
  });
  thread.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace clearsky::server
