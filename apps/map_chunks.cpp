// Distributed and resumable grid maps: chunks, checkpoint folder, rank 0's hand-out loop
// (map_chunks.hpp, docs/cluster.md).
#include "map_chunks.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"
#include "mpi_session.hpp"

namespace cpkit::cli {

namespace fs = std::filesystem;

namespace {
constexpr char kMagic[8] = {'c', 'p', 'k', 'c', 'h', 'n', 'k', '1'};
constexpr int kTagDone = 11;    // worker -> rank 0: a finished chunk (or "ready")
constexpr int kTagAssign = 12;  // rank 0 -> worker: the next chunk index, -1 = stop

void put_u64(std::string& s, uint64_t v) {
  char b[8];
  std::memcpy(b, &v, 8);
  s.append(b, 8);
}
uint64_t get_u64(const std::string& s, std::size_t& at) {
  if (at + 8 > s.size()) throw InputError("truncated map chunk");
  uint64_t v = 0;
  std::memcpy(&v, s.data() + at, 8);
  at += 8;
  return v;
}

std::string chunk_path(const std::string& folder, int k) {
  return (fs::path(folder) / ("chunk_" + std::to_string(k) + ".bin")).string();
}

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("cannot read '" + path + "'");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Written under a temporary name and renamed: a chunk file is complete or absent.
void write_file_atomic(const std::string& path, const std::string& bytes) {
  const std::string tmp = path + ".partial";
  {
    std::ofstream f(tmp, std::ios::binary);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.close();
    if (!f) throw InputError("cannot write '" + tmp + "' (disk full?)");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError("cannot write '" + path + "': " + ec.message());
}

/// Rank 0's side: stores finished chunks, consumes them in order.
class Collector {
 public:
  Collector(const ChunkRun& run, std::vector<char> in_checkpoint)
      : run_(run), in_checkpoint_(std::move(in_checkpoint)) {}

  void finished(MapChunk&& c) {
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
        MapChunk c = parse_chunk(read_file(chunk_path(run_.checkpoint, next_)));
        if (c.index != next_) throw InputError("checkpoint chunk " + std::to_string(next_) + " is corrupt");
        run_.consume(c);
      } else {
        break;
      }
      ++next_;
      if (run_.progress) run_.progress("chunks", static_cast<double>(next_) / run_.plan.chunks);
    }
  }
  bool all_consumed() const { return next_ == run_.plan.chunks; }

 private:
  const ChunkRun& run_;
  std::vector<char> in_checkpoint_;
  std::map<int, MapChunk> waiting_;
  int next_ = 0;
};

/// The chunks already finished in the checkpoint (rank 0): with --resume and the same manifest;
/// otherwise the folder is started afresh.
std::vector<char> open_checkpoint(const ChunkRun& run, ChunkRunStats& stats) {
  std::vector<char> have(static_cast<std::size_t>(run.plan.chunks), 0);
  if (run.checkpoint.empty()) {
    if (run.resume) throw InputError("--resume needs --out PREFIX (the checkpoint is PREFIX.parts)");
    return have;
  }
  const fs::path dir(run.checkpoint);
  const fs::path manifest = dir / "manifest.json";
  std::error_code ec;
  if (run.resume) {
    if (!fs::exists(manifest))
      throw InputError("--resume: no checkpoint in '" + dir.string() + "' (nothing to resume: run "
                       "without --resume)");
    const nlohmann::json old = parse_checkpoint_manifest(read_file(manifest.string()),
                                                         manifest.string());
    for (const auto& [key, value] : run.manifest.items())
      if (!old.contains(key) || old[key] != value)
        throw InputError("--resume: the checkpoint in '" + dir.string() + "' was made for a "
                         "different map (" + key + " differs: " +
                         (old.contains(key) ? json_excerpt(old[key], 80) : std::string("absent")) +
                         " there, " + json_excerpt(value, 80) + " now); remove it or run without "
                         "--resume");
    for (int k = 0; k < run.plan.chunks; ++k)
      if (fs::exists(chunk_path(run.checkpoint, k))) {
        have[static_cast<std::size_t>(k)] = 1;
        ++stats.resumed_chunks;
        stats.resumed_cells += static_cast<int64_t>(run.plan.end(k) - run.plan.begin(k)) * run.plan.columns;
      }
    return have;
  }
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec) throw InputError("cannot create the checkpoint folder '" + dir.string() + "'");
  write_file_atomic(manifest.string(), run.manifest.dump(1) + "\n");
  return have;
}

[[noreturn]] void fail_job(const char* what, int code) {
  std::cerr.clear();  // ranks other than 0 are silenced (main.cpp): this message must show
  std::cerr << "cpkit map: rank " << mpi::rank() << " of " << mpi::size() << ": " << what
            << "; the job stops (finished chunks stay in the checkpoint for --resume)\n";
  mpi::abort(code);
}
}  // namespace

std::string serialize_chunk(const MapChunk& c) {
  std::string s(kMagic, 8);
  put_u64(s, static_cast<uint64_t>(c.index));
  put_u64(s, static_cast<uint64_t>(c.row_begin));
  put_u64(s, static_cast<uint64_t>(c.row_end));
  put_u64(s, static_cast<uint64_t>(c.rank));
  const std::string j = c.summary.dump();
  put_u64(s, j.size());
  s += j;
  put_u64(s, c.arrays.size());
  for (const auto& a : c.arrays) {
    put_u64(s, a.size());
    s += a;
  }
  return s;
}

MapChunk parse_chunk(const std::string& b) {
  if (b.size() < 8 || std::memcmp(b.data(), kMagic, 8) != 0) throw InputError("not a cpkit map chunk");
  std::size_t at = 8;
  MapChunk c;
  c.index = static_cast<int>(get_u64(b, at));
  c.row_begin = static_cast<int>(get_u64(b, at));
  c.row_end = static_cast<int>(get_u64(b, at));
  c.rank = static_cast<int>(get_u64(b, at));
  const uint64_t jn = get_u64(b, at);
  if (jn > b.size() - at) throw InputError("truncated map chunk");
  try {  // the one bounded JSON parser (nesting, numbers): a hostile file cannot crash it
    c.summary = parse_json_bounded(b.substr(at, jn), "map chunk summary");
  } catch (const InputError& e) {
    throw InputError(std::string("corrupt map chunk summary: ") + e.what());
  }
  at += jn;
  const uint64_t na = get_u64(b, at);
  if (na > 64) throw InputError("corrupt map chunk");
  for (uint64_t i = 0; i < na; ++i) {
    const uint64_t n = get_u64(b, at);
    if (n > b.size() - at) throw InputError("truncated map chunk");
    c.arrays.push_back(b.substr(at, n));
    at += n;
  }
  if (at != b.size()) throw InputError("corrupt map chunk (trailing bytes)");
  return c;
}

nlohmann::json parse_checkpoint_manifest(const std::string& text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = parse_json_bounded(text, origin);
  } catch (const InputError& e) {
    throw InputError("--resume: '" + origin + "' is not a checkpoint manifest: " + e.what());
  }
  if (!j.is_object())
    throw InputError("--resume: '" + origin + "' is not a checkpoint manifest (not a JSON object)");
  return j;
}

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
  ChunkRunStats stats;
  stats.ranks = mpi::size();
  stats.rank_cells.assign(static_cast<std::size_t>(stats.ranks), 0);
  const bool distributed = mpi::active() && mpi::size() > 1;
  auto cells_of = [&](int k) {
    return static_cast<int64_t>(run.plan.end(k) - run.plan.begin(k)) * run.plan.columns;
  };
  if (!distributed) {
    const std::vector<char> have = open_checkpoint(run, stats);
    Collector col(run, have);
    col.drain();
    for (int k = 0; k < run.plan.chunks; ++k) {
      if (have[static_cast<std::size_t>(k)]) continue;
      MapChunk c = run.compute(k);
      stats.rank_cells[0] += cells_of(k);
      col.finished(std::move(c));
    }
    if (!col.all_consumed()) throw std::logic_error("map chunks left unconsumed");
    return stats;
  }

  // Distributed. Rank 0 decides what is missing (input errors there stop every rank cleanly:
  // the others wait for their first assignment, which is then "stop").
  if (mpi::rank() != 0) {
    try {
      mpi::send_bytes(std::string(), 0, kTagDone);  // ready
      for (;;) {
        const long long k = mpi::recv_int(0, kTagAssign);
        if (k < 0) break;
        MapChunk c = run.compute(static_cast<int>(k));
        c.rank = mpi::rank();
        mpi::send_bytes(serialize_chunk(c), 0, kTagDone);
      }
    } catch (const InputError& e) {
      fail_job(e.what(), 2);
    } catch (const std::exception& e) {
      fail_job(e.what(), 4);
    }
    return stats;  // the per-rank figures are rank 0's
  }
  std::vector<char> have;
  try {
    have = open_checkpoint(run, stats);
  } catch (const InputError&) {
    // Release the workers, then report the input error as a single process would.
    for (int r = 1; r < mpi::size(); ++r) {
      int from = 0;
      (void)mpi::recv_bytes(kTagDone, &from);
      mpi::send_int(-1, from, kTagAssign);
    }
    throw;
  }
  try {
    Collector col(run, have);
    col.drain();
    std::vector<int> todo;
    for (int k = run.plan.chunks - 1; k >= 0; --k)
      if (!have[static_cast<std::size_t>(k)]) todo.push_back(k);  // back = the next to hand out
    // Rank 0 computes chunks too, on a thread of its own, so that its main thread (the only
    // one that calls MPI) answers the other ranks at once: a rank never waits for its next
    // chunk while rank 0 computes.
    std::mutex mutex;
    std::vector<MapChunk> local_done;
    std::exception_ptr local_error;
    bool local_running = true;
    auto take = [&](int& k) {
      std::lock_guard<std::mutex> lock(mutex);
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
          stats.rank_cells[0] += cells_of(k);
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
    int workers = mpi::size() - 1;
    for (;;) {
      bool idle = true;
      int from = 0;
      if (workers > 0 && mpi::probe(kTagDone, &from, false)) {
        idle = false;
        const std::string bytes = mpi::recv_bytes(kTagDone, &from);
        if (!bytes.empty()) {
          MapChunk c = parse_chunk(bytes);
          stats.rank_cells[static_cast<std::size_t>(from)] += cells_of(c.index);
          col.finished(std::move(c));
        }
        int k = -1;
        if (take(k)) {
          mpi::send_int(k, from, kTagAssign);
        } else {
          mpi::send_int(-1, from, kTagAssign);
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
    if (!col.all_consumed()) throw std::logic_error("map chunks left unconsumed");
  } catch (const InputError& e) {
    fail_job(e.what(), 2);
  } catch (const std::exception& e) {
    fail_job(e.what(), 4);
  }
  return stats;
}

void remove_checkpoint(const std::string& folder) {
  if (folder.empty()) return;
  std::error_code ec;
  fs::remove_all(folder, ec);
}

ChunkRunStats run_map_chunks(const std::string& out_prefix, bool resume,
                             const nlohmann::json& manifest, const ChunkPlan& plan,
                             const std::function<MapChunk(int)>& compute,
                             const std::function<void(const MapChunk&)>& consume,
                             const rate::MapProgress& progress) {
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
  }
  if (mpi::rank() == 0) run.progress = progress;
  return run_chunks(run);
}

void add_run_figures(nlohmann::json& j, const ChunkRunStats& st) {
  j["ranks"] = st.ranks;
  j["rank_cells"] = st.rank_cells;
  if (st.resumed_chunks > 0) j["resumed_cells"] = st.resumed_cells;
}

nlohmann::json boxes_to_json(const std::vector<rate::GridClassBox>& boxes) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& b : boxes) out.push_back({b.code, b.cells, b.x_min, b.x_max, b.y_min, b.y_max});
  return out;
}

void merge_boxes(std::map<int, rate::GridClassBox>& into, const nlohmann::json& boxes) {
  for (const auto& b : boxes) {
    const int code = b.at(0).get<int>();
    rate::GridClassBox& g = into[code];
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

}  // namespace cpkit::cli
