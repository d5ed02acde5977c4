// Background work at the lowest CPU priority (docs/tables-and-memory.md "Background work"): the
// pass over the day's per-sun states and the tables queued to build after start (serve
// --prebuild-three's) run under Linux's SCHED_IDLE, so that they get a core only when no request
// (nor anything else at a normal priority) wants it and HTTP answers are not slowed by them. The
// policy is the thread's own (Linux applies sched_setscheduler(0, ...) to the calling thread),
// and threads it creates inherit it: a precomputation's worker threads (parallel_for,
// PrecomputeContext::threads) run at the same priority as the thread that started it. An
// unprivileged thread cannot leave SCHED_IDLE again, hence run_at_idle_priority's thread of its
// own; the start builds and a build a request starts keep the normal priority.
// Elsewhere than Linux both do nothing at all and report false.
#pragma once

#include <functional>

namespace clearsky::server {

// Puts the calling thread under SCHED_IDLE for good; whether it applied.
bool lower_this_thread_to_idle_priority();

// Runs work on a thread of its own under SCHED_IDLE and waits for it (rethrowing what it
// throws), so that the calling thread keeps its priority.
void run_at_idle_priority(const std::function<void()>& work);

}  // namespace clearsky::server
