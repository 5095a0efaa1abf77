// Streamed grid maps: the blocks a sink receives are the in-memory map, in row order; the
// summary (counts per class, types) agrees with a recount of the cells; progress covers every
// phase; the .npy header follows the NumPy format specification.
#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/npy_writer.hpp"

using namespace cpkit::rate;

TEST_CASE("StreamedParamDirectionBlocksEqualTheInMemoryMap", "[map][grid][stream]") {
  const MapPreset p = *find_map_preset("fig5b");
  // 2^20 / 50000 = 20 rows per block: 47 rows give three blocks, the last one partial.
  const int theta_n = 50000;
  REQUIRE(grid_block_rows(theta_n) == 20);
  const MapAxis axis{map_parameter("mu"), 0.1, 4.0, 47};
  MapOptions o;
  o.threads = 2;
  const ParamDirectionMap ref = compute_param_direction_map(p.params, p.state, axis, theta_n, o);
  std::vector<int8_t> count;
  std::vector<uint8_t> types;
  std::vector<int> begins;
  const ParamDirectionMap m = compute_param_direction_map(
      p.params, p.state, axis, theta_n, o, {}, [&](const ParamDirectionRows& r) {
        begins.push_back(r.row_begin);
        CHECK(r.row_begin == static_cast<int>(count.size() / theta_n));
        const std::size_t cells = static_cast<std::size_t>(r.row_end - r.row_begin) * theta_n;
        count.insert(count.end(), r.count, r.count + cells);
        types.insert(types.end(), r.types, r.types + cells);
        CHECK(r.disagree == nullptr);
      });
  CHECK(begins == std::vector<int>{0, 20, 40});
  CHECK(m.count.empty());  // streamed: not kept
  CHECK(count == ref.count);
  CHECK(types == ref.types);
  CHECK(m.cells() == ref.cells());
  CHECK(m.critical_directions.size() == ref.critical_directions.size());

  // The summary equals a recount of the cells.
  std::map<int, int64_t> recount;
  std::array<int64_t, 32> type_recount{};
  for (std::size_t k = 0; k < count.size(); ++k) {
    ++recount[count[k]];
    ++type_recount[types[k] & 31u];
  }
  REQUIRE(m.classes.size() == recount.size());
  for (const auto& b : m.classes) {
    CAPTURE(b.code);
    CHECK(b.cells == recount[b.code]);
  }
  CHECK(m.type_cells == type_recount);
  // The fig5b model has 3 solutions only above mu = a11 / a12 = 2 (D+ < 0).
  for (const auto& b : m.classes)
    if (b.code == 3) CHECK(b.x_min > 2.0);
}

TEST_CASE("StreamedParamParamMapAndThreadedCriticalCurves", "[map][grid][stream]") {
  const MapPreset p = *find_map_preset("state-d-mu-kappa");
  const MapAxis a1{map_parameter("mu"), 0.1, 2.0, 13}, a2{map_parameter("kappa"), 0.0, 2.0, 11};
  MapOptions o1, o3;
  o1.threads = 1;
  o3.threads = 3;
  const ParamParamMap ref = compute_param_param_map(p.params, p.state, a1, a2, o1);
  std::vector<uint8_t> cls;
  std::vector<std::pair<std::string, double>> phases;
  const ParamParamMap m = compute_param_param_map(
      p.params, p.state, a1, a2, o3,
      [&](std::string_view phase, double f) { phases.emplace_back(std::string(phase), f); },
      [&](const ParamParamRows& r) {
        cls.insert(cls.end(), r.cls, r.cls + static_cast<std::size_t>(r.row_end - r.row_begin) * a2.n);
      });
  CHECK(cls == ref.cls);
  REQUIRE(m.critical_curve.size() == ref.critical_curve.size());
  REQUIRE(!m.critical_curve.empty());
  for (std::size_t k = 0; k < m.critical_curve.size(); ++k) {
    CHECK(m.critical_curve[k].x == ref.critical_curve[k].x);
    CHECK(m.critical_curve[k].y == ref.critical_curve[k].y);
  }
  // Both phases end at 1, cells first.
  REQUIRE(!phases.empty());
  CHECK(phases.back() == std::make_pair(std::string("critical curves"), 1.0));
  bool cells_done = false;
  for (const auto& [ph, f] : phases)
    if (ph == "cells" && f == 1.0) cells_done = true;
  CHECK(cells_done);
  CHECK(phases.front().first == "cells");
}

TEST_CASE("NpyHeaderFollowsTheFormatSpecification", "[map][npy]") {
  // numpy.lib.format, version 1.0: magic, 1, 0, uint16 LE length, dict, spaces, '\n'; the data
  // starts at a multiple of 64. The dict text is what numpy itself writes for these arrays.
  const std::string h = npy_header("|i1", {2, 3});
  REQUIRE(h.size() % 64 == 0);
  CHECK(h.substr(0, 6) == "\x93NUMPY");
  CHECK(h[6] == 1);
  CHECK(h[7] == 0);
  CHECK(static_cast<unsigned char>(h[8]) + 256u * static_cast<unsigned char>(h[9]) ==
        h.size() - 10);
  CHECK(h.find("{'descr': '|i1', 'fortran_order': False, 'shape': (2, 3), }") == 10);
  CHECK(h.back() == '\n');
  const std::string v = npy_header("<f8", {5});
  CHECK(v.size() % 64 == 0);
  CHECK(v.find("'shape': (5,), }") != std::string::npos);
  const std::string big = npy_header("|u1", {100000, 1000000});
  CHECK(big.size() % 64 == 0);
  CHECK(big.find("(100000, 1000000)") != std::string::npos);
}
