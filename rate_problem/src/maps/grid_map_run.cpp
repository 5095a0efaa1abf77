// One-point grid maps run in chunks (grid_map_run.hpp): each chunk is a row range of the map
// (cells as raw arrays, its summary as JSON), merged on rank 0 in row order.
#include "cpkit/rate_problem/maps/grid_map_run.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>
#include <utility>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The arrays of chunk c, each of `cells` bytes and `expected` of them; InputError otherwise
/// (a chunk file edited by hand, a message cut short).
void check_arrays(const MapChunk& c, std::size_t expected, std::size_t cells) {
  if (c.arrays.size() != expected) throw InputError("corrupt map chunk " + std::to_string(c.index));
  for (const auto& arr : c.arrays)
    if (arr.size() != cells) throw InputError("corrupt map chunk " + std::to_string(c.index));
}

template <class T>
void append_bytes(std::vector<T>& v, const std::string& bytes) {
  const auto* p = reinterpret_cast<const T*>(bytes.data());
  v.insert(v.end(), p, p + bytes.size() / sizeof(T));
}



}  // namespace

ChunkRunStats run_grid_chunks(const GridRunOptions& run, nlohmann::json manifest,
                              const ChunkPlan& plan, const std::function<MapChunk(int)>& compute,
                              const std::function<void(const MapChunk&)>& consume) {
  if (!run.describe_grid) manifest = nlohmann::json::object();
  for (const auto& [k, v] : run.manifest.items()) manifest[k] = v;
  return run_map_chunks(run.checkpoint_prefix, run.resume, manifest, plan, compute, consume,
                        run.progress, run.transport, run.chunk_limit, run.stop);
}

int map_worker_threads(int requested, int rows) {
  const int t = requested > 0 ? requested
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(t, rows));
}

ParamDirectionRun run_param_direction_map(const ContactParameters& params,
                                          const ContactState& state, const MapAxis& axis,
                                          int theta_n, const MapOptions& options,
                                          const GridRunOptions& run,
                                          const ParamDirectionSink& sink) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool cross = options.method != RateMethod::kEnumerate;
  const ChunkPlan plan = plan_chunks(axis.n, theta_n);
  auto compute = [&](int k) {
    MapChunk c = chunk_of(plan, k);
    std::string cnt, typ, dis;
    const ParamDirectionMap part = compute_param_direction_map(
        params, state, axis, theta_n, options, {},
        [&](const ParamDirectionRows& r) {
          append_raw_cells(block_cells(r, theta_n),
                           {{&cnt, r.count}, {&typ, r.types}, {&dis, r.disagree}});
        },
        RowRange{c.row_begin, c.row_end});
    nlohmann::json crit = nlohmann::json::array(), values = nlohmann::json::array();
    for (const auto& d : part.critical_directions)
      crit.push_back({d.x, d.theta, d.conditions, d.summary.count, d.summary.types,
                      d.summary.reliable});
    for (const auto& v : part.critical_values) values.push_back({v.name, v.x, v.y});
    c.summary = {{"boxes", boxes_to_json(part.classes)}, {"type_cells", part.type_cells},
                 {"disagreements", part.disagreements}, {"unreliable", part.unreliable},
                 {"critical_directions", crit}, {"critical_values", values}};
    c.arrays = {std::move(cnt), std::move(typ)};
    if (cross) c.arrays.push_back(std::move(dis));
    return c;
  };
  ParamDirectionRun out;
  ParamDirectionMap& m = out.map;
  m.axis = axis;
  m.theta_n = theta_n;
  m.theta_from = options.theta_from;
  m.theta_to = options.theta_to;
  m.theta = map_theta_values(theta_n, options.theta_from, options.theta_to);
  m.cross_checked = cross;
  m.threads = map_worker_threads(options.threads, axis.n);
  std::map<int, GridClassBox> boxes;
  auto consume = [&](const MapChunk& c) {
    const std::size_t cells = static_cast<std::size_t>(c.row_end - c.row_begin) *
                              static_cast<std::size_t>(theta_n);
    check_arrays(c, cross ? 3u : 2u, cells);
    ParamDirectionRows r;
    r.row_begin = c.row_begin;
    r.row_end = c.row_end;
    r.count = reinterpret_cast<const int8_t*>(c.arrays[0].data());
    r.types = reinterpret_cast<const uint8_t*>(c.arrays[1].data());
    r.disagree = cross ? reinterpret_cast<const uint8_t*>(c.arrays[2].data()) : nullptr;
    if (sink) {
      sink(r);
    } else {
      append_bytes(m.count, c.arrays[0]);
      append_bytes(m.types, c.arrays[1]);
      if (cross) append_bytes(m.disagree, c.arrays[2]);
    }
    const nlohmann::json& sum = c.summary;
    merge_boxes(boxes, sum.at("boxes"));
    for (std::size_t b = 0; b < m.type_cells.size(); ++b)
      m.type_cells[b] += sum.at("type_cells").at(b).get<int64_t>();
    m.disagreements += sum.at("disagreements").get<int64_t>();
    m.unreliable += sum.at("unreliable").get<int64_t>();
    for (const auto& d : sum.at("critical_directions")) {
      RateSummary rs;
      rs.count = d.at(3).get<int>();
      rs.types = d.at(4).get<unsigned>();
      rs.reliable = d.at(5).get<bool>();
      m.critical_directions.push_back(
          {d.at(0).get<double>(), d.at(1).get<double>(), d.at(2).get<std::string>(), rs});
    }
    if (c.index == 0)  // the analytic curves are the whole axis's: every chunk has them
      for (const auto& v : sum.at("critical_values"))
        m.critical_values.push_back(
            {v.at(0).get<std::string>(), v.at(1).get<double>(), v.at(2).get<double>()});
  };
  nlohmann::json manifest = {
      {"axis", axis_json(axis)},
      {"theta", {{"n", theta_n}, {"from", options.theta_from}, {"to", options.theta_to}}}};
  out.stats = run_grid_chunks(run, manifest, plan, compute, consume);
  for (const auto& [code, b] : boxes) m.classes.push_back(b);
  m.seconds = seconds_since(t0);
  return out;
}

ParamParamRun run_param_param_map(const ContactParameters& params, const ContactState& state,
                                  const MapAxis& axis1, const MapAxis& axis2,
                                  const MapOptions& options, const GridRunOptions& run,
                                  const ParamParamSink& sink) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool cross = options.method != RateMethod::kEnumerate;
  const ChunkPlan plan = plan_chunks(axis1.n, axis2.n);
  auto compute = [&](int k) {
    MapChunk c = chunk_of(plan, k);
    std::string cls, lo, hi, typ, dis;
    const ParamParamMap part = compute_param_param_map(
        params, state, axis1, axis2, options, {},
        [&](const ParamParamRows& r) {
          append_raw_cells(block_cells(r, axis2.n), {{&cls, r.cls},
                                                     {&lo, r.min_count},
                                                     {&hi, r.max_count},
                                                     {&typ, r.types},
                                                     {&dis, r.disagree}});
        },
        RowRange{c.row_begin, c.row_end});
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& v : part.critical_curve) curve.push_back({v.name, v.x, v.y});
    c.summary = {{"boxes", boxes_to_json(part.classes)},
                 {"disagreements", part.disagreements},
                 {"inconsistent_sectors", part.inconsistent_sectors},
                 {"unreliable", part.unreliable}, {"critical_curve", curve}};
    c.arrays = {std::move(cls), std::move(lo), std::move(hi), std::move(typ)};
    if (cross) c.arrays.push_back(std::move(dis));
    return c;
  };
  ParamParamRun out;
  ParamParamMap& m = out.map;
  m.axis1 = axis1;
  m.axis2 = axis2;
  m.cross_checked = cross;
  m.threads = map_worker_threads(options.threads, axis1.n);
  std::map<int, GridClassBox> boxes;
  auto consume = [&](const MapChunk& c) {
    const std::size_t cells = static_cast<std::size_t>(c.row_end - c.row_begin) *
                              static_cast<std::size_t>(axis2.n);
    check_arrays(c, cross ? 5u : 4u, cells);
    ParamParamRows r;
    r.row_begin = c.row_begin;
    r.row_end = c.row_end;
    r.cls = reinterpret_cast<const uint8_t*>(c.arrays[0].data());
    r.min_count = reinterpret_cast<const int8_t*>(c.arrays[1].data());
    r.max_count = reinterpret_cast<const int8_t*>(c.arrays[2].data());
    r.types = reinterpret_cast<const uint8_t*>(c.arrays[3].data());
    r.disagree = cross ? reinterpret_cast<const uint8_t*>(c.arrays[4].data()) : nullptr;
    if (sink) {
      sink(r);
    } else {
      append_bytes(m.cls, c.arrays[0]);
      append_bytes(m.min_count, c.arrays[1]);
      append_bytes(m.max_count, c.arrays[2]);
      append_bytes(m.types, c.arrays[3]);
      if (cross) append_bytes(m.disagree, c.arrays[4]);
    }
    const nlohmann::json& sum = c.summary;
    merge_boxes(boxes, sum.at("boxes"));
    m.disagreements += sum.at("disagreements").get<int64_t>();
    m.inconsistent_sectors += sum.at("inconsistent_sectors").get<int64_t>();
    m.unreliable += sum.at("unreliable").get<int64_t>();
    for (const auto& v : sum.at("critical_curve"))
      m.critical_curve.push_back(
          {v.at(0).get<std::string>(), v.at(1).get<double>(), v.at(2).get<double>()});
  };
  const nlohmann::json manifest = {{"axis", axis_json(axis1)}, {"axis2", axis_json(axis2)}};
  out.stats = run_grid_chunks(run, manifest, plan, compute, consume);
  for (const auto& [code, b] : boxes) m.classes.push_back(b);
  m.seconds = seconds_since(t0);
  return out;
}

}  // namespace cpkit::rate
