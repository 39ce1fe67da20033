#pragma once
/// fn(i) for every i in [0, n) on up to `threads` threads (internal to contact/; not its API).
/// Each i is taken by one thread, in chunks handed out as threads come free; fn must write only
/// what belongs to i, so the results do not depend on the thread count. The first exception a
/// thread throws is rethrown here once all have stopped.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace inpact::contact {

/// `min_per_thread`: below this many items per thread a thread costs more than it saves
/// (starting one costs some 10 µs: a slave facet's points take about ten times that).
template <class Fn>
void parallel_for(std::size_t n, int threads, std::size_t min_per_thread, Fn&& fn) {
  const std::size_t n_threads =
      std::min(static_cast<std::size_t>(std::max(threads, 1)), n / std::max<std::size_t>(min_per_thread, 1));
  if (n_threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  const std::size_t chunk = std::max<std::size_t>(1, n / (8 * n_threads));
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    try {
      for (std::size_t begin; (begin = next.fetch_add(chunk)) < n;)
        for (std::size_t i = begin; i < std::min(n, begin + chunk); ++i) fn(i);
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      next = n;  // the others stop at their next chunk
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < n_threads; ++t) pool.emplace_back(work);
    work();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace inpact::contact
