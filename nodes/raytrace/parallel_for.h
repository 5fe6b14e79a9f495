// Runs a function over the indices [0, count) on all cores. Work is handed out in small blocks
// from a shared counter, so uneven items balance; each index runs exactly once, on some thread,
// so a body that writes only its own index's result gives the same output on any thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace lg {

// threads = 0: std::thread::hardware_concurrency(). The first exception a body throws is
// rethrown here after every thread has stopped (the remaining indices are skipped).
void parallel_for(size_t count, const std::function<void(size_t index)>& body, unsigned threads = 0);

// parallel_for on all cores in batches of about 1/200 of the count (at least 1,024 indices),
// calling `progress` (when given) from the calling thread after each with the indices done.
void parallel_for_with_progress(size_t count, const std::function<void(size_t index)>& body,
                                const std::function<void(size_t done)>& progress);

}  // namespace lg
