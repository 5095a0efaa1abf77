// The run of a map's chunks (map_run.hpp): one process, or rank 0 handing chunks out to the
// ranks of a job through the injected transport; rank 0 stores and consumes them in order.
#include "cpkit/rate_problem/maps/map_run.hpp"

#include <chrono>
#include <exception>
#include <string>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "cpkit/core/errors.hpp"
#include "map_checkpoint.hpp"

namespace cpkit::rate {

namespace {
constexpr int kTagDone = 11;    // worker -> rank 0: a finished chunk (or "ready")
constexpr int kTagAssign = 12;  // rank 0 -> worker: the next chunk index, -1 = stop

/// Rank 0's side: stores finished chunks, consumes them in order.
class Collector {
 public:
  Collector(const ChunkRun& run, std::vector<char> in_checkpoint)
      : run_(run), in_checkpoint_(std::move(in_checkpoint)) {}

  void finished(MapChunk&& c) {
    c.map_id = run_.map_id;
    if (!run_.checkpoint.empty()) write_file_atomic(chunk_path(run_.checkpoint, c.index), serialize_chunk(c));
    const int k = c.index;
    waiting_.emplace(k, std::move(c));
    drain();
  }
  /// Consumes what is ready: the next chunk in order, from memory or from the checkpoint.
  void drain() {
    while (next_ < run_.plan.chunks) {
      auto it = waiting_.find(next_);
      if (it != waiting_.end()) {
        run_.consume(it->second);
        waiting_.erase(it);
      } else if (in_checkpoint_[static_cast<std::size_t>(next_)]) {
        run_.consume(read_chunk(run_, chunk_path(run_.checkpoint, next_), next_));
      } else {
        break;
      }
      ++next_;
      if (run_.progress) run_.progress("chunks", static_cast<double>(next_) / run_.plan.chunks);
    }
  }
  bool all_consumed() const { return next_ == run_.plan.chunks; }
  /// The rows consumed so far (the first ones, in order).
  int rows_consumed() const { return next_ == 0 ? 0 : run_.plan.end(next_ - 1); }

 private:
  const ChunkRun& run_;
  std::vector<char> in_checkpoint_;
  std::map<int, MapChunk> waiting_;
  int next_ = 0;
};


[[noreturn]] void fail_job(MapTransport& t, const char* what, int code) {
  t.abort("cpkit map: rank " + std::to_string(t.rank()) + " of " + std::to_string(t.size()) +
              ": " + what + "; the job stops (finished chunks stay in the checkpoint for --resume)",
          code);
  std::terminate();  // abort() never returns; GCC does not carry [[noreturn]] through virtuals
}

int64_t cells_of(const ChunkPlan& p, int k) {
  return static_cast<int64_t>(p.end(k) - p.begin(k)) * p.columns;
}

/// One process: the missing chunks in order, at most run.chunk_limit of them.
void run_local(const ChunkRun& run, ChunkRunStats& stats) {
  const std::vector<char> have = open_checkpoint(run, stats);
  Collector col(run, have);
  col.drain();
  int computed = 0;
  for (int k = 0; k < run.plan.chunks; ++k) {
    if (have[static_cast<std::size_t>(k)]) continue;
    if (run.chunk_limit >= 0 && computed >= run.chunk_limit) break;
    if (run.stop && run.stop()) {
      stats.stopped = true;
      break;
    }
    MapChunk c = run.compute(k);
    ++computed;
    stats.rank_cells[0] += cells_of(run.plan, k);
    col.finished(std::move(c));
  }
  stats.complete = col.all_consumed();
  stats.rows_done = col.rows_consumed();
  if (stats.stopped && run.progress) run.progress("chunks", -1);
  if (!stats.complete && run.chunk_limit < 0 && !stats.stopped)
    throw std::logic_error("map chunks left unconsumed");
}

/// A rank other than 0: computes the chunks rank 0 assigns until told to stop.
void run_worker(const ChunkRun& run, MapTransport& t) {
  try {
    t.send_bytes(std::string(), 0, kTagDone);  // ready
    for (;;) {
      const long long k = t.recv_int(0, kTagAssign);
      if (k < 0) break;
      MapChunk c = run.compute(static_cast<int>(k));
      c.rank = t.rank();
      t.send_bytes(serialize_chunk(c), 0, kTagDone);
    }
  } catch (const InputError& e) {
    fail_job(t, e.what(), 2);
  } catch (const std::exception& e) {
    fail_job(t, e.what(), 4);
  }
}

/// Rank 0 of a job: hands out the missing chunks, computes some itself, consumes in order.
void run_rank0(const ChunkRun& run, MapTransport& t, const std::vector<char>& have,
               ChunkRunStats& stats) {
  Collector col(run, have);
  col.drain();
  std::vector<int> todo;
  for (int k = run.plan.chunks - 1; k >= 0; --k)
    if (!have[static_cast<std::size_t>(k)]) todo.push_back(k);  // back = the next to hand out
  // Rank 0 computes chunks too, on a thread of its own, so that its main thread (the only
  // one that calls the transport) answers the other ranks at once: a rank never waits for its
  // next chunk while rank 0 computes.
  std::mutex mutex;
  std::vector<MapChunk> local_done;
  std::exception_ptr local_error;
  bool local_running = true;
  bool stopped = false;  // run.stop said so: no chunk is begun or handed out any more
  auto take = [&](int& k) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!todo.empty() && !stopped && run.stop && run.stop()) {
      stopped = true;
      todo.clear();
    }
    if (todo.empty()) return false;
    k = todo.back();
    todo.pop_back();
    return true;
  };
  std::thread local([&] {
    try {
      for (int k; take(k);) {
        MapChunk c = run.compute(k);
        std::lock_guard<std::mutex> lock(mutex);
        stats.rank_cells[0] += cells_of(run.plan, k);
        local_done.push_back(std::move(c));
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      local_error = std::current_exception();
      todo.clear();
    }
    std::lock_guard<std::mutex> lock(mutex);
    local_running = false;
  });
  struct Join {
    std::thread& t;
    ~Join() { if (t.joinable()) t.join(); }
  } join{local};
  int workers = t.size() - 1;
  for (;;) {
    bool idle = true;
    int from = 0;
    if (workers > 0 && t.probe(kTagDone, &from, false)) {
      idle = false;
      const std::string bytes = t.recv_bytes(kTagDone, &from);
      if (!bytes.empty()) {
        MapChunk c = parse_chunk(bytes);
        stats.rank_cells[static_cast<std::size_t>(from)] += cells_of(run.plan, c.index);
        col.finished(std::move(c));
      }
      int k = -1;
      if (take(k)) {
        t.send_int(k, from, kTagAssign);
      } else {
        t.send_int(-1, from, kTagAssign);
        --workers;
      }
    }
    std::vector<MapChunk> mine;
    bool running = true;
    {
      std::lock_guard<std::mutex> lock(mutex);
      mine.swap(local_done);
      running = local_running;
      if (local_error) std::rethrow_exception(local_error);
    }
    for (auto& c : mine) col.finished(std::move(c));
    if (!mine.empty()) idle = false;
    if (workers == 0 && !running) break;
    if (idle) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  stats.rows_done = col.rows_consumed();
  stats.stopped = stopped;
  if (stopped && run.progress) run.progress("chunks", -1);
  stats.complete = col.all_consumed();
  if (!stats.complete && !stopped) throw std::logic_error("map chunks left unconsumed");
}

}  // namespace

ChunkPlan plan_chunks(int rows, int64_t columns) {
  ChunkPlan p;
  p.rows = rows;
  p.columns = columns;
  const int max_rows = static_cast<int>(std::max<int64_t>(1, (int64_t{1} << 20) / std::max<int64_t>(1, columns)));
  p.chunk_rows = std::max(1, std::min(max_rows, (rows + 63) / 64));
  p.chunks = (rows + p.chunk_rows - 1) / p.chunk_rows;
  return p;
}

ChunkRunStats run_chunks(const ChunkRun& run) {
  MapTransport* t = run.transport;
  ChunkRunStats stats;
  stats.ranks = t ? t->size() : 1;
  stats.rank_cells.assign(static_cast<std::size_t>(stats.ranks), 0);
  if (!t || t->size() <= 1) {
    run_local(run, stats);
    return stats;
  }
  if (run.chunk_limit >= 0) throw std::logic_error("ChunkRun::chunk_limit is for one process");
  if (t->rank() != 0) {
    run_worker(run, *t);
    stats.complete = true;
    return stats;  // the per-rank figures are rank 0's
  }
  // Rank 0 decides what is missing (input errors there stop every rank cleanly: the others
  // wait for their first assignment, which is then "stop").
  std::vector<char> have;
  try {
    have = open_checkpoint(run, stats);
  } catch (const InputError&) {
    // Release the workers, then report the input error as a single process would.
    for (int r = 1; r < t->size(); ++r) {
      int from = 0;
      (void)t->recv_bytes(kTagDone, &from);
      t->send_int(-1, from, kTagAssign);
    }
    throw;
  }
  try {
    run_rank0(run, *t, have, stats);
  } catch (const InputError& e) {
    fail_job(*t, e.what(), 2);
  } catch (const std::exception& e) {
    fail_job(*t, e.what(), 4);
  }
  return stats;
}

ChunkRunStats run_map_chunks(const std::string& out_prefix, bool resume,
                             const nlohmann::json& manifest, const ChunkPlan& plan,
                             const std::function<MapChunk(int)>& compute,
                             const std::function<void(const MapChunk&)>& consume,
                             const MapProgress& progress, MapTransport* transport,
                             int chunk_limit, const std::function<bool()>& stop) {
  ChunkRun run;
  run.plan = plan;
  run.compute = compute;
  run.consume = consume;
  run.resume = resume;
  if (!out_prefix.empty()) {
    run.checkpoint = out_prefix + ".parts";
    run.manifest = manifest;
    run.manifest["chunk_rows"] = plan.chunk_rows;
    run.manifest["chunks"] = plan.chunks;
    run.map_id = fnv1a(run.manifest.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  }
  run.transport = transport;
  run.chunk_limit = chunk_limit;
  run.stop = stop;
  if (!transport || transport->rank() == 0) run.progress = progress;
  return run_chunks(run);
}

void add_run_figures(nlohmann::json& j, const ChunkRunStats& st) {
  j["ranks"] = st.ranks;
  j["rank_cells"] = st.rank_cells;
  if (st.resumed_chunks > 0) j["resumed_cells"] = st.resumed_cells;
}

nlohmann::json boxes_to_json(const std::vector<GridClassBox>& boxes) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& b : boxes) out.push_back({b.code, b.cells, b.x_min, b.x_max, b.y_min, b.y_max});
  return out;
}

void merge_boxes(std::map<int, GridClassBox>& into, const nlohmann::json& boxes) {
  for (const auto& b : boxes) {
    const int code = b.at(0).get<int>();
    GridClassBox& g = into[code];
    if (g.cells == 0) {
      g.code = code;
      g.x_min = b.at(2).get<double>();
      g.x_max = b.at(3).get<double>();
      g.y_min = b.at(4).get<double>();
      g.y_max = b.at(5).get<double>();
    } else {
      g.x_min = std::min(g.x_min, b.at(2).get<double>());
      g.x_max = std::max(g.x_max, b.at(3).get<double>());
      g.y_min = std::min(g.y_min, b.at(4).get<double>());
      g.y_max = std::max(g.y_max, b.at(5).get<double>());
    }
    g.cells += b.at(1).get<int64_t>();
  }
}

}  // namespace cpkit::rate
