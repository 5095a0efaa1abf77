#pragma once
// Internal to the map engines: running independent work items (rows of a grid map) on threads.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <initializer_list>
#include <mutex>
#include <thread>
#include <string>
#include <utility>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"

namespace cpkit::rate {

/// One cell array of a block of rows, as the bytes of a map chunk (map_run.hpp).
struct RawCells {
  std::string* bytes;
  const void* data;  ///< null: an absent array (skipped)
  std::size_t item_bytes = 1;
};

/// Appends `cells` items of every present array to its bytes.
inline void append_raw_cells(std::size_t cells, std::initializer_list<RawCells> arrays) {
  for (const RawCells& a : arrays)
    if (a.data) a.bytes->append(static_cast<const char*>(a.data), cells * a.item_bytes);
}

/// Cells of a block of rows [row_begin, row_end) of a grid with `cols` columns.
template <class Rows>
std::size_t block_cells(const Rows& r, int cols) {
  return static_cast<std::size_t>(r.row_end - r.row_begin) * static_cast<std::size_t>(cols);
}

/// The rows [first, last) a call computes; throws InputError for a range outside [0, rows].
inline std::pair<int, int> checked_range(const RowRange& r, int rows) {
  const int end = r.end < 0 ? rows : r.end;
  if (r.begin < 0 || r.begin > end || end > rows)
    throw InputError("row range [" + std::to_string(r.begin) + ", " + std::to_string(end) +
                     ") is outside the map's " + std::to_string(rows) + " rows");
  return {r.begin, end};
}

/// Throws InputError unless a param-direction map's direction count is in [1, 1000000].
inline void check_theta_n(int theta_n) {
  if (theta_n < 1 || theta_n > 1000000)
    throw InputError("theta-n must be in [1, 1000000], got " + std::to_string(theta_n));
}

/// The classes of a grid map with cells, in code order (code = index + first_code).
template <std::size_t K>
std::vector<GridClassBox> present_classes(std::array<GridClassBox, K>& boxes, int first_code) {
  std::vector<GridClassBox> v;
  for (std::size_t c = 0; c < K; ++c)
    if (boxes[c].cells > 0) {
      boxes[c].code = static_cast<int>(c) + first_code;
      v.push_back(boxes[c]);
    }
  return v;
}

inline int resolve_threads(int requested, int64_t work_items) {
  int t = requested;
  if (t <= 0) t = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (work_items < t) t = static_cast<int>(std::max<int64_t>(1, work_items));
  return t;
}

/// Runs fn(i) for every i in [begin, end) on `threads` workers (items handed out one at a time;
/// one worker: the calling thread itself).
/// Results must be stored by index by fn, so the outcome does not depend on the thread count.
/// The calling thread calls report(items done) about every 0.1 s. The first exception of a
/// worker is rethrown.
template <class ItemFn, class Report>
void run_items(int begin, int end, int threads, ItemFn&& fn, Report&& report) {
  threads = std::max(1, std::min(threads, end - begin));
  if (threads == 1) {  // in the calling thread: no thread to start for small or nested work
    auto last = std::chrono::steady_clock::now();
    for (int i = begin; i < end; ++i) {
      fn(i);
      const auto now = std::chrono::steady_clock::now();
      if (now - last > std::chrono::milliseconds(100)) {
        last = now;
        report(i + 1 - begin);
      }
    }
    return;
  }
  std::atomic<int> next{begin}, done{0};
  std::mutex mutex;
  std::condition_variable cv;
  int active = threads;
  std::exception_ptr error;
  auto worker = [&] {
    try {
      for (;;) {
        const int i = next.fetch_add(1);
        if (i >= end) break;
        fn(i);
        done.fetch_add(1);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      next.store(end);
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      --active;
    }
    cv.notify_all();
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (active > 0) {
      cv.wait_for(lock, std::chrono::milliseconds(100));
      if (active > 0) {
        lock.unlock();
        report(done.load());
        lock.lock();
      }
    }
  }
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace cpkit::rate
