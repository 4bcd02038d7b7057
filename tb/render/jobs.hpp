// Runs fn(0) .. fn(count - 1) on up to `jobs` threads (in the calling thread when jobs <= 1 or
// count <= 1). Every index runs even when one throws; the exception of the lowest index that
// threw is rethrown after all have finished, so what fails is the same whatever the number of
// jobs.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace tmu::render {

inline void run_jobs(size_t count, int jobs, const std::function<void(size_t)>& fn) {
  std::vector<std::exception_ptr> errors(count);
  std::atomic<size_t> next{0};
  const auto worker = [&] {
    for (size_t i = next++; i < count; i = next++) {
      try {
        fn(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  const size_t threads = std::min(count, static_cast<size_t>(std::max(jobs, 1)));
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace tmu::render
