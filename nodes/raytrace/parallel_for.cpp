// parallel_for(): std::thread workers pulling blocks of indices from an atomic counter; and in
// batches with progress reports between them.
#include "nodes/raytrace/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace lg {

void parallel_for(size_t count, const std::function<void(size_t)>& body, unsigned threads) {
  if (count == 0) return;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  // Blocks small enough to balance, large enough that the counter is not contended.
  const size_t block = std::max<size_t>(1, count / (size_t(threads) * 16));
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    for (;;) {
      const size_t begin = next.fetch_add(block);
      if (begin >= count || failed.load()) return;
      const size_t end = std::min(count, begin + block);
      try {
        for (size_t i = begin; i < end; ++i) body(i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  const unsigned workers = unsigned(std::min<size_t>(threads, (count + block - 1) / block));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

void parallel_for_with_progress(size_t count, const std::function<void(size_t)>& body,
                                const std::function<void(size_t)>& progress) {
  const size_t batch = progress ? std::max<size_t>(1024, count / 200) : std::max<size_t>(1, count);
  for (size_t begin = 0; begin < count; begin += batch) {
    const size_t end = std::min(count, begin + batch);
    parallel_for(end - begin, [&](size_t j) { body(begin + j); });
    if (progress) progress(end);
  }
}

}  // namespace lg
