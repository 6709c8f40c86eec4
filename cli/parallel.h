// Work spread over threads for `--jobs N` (cosim's frames, sweep's points).
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rastersim {

// Calls task(i) once for each i in [0, count), on `jobs` threads (the calling one included),
// starting the indices in increasing order. An index at or beyond limit() (when given; it may
// shrink while tasks run) is not started. The first exception a task throws stops the others from
// starting more and is rethrown here once all have returned.
inline void parallel_for(int jobs, size_t count, const std::function<void(size_t)>& task,
                         const std::function<size_t()>& limit = nullptr) {
  std::atomic<size_t> next{0};
  std::mutex mutex;
  std::exception_ptr error;
  auto worker = [&] {
    try {
      for (size_t i = next++; i < count && (!limit || i < limit()); i = next++) task(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace rastersim
