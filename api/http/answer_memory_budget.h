// The server-wide byte budget of answer buffers in flight (docs/threat-model.md "exhaust memory
// with answers or requests"): a streamed answer holds a buffer while its client reads (a skydome
// its band of rows, api/skydome/skydome_render.h), for as long as the client takes, and each
// worker may hold one; without a bound across workers slow readers alone can grow the process by
// hundreds of megabytes. An answer reserves its buffer bytes before computing; the reservation is
// released when the object returned by try_reserve() is destroyed (the answer ended, or its
// connection was cut). When the bytes do not fit, try_reserve() returns null and the caller
// refuses the answer (503 naming answer_memory) instead of growing memory.
//
// | option        | unit | default | meaning                                                 |
// |---------------|------|---------|---------------------------------------------------------|
// | limit_bytes   | byte | 256 MiB | answer buffer bytes in flight, every worker together    |
//
// Thread-safety: every member may be called from any thread; a reservation may outlive the
// budget object (it keeps the shared counter alive).
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>

namespace clearsky::api {

class AnswerMemoryBudget {
 public:
  // What an answer holds while it is in flight; releases its bytes when destroyed.
  class Reservation;

  explicit AnswerMemoryBudget(std::size_t limit_bytes);

  // bytes reserved until the result is destroyed; null when reserved_bytes() + bytes would be
  // above limit_bytes() (nothing is reserved then).
  std::shared_ptr<const Reservation> try_reserve(std::size_t bytes);

  std::size_t limit_bytes() const { return counter_->limit_bytes; }
  std::size_t reserved_bytes() const { return counter_->reserved_bytes.load(); }

 private:
  struct Counter {
    std::size_t limit_bytes = 0;
    std::atomic<std::size_t> reserved_bytes{0};
  };
  std::shared_ptr<Counter> counter_;
};

class AnswerMemoryBudget::Reservation {
 public:
  Reservation(std::shared_ptr<Counter> counter, std::size_t bytes)
      : counter_(std::move(counter)), bytes_(bytes) {}
  ~Reservation() { counter_->reserved_bytes.fetch_sub(bytes_); }
  Reservation(const Reservation&) = delete;
  Reservation& operator=(const Reservation&) = delete;

  std::size_t bytes() const { return bytes_; }

 private:
  std::shared_ptr<Counter> counter_;
  std::size_t bytes_;
};

}  // namespace clearsky::api
