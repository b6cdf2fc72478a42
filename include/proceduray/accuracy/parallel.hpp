// Ground truth on every core: the rows of an image (any index range) handed out to worker
// threads, each with its own accumulator, merged afterwards in worker order. The truth of a ray
// depends on that ray alone (the shared GLSL keeps no state: a marcher takes its field as a
// parameter), so the result does not depend on the schedule.
//
//   std::vector<std::uint64_t> per_worker(proceduray::accuracy::worker_count());   // e.g. evaluations
//   proceduray::accuracy::parallel_rows(height, [&](std::uint32_t y, std::uint32_t worker) {
//     per_worker[worker] += trace_row(y);        // pixels of row y: written by this call only
//   });
//   std::uint64_t total = 0;
//   for (std::uint64_t n : per_worker) total += n;
//
// Workers: PROCEDURAY_THREADS when set (1: on the calling thread), else every hardware thread.
// An exception thrown by a row is rethrown after every worker stopped: the one of the lowest row
// that threw, so a bad input reports the same error whatever the schedule.
#pragma once

#include <proceduray/error.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace proceduray::accuracy {

/// Worker threads parallel_rows uses: PROCEDURAY_THREADS (1 to 1024) when set, else
/// std::thread::hardware_concurrency() (at least 1). Throws UsageError for a malformed value.
inline std::uint32_t worker_count() {
  if (const char* text = std::getenv("PROCEDURAY_THREADS"); text != nullptr && *text != '\0') {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (*end != '\0' || n < 1 || n > 1024) {
      throw UsageError("accuracy::worker_count: PROCEDURAY_THREADS='" + std::string(text) +
                       "' is not a thread count; give 1 to 1024, or unset it to use every core");
    }
    return static_cast<std::uint32_t>(n);
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls fn(row, worker) once for every row in [0, rows), on up to `workers` threads (worker <
/// workers); returns when all are done. See the header for exceptions.
template <class Fn>
void parallel_rows(std::uint32_t rows, Fn&& fn, std::uint32_t workers = worker_count()) {
  workers = std::max(1u, std::min(workers, rows));
  if (workers <= 1) {
    for (std::uint32_t y = 0; y < rows; ++y) fn(y, 0u);
    return;
  }
  std::atomic<std::uint32_t> next{0};
  std::mutex failed;
  std::uint32_t failed_row = rows;
  std::exception_ptr failure;
  auto work = [&](std::uint32_t worker) {
    for (std::uint32_t y = next++; y < rows; y = next++) {
      try {
        fn(y, worker);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failed);
        if (y < failed_row) {
          failed_row = y;
          failure = std::current_exception();
        }
      }
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  for (std::uint32_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
  work(0);
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace proceduray::accuracy
