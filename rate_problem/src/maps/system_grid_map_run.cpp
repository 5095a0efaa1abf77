// N-point grid maps run in chunks (system_grid_map_run.hpp): a chunk is a row range with its
// own pattern table; rank 0 renumbers the patterns over the whole map and merges the rest.
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {

/// A chunk's summary: class boxes, its pattern table (chunk-local ids), counters.
nlohmann::json chunk_summary(const std::vector<GridClassBox>& classes,
                             const SystemPatternTable& table, int64_t unreliable,
                             int64_t inconsistent, int m_max) {
  return {{"boxes", boxes_to_json(classes)}, {"patterns", table.patterns},
          {"unreliable", unreliable}, {"inconsistent", inconsistent}, {"m_max", m_max}};
}

/// Rank 0's merge of the chunks in row order: patterns renumbered in order of first
/// appearance over the whole map (as one process numbers them), boxes and counters combined.
struct PatternMerge {
  SystemPatternTable table;
  std::map<std::vector<TypeTuple>, int> index;
  std::map<int, GridClassBox> boxes;  // by code
  int64_t unreliable = 0, inconsistent = 0;
  int m_max = 0;

  /// Renumbers a chunk's pattern ids in `ids` and merges its summary.
  void add(const nlohmann::json& summary, std::vector<uint16_t>& ids) {
    std::vector<uint16_t> to_global;
    for (const auto& p : summary.at("patterns")) {
      const auto tuples = p.get<std::vector<TypeTuple>>();
      auto [it, added] = index.emplace(tuples, static_cast<int>(table.patterns.size()));
      if (added) {
        if (table.patterns.size() >= 65535)
          throw InputError("the map has more than 65535 distinct point-type patterns");
        table.patterns.push_back(tuples);
        table.cells.push_back(0);
      }
      to_global.push_back(static_cast<uint16_t>(it->second));
    }
    for (auto& id : ids) {
      if (id >= to_global.size()) throw InputError("corrupt map chunk (pattern id)");
      id = to_global[id];
      ++table.cells[id];
    }
    merge_boxes(boxes, summary.at("boxes"));
    unreliable += summary.at("unreliable").get<int64_t>();
    inconsistent += summary.at("inconsistent").get<int64_t>();
    m_max = std::max(m_max, summary.at("m_max").get<int>());
  }
  std::vector<GridClassBox> classes() const {
    std::vector<GridClassBox> v;
    for (const auto& [code, b] : boxes) v.push_back(b);
    return v;
  }
};

std::vector<uint16_t> ids_of(const std::string& bytes) {
  std::vector<uint16_t> ids(bytes.size() / 2);
  std::memcpy(ids.data(), bytes.data(), ids.size() * 2);
  return ids;
}


template <class T>
void append_cells(std::vector<T>& v, const T* p, std::size_t n) {
  v.insert(v.end(), p, p + n);
}

/// The rows of a chunk (their arrays set by the caller).
template <class Rows>
Rows rows_of(const MapChunk& c) {
  Rows r;
  r.row_begin = c.row_begin;
  r.row_end = c.row_end;
  return r;
}

/// A map's cells kept in the map (no sink): `n` cells of every array.
void store_rows(SystemParamDirectionMap& m, const SystemParamDirectionRows& r, std::size_t n) {
  append_cells(m.count, r.count, n);
  append_cells(m.pattern, r.pattern, n);
}
void store_rows(SystemParamParamMap& m, const SystemParamParamRows& r, std::size_t n) {
  append_cells(m.cls, r.cls, n);
  append_cells(m.min_count, r.min_count, n);
  append_cells(m.max_count, r.max_count, n);
  append_cells(m.pattern, r.pattern, n);
}

}  // namespace

SystemParamDirectionRun run_system_param_direction_map(const ContactSystem& sys,
                                                       const SystemMapAxis& axis, int theta_n,
                                                       const MapOptions& options,
                                                       const GridRunOptions& run,
                                                       const SystemParamDirectionSink& sink) {
  const auto t0 = std::chrono::steady_clock::now();
  const ChunkPlan plan = plan_chunks(axis.n, theta_n);
  auto compute = [&](int k) {
    MapChunk c = chunk_of(plan, k);
    std::string count, pattern;
    const SystemParamDirectionMap m = compute_system_param_direction_map(
        sys, axis, theta_n, options, {},
        [&](const SystemParamDirectionRows& rows) {
          append_raw_cells(block_cells(rows, theta_n),
                           {{&count, rows.count}, {&pattern, rows.pattern, 2}});
        },
        RowRange{c.row_begin, c.row_end});
    c.summary = chunk_summary(m.classes, m.table, m.unreliable, 0, m.m_max);
    c.arrays = {std::move(count), std::move(pattern)};
    return c;
  };
  SystemParamDirectionRun out;
  SystemParamDirectionMap& m = out.map;
  PatternMerge merge;
  auto consume = [&](const MapChunk& c) {
    const std::string& count = c.arrays.at(0);
    std::vector<uint16_t> ids = ids_of(c.arrays.at(1));
    if (count.size() != ids.size() ||
        count.size() != static_cast<std::size_t>(c.row_end - c.row_begin) * theta_n)
      throw InputError("corrupt map chunk " + std::to_string(c.index) + " (sizes)");
    merge.add(c.summary, ids);
    auto rows = rows_of<SystemParamDirectionRows>(c);
    rows.count = reinterpret_cast<const int8_t*>(count.data());
    rows.pattern = ids.data();
    sink ? sink(rows) : store_rows(m, rows, ids.size());
  };
  const nlohmann::json manifest = {
      {"axis", axis_json(axis)},
      {"theta", {{"n", theta_n}, {"from", options.theta_from}, {"to", options.theta_to}}}};
  out.stats = run_grid_chunks(run, manifest, plan, compute, consume);
  m.axis = axis;
  m.theta_n = theta_n;
  m.theta_from = options.theta_from;
  m.theta_to = options.theta_to;
  m.theta = map_theta_values(theta_n, options.theta_from, options.theta_to);
  m.table = std::move(merge.table);
  m.classes = merge.classes();
  m.unreliable = merge.unreliable;
  m.m_max = merge.m_max;
  m.threads = map_worker_threads(options.threads, axis.n);
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

SystemParamParamRun run_system_param_param_map(const ContactSystem& sys,
                                               const SystemMapAxis& a1, const SystemMapAxis& a2,
                                               const MapOptions& options,
                                               const GridRunOptions& run,
                                               const SystemParamParamSink& sink) {
  const auto t0 = std::chrono::steady_clock::now();
  const ChunkPlan plan = plan_chunks(a1.n, a2.n);
  auto compute = [&](int k) {
    MapChunk c = chunk_of(plan, k);
    std::string cls, lo, hi, pattern;
    const SystemParamParamMap m = compute_system_param_param_map(
        sys, a1, a2, options, {},
        [&](const SystemParamParamRows& rows) {
          append_raw_cells(block_cells(rows, a2.n), {{&cls, rows.cls},
                                                     {&lo, rows.min_count},
                                                     {&hi, rows.max_count},
                                                     {&pattern, rows.pattern, 2}});
        },
        RowRange{c.row_begin, c.row_end});
    c.summary = chunk_summary(m.classes, m.table, m.unreliable, m.inconsistent_sectors, m.m_max);
    c.arrays = {std::move(cls), std::move(lo), std::move(hi), std::move(pattern)};
    return c;
  };
  SystemParamParamRun out;
  SystemParamParamMap& m = out.map;
  PatternMerge merge;
  auto consume = [&](const MapChunk& c) {
    const std::string &cls = c.arrays.at(0), &lo = c.arrays.at(1), &hi = c.arrays.at(2);
    std::vector<uint16_t> ids = ids_of(c.arrays.at(3));
    const std::size_t n = static_cast<std::size_t>(c.row_end - c.row_begin) * a2.n;
    if (cls.size() != n || lo.size() != n || hi.size() != n || ids.size() != n)
      throw InputError("corrupt map chunk " + std::to_string(c.index) + " (sizes)");
    merge.add(c.summary, ids);
    auto rows = rows_of<SystemParamParamRows>(c);
    rows.cls = reinterpret_cast<const uint8_t*>(cls.data());
    rows.min_count = reinterpret_cast<const int8_t*>(lo.data());
    rows.max_count = reinterpret_cast<const int8_t*>(hi.data());
    rows.pattern = ids.data();
    sink ? sink(rows) : store_rows(m, rows, n);
  };
  const nlohmann::json manifest = {{"axis", axis_json(a1)}, {"axis2", axis_json(a2)}};
  out.stats = run_grid_chunks(run, manifest, plan, compute, consume);
  m.axis1 = a1;
  m.axis2 = a2;
  m.table = std::move(merge.table);
  m.classes = merge.classes();
  m.unreliable = merge.unreliable;
  m.inconsistent_sectors = merge.inconsistent;
  m.m_max = merge.m_max;
  m.threads = map_worker_threads(options.threads, a1.n);
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::string system_data_fingerprint(const ContactSystem& sys) {
  uint64_t h = 1469598103934665603ull;
  auto bytes = [&](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  };
  auto real = [&](double x) { bytes(&x, sizeof x); };
  auto vec = [&](const std::optional<Eigen::VectorXd>& v) {
    const int64_t n = v ? v->size() : -1;
    bytes(&n, sizeof n);
    if (v) bytes(v->data(), sizeof(double) * static_cast<std::size_t>(v->size()));
  };
  const int64_t rows = sys.A.rows(), cols = sys.A.cols();
  bytes(&rows, sizeof rows);
  bytes(&cols, sizeof cols);
  bytes(sys.A.data(), sizeof(double) * static_cast<std::size_t>(sys.A.size()));
  for (const SystemPoint& p : sys.points) {
    for (double x : {p.mu, p.C_T, p.k_a, p.P_s, p.state.P_N, p.P_T, p.P_N, p.g}) real(x);
    const int ints[] = {static_cast<int>(p.state.label), p.state.sgn_PT, p.values_given ? 1 : 0};
    bytes(ints, sizeof ints);
  }
  const int crit = static_cast<int>(sys.criterion);
  bytes(&crit, sizeof crit);
  vec(sys.dF);
  vec(sys.pattern1);
  vec(sys.pattern2);
  std::ostringstream o;
  o << std::hex << h;
  return o.str();
}

}  // namespace cpkit::rate
