// The map run in chunks (maps/map_run.hpp, maps/grid_map_run.hpp) called directly: a map stopped
// after a few chunks (ChunkRun::chunk_limit) and resumed from its checkpoint equals the map
// computed independently: the cell counts of the state-b closed form (three solutions exactly
// for mu > a11/a12 and theta between L+ = 0 and N = 0, as in test_map_grid.cpp) and the one-pass
// map; the checkpoint of another map is refused; an N-point map likewise; the distributed path
// (rank 0 hands chunks out) over an injected in-process transport equals the one-pass map.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map_run.hpp"
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"

using namespace cpkit::rate;
namespace fs = std::filesystem;

namespace {
ContactParameters fig5() {
  ContactParameters p;
  p.a11 = 1;
  p.a12 = 0.5;
  p.a22 = 1;
  p.C_T = 0.25;
  p.mu = 3;
  return p;
}
ContactState state_b() {
  ContactState s;
  s.label = StateLabel::kB;
  return s;
}
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("cpkit_test_map_run_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
/// The processes of a job as threads of this one (the transport is injected: no MPI needed).
/// Messages go to the destination's mailbox; abort throws (the job's end, seen by the test).
struct Message {
  int from = 0, tag = 0;
  std::string bytes;
  long long value = 0;
};
struct Mailboxes {
  std::mutex mutex;
  std::condition_variable arrived;
  std::vector<std::deque<Message>> box;
  explicit Mailboxes(int ranks) : box(static_cast<std::size_t>(ranks)) {}
};
class ThreadTransport final : public MapTransport {
 public:
  ThreadTransport(int rank, int size, Mailboxes& m) : rank_(rank), size_(size), m_(m) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void send_bytes(const std::string& b, int dest, int tag) override { post(dest, {rank_, tag, b, 0}); }
  std::string recv_bytes(int tag, int* from) override {
    const Message msg = take(tag, -1);
    if (from) *from = msg.from;
    return msg.bytes;
  }
  bool probe(int tag, int* from, bool wait) override {
    std::unique_lock<std::mutex> lock(m_.mutex);
    for (;;) {
      for (const auto& msg : mine())
        if (msg.tag == tag) {
          if (from) *from = msg.from;
          return true;
        }
      if (!wait) return false;
      m_.arrived.wait(lock);
    }
  }
  void send_int(long long v, int dest, int tag) override { post(dest, {rank_, tag, {}, v}); }
  long long recv_int(int source, int tag) override { return take(tag, source).value; }
  [[noreturn]] void abort(const std::string& message, int) override {
    throw std::runtime_error(message);
  }

 private:
  int rank_, size_;
  Mailboxes& m_;
  std::deque<Message>& mine() { return m_.box[static_cast<std::size_t>(rank_)]; }
  void post(int dest, Message msg) {
    {
      std::lock_guard<std::mutex> lock(m_.mutex);
      m_.box[static_cast<std::size_t>(dest)].push_back(std::move(msg));
    }
    m_.arrived.notify_all();
  }
  Message take(int tag, int source) {
    std::unique_lock<std::mutex> lock(m_.mutex);
    for (;;) {
      auto& q = mine();
      for (auto it = q.begin(); it != q.end(); ++it)
        if (it->tag == tag && (source < 0 || it->from == source)) {
          Message msg = std::move(*it);
          q.erase(it);
          return msg;
        }
      m_.arrived.wait(lock);
    }
  }
};

int chunk_files(const fs::path& parts) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(parts))
    if (e.path().extension() == ".bin") ++n;
  return n;
}
}  // namespace

TEST_CASE("MapRunStoppedAfterChunksAndResumedEqualsTheClosedForm", "[map][run]") {
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 13};  // 13 rows: 13 chunks of one row
  const int tn = 48;
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("pd");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  run.manifest = {{"model", "fig5 b"}};
  run.chunk_limit = 5;
  const ParamDirectionRun cut = run_param_direction_map(fig5(), state_b(), axis, tn, options, run);
  CHECK_FALSE(cut.stats.complete);
  CHECK(chunk_files(dir / "map.parts") == 5);
  CHECK(cut.map.count.size() == 5u * tn);  // the chunks before the first gap are consumed

  run.resume = true;
  run.chunk_limit = -1;
  const ParamDirectionRun full = run_param_direction_map(fig5(), state_b(), axis, tn, options, run);
  REQUIRE(full.stats.complete);
  CHECK(full.stats.resumed_chunks == 5);
  CHECK(full.stats.resumed_cells == 5 * tn);
  CHECK(full.stats.rank_cells.at(0) == 8 * tn);  // only the missing chunks were computed
  REQUIRE(full.map.count.size() == static_cast<std::size_t>(axis.n) * tn);

  // Independent source 1: the closed form of state b (test_map_grid.cpp).
  const double tN = std::atan(0.5);
  int threes = 0;
  for (int i = 0; i < axis.n; ++i) {
    const double mu = axis.value(i);
    const double tL = std::atan((1 + mu * 0.125) / (mu * 1.25));
    for (int j = 0; j < tn; ++j) {
      const double th = full.map.theta[static_cast<std::size_t>(j)];
      if (std::abs(th - tL) < 1e-9 || std::abs(th - tN) < 1e-9) continue;
      const bool three = mu > 2 + 1e-9 && th > tL && th < tN;
      CAPTURE(mu, th);
      CHECK(full.map.count[static_cast<std::size_t>(i) * tn + j] == (three ? 3 : 1));
      threes += three;
    }
  }
  CHECK(threes > 0);
  // Independent source 2: the map in one pass, without chunks.
  const ParamDirectionMap one = compute_param_direction_map(fig5(), state_b(), axis, tn, options);
  CHECK(full.map.count == one.count);
  CHECK(full.map.types == one.types);
  CHECK(full.map.type_cells == one.type_cells);
  REQUIRE(full.map.classes.size() == one.classes.size());
  for (std::size_t k = 0; k < one.classes.size(); ++k) {
    CHECK(full.map.classes[k].code == one.classes[k].code);
    CHECK(full.map.classes[k].cells == one.classes[k].cells);
    CHECK(full.map.classes[k].y_min == one.classes[k].y_min);
    CHECK(full.map.classes[k].y_max == one.classes[k].y_max);
  }
  REQUIRE(full.map.critical_values.size() == 1);  // D+ = 0 at mu = a11/a12 = 2
  CHECK(full.map.critical_values[0].x == Approx(2.0).margin(1e-12));
  CHECK(full.map.critical_directions.size() == one.critical_directions.size());
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunParamParamResumedEqualsTheOnePassMap", "[map][run]") {
  const MapAxis a1{map_parameter("mu"), 0.5, 3.5, 7}, a2{map_parameter("a12"), -0.9, 0.9, 5};
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("pp");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  run.chunk_limit = 3;
  const ParamParamRun cut = run_param_param_map(fig5(), state_b(), a1, a2, options, run);
  CHECK_FALSE(cut.stats.complete);
  run.resume = true;
  run.chunk_limit = 2;  // a second stop, then the rest
  CHECK_FALSE(run_param_param_map(fig5(), state_b(), a1, a2, options, run).stats.complete);
  run.chunk_limit = -1;
  const ParamParamRun full = run_param_param_map(fig5(), state_b(), a1, a2, options, run);
  REQUIRE(full.stats.complete);
  CHECK(full.stats.resumed_chunks == 5);
  const ParamParamMap one = compute_param_param_map(fig5(), state_b(), a1, a2, options);
  CHECK(full.map.cls == one.cls);
  CHECK(full.map.min_count == one.min_count);
  CHECK(full.map.max_count == one.max_count);
  CHECK(full.map.types == one.types);
  CHECK(full.map.critical_curve.size() == one.critical_curve.size());
  // The closed form: state b is non-unique for some direction exactly when mu |a12| > a11.
  for (int i = 0; i < a1.n; ++i)
    for (int j = 0; j < a2.n; ++j) {
      const double prod = a1.value(i) * std::abs(a2.value(j));
      if (std::abs(prod - 1) < 1e-9) continue;
      CAPTURE(a1.value(i), a2.value(j));
      CHECK((full.map.cls[static_cast<std::size_t>(i) * a2.n + j] == 0) == (prod < 1));
    }
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunRefusesTheCheckpointOfAnotherMap", "[map][run]") {
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 4};
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("other");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  run.chunk_limit = 1;
  (void)run_param_direction_map(fig5(), state_b(), axis, 8, options, run);
  run.resume = true;
  run.chunk_limit = -1;
  const MapAxis other{map_parameter("mu"), 0.5, 3.0, 4};
  CHECK_THROWS_WITH(run_param_direction_map(fig5(), state_b(), other, 8, options, run),
                    Catch::Contains("axis.to differs"));
  GridRunOptions none;
  none.resume = true;  // nothing to resume without a checkpoint
  CHECK_THROWS_AS(run_param_direction_map(fig5(), state_b(), axis, 8, options, none),
                  cpkit::InputError);
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunOfNPointsStoppedAndResumedEqualsTheOnePassMap", "[map][run][system]") {
  // docs/examples/coupled_grazing_points.json: coupling alone creates non-uniqueness.
  const ContactSystem sys = parse_contact_system(
      R"({"A": [[2.03, 0.25, -1.23, 1.58], [0.25, 3.76, 1.23, 0.26],
                [-1.23, 1.23, 2.12, -0.99], [1.58, 0.26, -0.99, 2.05]],
          "points": [{"state": "b", "mu": 7.71}, {"state": "b", "mu": 2.03}]})");
  SystemMapAxis axis;
  axis.param = parse_system_map_parameter("coupling", 2);
  axis.from = 0;
  axis.to = 1;
  axis.n = 9;
  const int tn = 60;
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("system");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  run.chunk_limit = 4;
  CHECK_FALSE(run_system_param_direction_map(sys, axis, tn, options, run).stats.complete);
  run.resume = true;
  run.chunk_limit = -1;
  const SystemParamDirectionRun full = run_system_param_direction_map(sys, axis, tn, options, run);
  REQUIRE(full.stats.complete);
  CHECK(full.stats.resumed_chunks == 4);
  const SystemParamDirectionMap one = compute_system_param_direction_map(sys, axis, tn, options);
  CHECK(full.map.count == one.count);
  CHECK(full.map.pattern == one.pattern);  // the patterns renumbered as one pass numbers them
  CHECK(full.map.table.patterns == one.table.patterns);
  CHECK(full.map.table.cells == one.table.cells);
  REQUIRE(full.map.classes.size() == one.classes.size());
  for (std::size_t k = 0; k < one.classes.size(); ++k) {
    CHECK(full.map.classes[k].code == one.classes[k].code);
    CHECK(full.map.classes[k].cells == one.classes[k].cells);
  }
  // docs/maps.md: uncoupled (c = 0) every direction has one solution; coupled, some have 3.
  for (int j = 0; j < tn; ++j) CHECK(full.map.count[static_cast<std::size_t>(j)] == 1);
  int threes = 0;
  for (int j = 0; j < tn; ++j) threes += full.map.count[static_cast<std::size_t>(8 * tn + j)] == 3;
  CHECK(threes > 0);
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunOverAnInjectedTransportEqualsTheOnePassMap", "[map][run][transport]") {
  // Three ranks as threads: rank 0 hands the chunks out, stores and merges them; the resumed
  // part of a map stopped by a one-process run is not computed again.
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 17};
  const int tn = 40;
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("transport");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  run.chunk_limit = 6;
  REQUIRE_FALSE(run_param_direction_map(fig5(), state_b(), axis, tn, options, run).stats.complete);
  run.chunk_limit = -1;
  run.resume = true;
  const int ranks = 3;
  Mailboxes boxes(ranks);
  std::vector<ThreadTransport> t;
  for (int r = 0; r < ranks; ++r) t.emplace_back(r, ranks, boxes);
  std::vector<std::thread> others;
  std::vector<int> other_complete(ranks, 0);
  for (int r = 1; r < ranks; ++r)
    others.emplace_back([&, r] {
      GridRunOptions mine = run;
      mine.transport = &t[static_cast<std::size_t>(r)];
      const ParamDirectionRun res = run_param_direction_map(fig5(), state_b(), axis, tn, options, mine);
      other_complete[static_cast<std::size_t>(r)] = res.stats.complete && res.map.count.empty();
    });
  GridRunOptions rank0 = run;
  rank0.transport = &t[0];
  const ParamDirectionRun full = run_param_direction_map(fig5(), state_b(), axis, tn, options, rank0);
  for (auto& th : others) th.join();
  REQUIRE(full.stats.complete);
  CHECK(full.stats.ranks == ranks);
  CHECK(full.stats.resumed_chunks == 6);
  int64_t computed = 0;
  for (const int64_t c : full.stats.rank_cells) computed += c;
  CHECK(computed == (17 - 6) * tn);  // every missing chunk once, on whichever rank
  CHECK(other_complete[1] == 1);
  CHECK(other_complete[2] == 1);
  const ParamDirectionMap one = compute_param_direction_map(fig5(), state_b(), axis, tn, options);
  CHECK(full.map.count == one.count);
  CHECK(full.map.types == one.types);
  CHECK(full.map.type_cells == one.type_cells);
  CHECK(full.map.critical_directions.size() == one.critical_directions.size());
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunStoppedByItsStopQuestionKeepsTheRowsDoneAndResumes", "[map][run][time]") {
  // GridRunOptions::stop is `cpkit map`'s time limit (issue 37): asked before every chunk, it
  // ends the run where it says so (here: after 4 chunks, deterministically, where the program
  // asks the clock). The rows done are the one-pass map's first rows; the rest resumes.
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 13};  // 13 chunks of one row
  const int tn = 48;
  MapOptions options;
  options.threads = 1;
  const fs::path dir = scratch("stop");
  GridRunOptions run;
  run.checkpoint_prefix = (dir / "map").string();
  int asked = 0;
  run.stop = [&asked] { return ++asked > 4; };
  const ParamDirectionRun cut = run_param_direction_map(fig5(), state_b(), axis, tn, options, run);
  CHECK_FALSE(cut.stats.complete);
  CHECK(cut.stats.stopped);
  CHECK(asked == 5);  // asked once more, and stopped there
  CHECK(cut.stats.rows_done == 4);
  CHECK(chunk_files(dir / "map.parts") == 4);
  const ParamDirectionMap one = compute_param_direction_map(fig5(), state_b(), axis, tn, options);
  REQUIRE(cut.map.count.size() == 4u * tn);
  CHECK(std::equal(cut.map.count.begin(), cut.map.count.end(), one.count.begin()));
  int64_t cells = 0;
  for (const int64_t c : cut.map.type_cells) cells += c;
  CHECK(cells == 4 * tn);  // the summary counts the rows done only
  run.stop = {};
  run.resume = true;
  const ParamDirectionRun full = run_param_direction_map(fig5(), state_b(), axis, tn, options, run);
  REQUIRE(full.stats.complete);
  CHECK_FALSE(full.stats.stopped);
  CHECK(full.stats.rows_done == 13);
  CHECK(full.stats.resumed_chunks == 4);
  CHECK(full.map.count == one.count);
  fs::remove_all(dir.parent_path());
}

TEST_CASE("MapRunOverATransportStopsHandingOutChunksWhenAskedTo", "[map][run][transport][time]") {
  // The distributed path: rank 0 hands out no chunk once stop() says so; the workers are told
  // to stop, the chunks consumed in order are the one-pass map's first rows.
  const MapAxis axis{map_parameter("mu"), 0.5, 3.5, 17};
  const int tn = 40;
  MapOptions options;
  options.threads = 1;
  const int ranks = 3;
  Mailboxes boxes(ranks);
  std::vector<ThreadTransport> t;
  for (int r = 0; r < ranks; ++r) t.emplace_back(r, ranks, boxes);
  std::vector<std::thread> others;
  for (int r = 1; r < ranks; ++r)
    others.emplace_back([&, r] {
      GridRunOptions mine;
      mine.transport = &t[static_cast<std::size_t>(r)];
      (void)run_param_direction_map(fig5(), state_b(), axis, tn, options, mine);
    });
  GridRunOptions rank0;
  rank0.transport = &t[0];
  std::mutex m;
  int asked = 0;
  rank0.stop = [&] {
    std::lock_guard<std::mutex> lock(m);
    return ++asked > 6;
  };
  const ParamDirectionRun cut = run_param_direction_map(fig5(), state_b(), axis, tn, options, rank0);
  for (auto& th : others) th.join();
  CHECK(cut.stats.stopped);
  CHECK_FALSE(cut.stats.complete);
  int64_t computed = 0;
  for (const int64_t c : cut.stats.rank_cells) computed += c;
  CHECK(computed == 6 * tn);  // six chunks were handed out, none after
  CHECK(cut.stats.rows_done == 6);  // chunks 0..5, each finished and consumed
  const ParamDirectionMap one = compute_param_direction_map(fig5(), state_b(), axis, tn, options);
  REQUIRE(cut.map.count.size() == static_cast<std::size_t>(cut.stats.rows_done) * tn);
  CHECK(std::equal(cut.map.count.begin(), cut.map.count.end(), one.count.begin()));
}
