// `cpkit map --system FILE` with a "dim": 3 system (docs/contact_3d.md, "Maps over the sphere of
// load directions"): --kind sphere (the load direction of one point over the sphere, two angles),
// param-direction (a parameter x directions in a meridian plane) and param-param (two
// parameters at the file's dF). Every cell: the number of solutions, the mask of solution types
// of the loaded point, and whether the solution set is proved complete. Files: PREFIX_count.npy
// (|i1), PREFIX_types.npy (|u1), PREFIX_complete.npy (|u1), PREFIX_x.npy, PREFIX_y.npy (axis
// values), PREFIX.json; --plot draws PREFIX.png/.svg (scripts/cpkit_plot.py).
// Exit codes: 0 map computed, every cell proved complete; 2 bad input; 4 a requested picture
// not drawn; 5 some cells not proved complete (counted in the JSON, flagged in the files).
#include "map_system_3d.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.hpp"
#include "machine_resources.hpp"
#include "map_files.hpp"
#include "memory_limit.hpp"
#include "mpi_session.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::cli {

bool Map3dRequest::has(const std::string& o) const {
  return std::find(given.begin(), given.end(), o) != given.end();
}

namespace {

namespace fs = std::filesystem;
using namespace cpkit::rate3d;

constexpr double kPi = 3.141592653589793;

std::string fmt(double x, int digits = 4) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

std::string count_text(int count) {
  if (count < 0) return "infinitely many solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}

/// Options that apply to a kind; every other option given is refused (no silent defaults).
std::vector<std::string> allowed_options(const std::string& kind) {
  std::vector<std::string> a = {"--system", "--kind",   "--out",   "--threads",
                                "--time-limit", "--max-output", "--facets", "--point", "--format"};
  const std::vector<std::string> extra =
      kind == "sphere"
          ? std::vector<std::string>{"--n", "--n2", "--from", "--to", "--others"}
      : kind == "param-direction"
          ? std::vector<std::string>{"--param", "--from", "--to", "--n", "--theta-n",
                                     "--theta-from", "--theta-to", "--gamma", "--others"}
          : std::vector<std::string>{"--param", "--from", "--to", "--n", "--param2", "--from2",
                                     "--to2", "--n2"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

void check_request(const Map3dRequest& r) {
  if (r.kind.empty())
    throw InputError("maps of a dim 3 system need --kind sphere, param-direction or param-param "
                     "(the 2-D direction map has no 3-D counterpart: --kind sphere maps the "
                     "sphere of load directions)");
  if (r.kind != "sphere" && r.kind != "param-direction" && r.kind != "param-param")
    throw InputError("--kind with a dim 3 system must be sphere, param-direction or param-param, "
                     "got '" + r.kind + "'");
  const std::vector<std::string> allowed = allowed_options(r.kind);
  std::string list;
  for (const auto& o : allowed) list += (list.empty() ? "" : ", ") + o;
  for (const auto& o : r.given)
    if (std::find(allowed.begin(), allowed.end(), o) == allowed.end())
      throw InputError(o + " has no effect with a dim 3 system and --kind " + r.kind +
                       " (the model comes from the system file; options: " + list +
                       ", --json, --plot)");
  std::vector<std::string> needed;
  if (r.kind == "param-direction") needed = {"--param", "--from", "--to"};
  if (r.kind == "param-param") needed = {"--param", "--from", "--to", "--param2", "--from2", "--to2"};
  for (const auto& o : needed)
    if (!r.has(o)) throw InputError("--kind " + r.kind + " with a dim 3 system needs " + o);
  if (r.kind == "sphere" && (r.has("--from") != r.has("--to")))
    throw InputError("--from and --to (the range of b, rad) go together");
  const std::pair<const char*, double> reals[] = {
      {"--from", r.from},   {"--to", r.to},         {"--from2", r.from2},
      {"--to2", r.to2},     {"--theta-from", r.theta_from}, {"--theta-to", r.theta_to},
      {"--gamma", r.gamma}, {"--time-limit", r.time_limit}};
  for (const auto& [name, v] : reals)
    if (r.has(name) && !std::isfinite(v)) throw InputError(std::string(name) + " must be finite");
  if (!(r.time_limit > 0)) throw InputError("--time-limit must be a positive number of seconds");
  if (r.has("--format") && r.format != "npy")
    throw InputError("--format: 3-D maps are written as .npy arrays only, got '" + r.format + "'");
  if (r.has("--format") && r.out.empty()) throw InputError("--format needs --out PREFIX");
  if (r.plot && r.out.empty()) throw InputError("--plot needs --out PREFIX");
  if (r.threads < 0 || r.threads > 1024)
    throw InputError("--threads must be in [0, 1024] (0: all cores), got " + std::to_string(r.threads));
  if (r.has("--others") && r.others != "zero" && r.others != "file")
    throw InputError("--others must be zero or file, got '" + r.others + "'");
  if (mpi::size() > 1)
    throw InputError("3-D maps run on the threads of one process: run them without mpirun "
                     "(--threads)");
}

/// The map of the request (also used on a small sample grid for the time estimate).
struct Plan {
  ContactSystem3d sys;
  Map3dOptions options;
  SphereGrid grid;
  Map3dAxis a1, a2;
  int theta_n = 360;
  double theta_from = 0, theta_to = 2 * kPi, gamma = 0;
  int64_t cells() const {
    return static_cast<int64_t>(a1.n) * (a2.n > 0 ? a2.n : 1);
  }
};

Map3d compute(const std::string& kind, const Plan& p, const Map3dOptions& o,
              const Map3dProgress& progress = {}) {
  if (kind == "sphere") return compute_sphere_map_3d(p.sys, p.grid, o, progress);
  if (kind == "param-direction")
    return compute_param_direction_map_3d(p.sys, p.a1, p.theta_n, p.theta_from, p.theta_to,
                                          p.gamma, o, progress);
  return compute_param_param_map_3d(p.sys, p.a1, p.a2, o, progress);
}

/// Seconds of the whole map on `threads`, from a timed sample of at most 4 x 8 cells spread
/// over the same ranges (one thread; the faster of two runs). The sample runs within what is
/// left of the --time-limit budget (`clock` started with the command): a sample that does not
/// finish in it is refused (InputError): the map would need more. A map no larger than the
/// sample is not estimated (-1, sampled = 0): it is computed once, within the deadline.
double estimate_seconds(const std::string& kind, const Plan& p, int64_t cells, int threads,
                        int64_t& sampled, const Stopwatch& clock, double time_limit,
                        const std::string& cells_text, const std::string& fewer) {
  Plan s = p;
  Map3dOptions one = p.options;
  one.threads = 1;
  if (kind == "sphere") {
    s.grid.n_beta = std::min(p.grid.n_beta, 4);
    s.grid.n_gamma = std::min(p.grid.n_gamma, 8);
  } else if (kind == "param-direction") {
    s.a1.n = std::min(p.a1.n, 3);
    s.theta_n = std::min(p.theta_n, 8);
  } else {
    s.a1.n = std::min(p.a1.n, 3);
    s.a2.n = std::min(p.a2.n, 6);
  }
  const bool whole = kind == "sphere" ? s.grid.n_beta == p.grid.n_beta && s.grid.n_gamma == p.grid.n_gamma
                     : kind == "param-direction" ? s.a1.n == p.a1.n && s.theta_n == p.theta_n
                                                 : s.a1.n == p.a1.n && s.a2.n == p.a2.n;
  if (whole) {
    sampled = 0;  // the sample would be the map itself: computed once, within the deadline
    return -1;
  }
  double t = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    // The second run only when the first left most of the budget.
    if (rep == 1 && t > 0.25 * (time_limit - clock.seconds())) break;
    one.time_limit_s = time_limit - clock.seconds();
    const Stopwatch c;
    const Map3d m = one.time_limit_s > 0 ? compute(kind, s, one) : Map3d{};
    if (!(one.time_limit_s > 0) || m.timed_out_cells > 0)
      throw InputError("the map has " + cells_text + "; a timed sample of " +
                       std::to_string(std::max<int64_t>(1, m.cells())) +
                       " of them alone ran past --time-limit " + fmt(time_limit) +
                       " s (the time limit was reached): " + fewer +
                       (p.options.facets ? ", fewer --facets or fewer grazing points" : "") +
                       ", or raise --time-limit");
    t = std::min(t, c.seconds());
    sampled = m.cells();
  }
  return t / static_cast<double>(std::max<int64_t>(1, sampled)) * static_cast<double>(cells) /
         threads;
}

}  // namespace

int run_map_system_3d(const Map3dRequest& r) {
  check_request(r);
  std::unique_ptr<PrefixLock> lock;  // held until the map is written
  if (!r.out.empty()) lock = claim_map_prefix(r.out, {{"--system", r.path}});
  const Stopwatch clock;
  Plan p;
  p.sys = parse_contact_system_3d(r.file);
  const int N = p.sys.n_points();
  Map3dOptions& o = p.options;
  if (r.has("--facets")) {
    if (r.facets < 3 || r.facets > kMaxFacets)
      throw InputError("--facets must be in [3, " + std::to_string(kMaxFacets) + "], got " +
                       std::to_string(r.facets));
    o.facets = r.facets;
  }
  if (N > 1 && o.facets == 0)
    throw InputError("a system of " + std::to_string(N) +
                     " 3-D points needs --facets K (the faceted ellipses; the exact route is for "
                     "one point)");
  if (o.facets > 0) {
    // Limits that depend on N and the states, before any work (issue 24, item 12).
    int nb = 0, nd = 0;
    for (const auto& pt : p.sys.points) nb += pt.state.state == 'b', nd += pt.state.state == 'd';
    if (nb > kMaxGrazing3d)
      throw InputError(r.path + ": " + std::to_string(nb) + " grazing points (state b); the "
                       "faceted route takes at most " + std::to_string(kMaxGrazing3d) +
                       " (2^n_b separation cases per cell)");
    if (nd + o.facets * nb > lcp::kMaxEnumerationSize)
      throw InputError(r.path + ": the faceted LCP would have size n_d + K n_b = " +
                       std::to_string(nd + o.facets * nb) + " > " +
                       std::to_string(lcp::kMaxEnumerationSize) + ": use fewer --facets");
  }
  if (r.point < 1 || r.point > N)
    throw InputError("--point must be in [1, " + std::to_string(N) + "], got " +
                     std::to_string(r.point));
  o.point = r.point - 1;
  // The other points' load rates: the file's dF when it has one (a grazing point with a zero
  // load rate is a degenerate LCP: slow, and not proved complete), else 0; --others chooses.
  o.others_from_file = r.has("--others") ? r.others == "file" : (N > 1 && p.sys.dF.has_value());
  if (o.others_from_file && !p.sys.dF)
    throw InputError("--others file needs \"dF\" in the system file (the other points' load "
                     "rates)");
  if (o.others_from_file && N == 1)
    throw InputError("--others has no effect with one point");
  o.threads = r.threads;
  std::string cells_text, fewer;
  nlohmann::json input = {{"system", r.path}, {"name", p.sys.name}, {"n_points", N},
                          {"point", r.point},
                          {"route", o.facets ? "faceted" : "exact"},
                          {"facets", o.facets ? nlohmann::json(o.facets) : nlohmann::json()}};
  int64_t cells = 0;
  std::string xname, yname;
  if (r.kind == "sphere") {
    p.grid.n_beta = r.has("--n") ? r.n : 91;
    p.grid.n_gamma = r.has("--n2") ? r.n2 : 180;
    if (r.has("--from")) p.grid.beta_from = r.from;
    if (r.has("--to")) p.grid.beta_to = r.to;
    if (p.grid.n_beta < 1 || p.grid.n_beta > 1000000) throw InputError("--n must be in [1, 1000000]");
    if (p.grid.n_gamma < 1 || p.grid.n_gamma > 1000000)
      throw InputError("--n2 must be in [1, 1000000]");
    if (p.grid.beta_from < 0 || p.grid.beta_from > kPi || p.grid.beta_to < 0 || p.grid.beta_to > kPi)
      throw InputError("--from/--to (the range of b, rad) must lie in [0, pi]");
    if (!(p.grid.beta_from < p.grid.beta_to)) throw InputError("--from must be < --to");
    cells = static_cast<int64_t>(p.grid.n_beta) * p.grid.n_gamma;
    cells_text = std::to_string(p.grid.n_beta) + " x " + std::to_string(p.grid.n_gamma) +
                 " cells (--n x --n2)";
    fewer = "use a smaller --n or --n2";
    xname = "beta";
    yname = "gamma";
    input["n"] = p.grid.n_beta;
    input["n2"] = p.grid.n_gamma;
    input["beta_from"] = p.grid.beta_from;
    input["beta_to"] = p.grid.beta_to;
    input["others"] = o.others_from_file ? "file" : "zero";
  } else {
    p.a1.param = parse_map_3d_parameter(r.param, N);
    p.a1.from = r.from;
    p.a1.to = r.to;
    p.a1.n = r.has("--n") ? r.n : 100;
    if (p.a1.n < 1 || p.a1.n > 1000000) throw InputError("--n must be in [1, 1000000]");
    if (p.a1.n > 1 && !(r.from < r.to)) throw InputError("--from must be < --to");
    xname = p.a1.param.name();
    input["param"] = xname;
    input["from"] = r.from;
    input["to"] = r.to;
    input["n"] = p.a1.n;
    if (r.kind == "param-direction") {
      p.theta_n = r.has("--theta-n") ? r.theta_n : 360;
      if (p.theta_n < 1 || p.theta_n > 1000000)
        throw InputError("--theta-n must be in [1, 1000000]");
      if (r.has("--theta-from")) p.theta_from = r.theta_from;
      if (r.has("--theta-to")) p.theta_to = r.theta_to;
      if (!(p.theta_to > p.theta_from) || p.theta_to - p.theta_from > 2 * kPi + 1e-12)
        throw InputError("--theta-from/--theta-to: need 0 < theta_to - theta_from <= 2 pi");
      p.gamma = r.has("--gamma") ? r.gamma : 0.0;
      cells = static_cast<int64_t>(p.a1.n) * p.theta_n;
      cells_text = std::to_string(p.a1.n) + " x " + std::to_string(p.theta_n) +
                   " cells (--n x --theta-n)";
      fewer = "use a smaller --n or --theta-n";
      yname = "theta";
      input["theta_n"] = p.theta_n;
      input["theta_from"] = p.theta_from;
      input["theta_to"] = p.theta_to;
      input["gamma"] = p.gamma;
      input["others"] = o.others_from_file ? "file" : "zero";
    } else {
      p.a2.param = parse_map_3d_parameter(r.param2, N);
      p.a2.from = r.from2;
      p.a2.to = r.to2;
      p.a2.n = r.has("--n2") ? r.n2 : 100;
      if (p.a2.n < 1 || p.a2.n > 1000000) throw InputError("--n2 must be in [1, 1000000]");
      if (p.a2.n > 1 && !(r.from2 < r.to2)) throw InputError("--from2 must be < --to2");
      if (!p.sys.dF)
        throw InputError("--kind param-param with a dim 3 system is computed at the file's "
                         "load rate: the system file needs \"dF\"");
      cells = static_cast<int64_t>(p.a1.n) * p.a2.n;
      cells_text = std::to_string(p.a1.n) + " x " + std::to_string(p.a2.n) + " cells (--n x --n2)";
      fewer = "use a smaller --n or --n2";
      yname = p.a2.param.name();
      input["param2"] = yname;
      input["from2"] = r.from2;
      input["to2"] = r.to2;
      input["n2"] = p.a2.n;
      const Eigen::VectorXd& d = *p.sys.dF;
      input["dF"] = std::vector<double>(d.data(), d.data() + d.size());
    }
  }
  if (cells > kMaxMap3dCells)
    throw InputError("the map has " + cells_text + ", more than the " +
                     std::to_string(kMaxMap3dCells) + " cells a 3-D map holds: " + fewer);
  if (!r.out.empty()) {
    // 3 bytes a cell (count, types, complete) and the axis values, before any cell is computed.
    const double axes = r.kind == "sphere" ? p.grid.n_beta + p.grid.n_gamma
                        : r.kind == "param-direction" ? p.a1.n + p.theta_n
                                                      : p.a1.n + p.a2.n;
    const double output = 3.0 * static_cast<double>(cells) + 8.0 * axes + 5 * 4096;
    const std::string dir = fs::path(r.out).parent_path().string();
    if (output > r.max_output)
      throw InputError("the map has " + cells_text + " and its output would take about " +
                       byte_text(output) + " (estimated), more than --max-output " +
                       byte_text(r.max_output) + ": " + fewer + ", or raise --max-output");
    const double free = free_disk_bytes(dir);
    if (free >= 0 && output > 0.95 * free)
      throw InputError("the map has " + cells_text + " and its output would take about " +
                       byte_text(output) + " but only " + byte_text(free) + " is free in '" +
                       (dir.empty() ? "." : dir) + "': " + fewer);
  }
  // Up-front cost from a timed sample (which also reports invalid input before the long run).
  const int threads = std::max(1, std::min<int>(
      r.threads > 0 ? r.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
      r.kind == "sphere" ? p.grid.n_beta : p.a1.n));
  int64_t sampled = 0;
  const double seconds = estimate_seconds(r.kind, p, cells, threads, sampled, clock,
                                          r.time_limit, cells_text, fewer);
  if (seconds > r.time_limit)
    throw InputError("the map has " + cells_text + " and would need about " + fmt(seconds, 3) +
                     " s on " + std::to_string(threads) + " threads (estimated from " +
                     std::to_string(sampled) + " timed cells), more than --time-limit " +
                     fmt(r.time_limit) + ": " + fewer +
                     (o.facets ? ", fewer --facets" : "") + ", or raise --time-limit");
  if (seconds > 1.0)
    std::cerr << "cpkit map: " << cells_text << ": about " << fmt(seconds, 3) << " s on "
              << threads << " threads (estimate)\n";
  // One deadline for the whole command (issue 24, item 11): the estimate was within it; the
  // cells get what is left, and the ones it does not cover are flagged, never dropped.
  o.time_limit_s = std::max(1e-3, r.time_limit - clock.seconds());
  const Map3d m = compute(r.kind, p, o, [prog = make_map_progress()](double f) { prog("cells", f); });

  nlohmann::json j;
  j["cpkit_version"] = CPKIT_VERSION;
  j["kind"] = r.kind;
  j["dim"] = 3;
  j["input"] = input;
  j["axes"] = {{"x", xname}, {"y", yname}};
  j["cells"] = m.cells();
  nlohmann::json counts = nlohmann::json::array();
  for (const auto& [c, n] : m.count_cells)
    counts.push_back({{"count", c < 0 ? nlohmann::json("infinite") : nlohmann::json(c)}, {"cells", n}});
  j["counts"] = counts;
  nlohmann::json types = nlohmann::json::array();
  for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
    if (m.type_cells[mask] > 0)
      types.push_back({{"mask", mask}, {"types", type_mask_string(mask)}, {"cells", m.type_cells[mask]}});
  j["types"] = types;
  j["type_bits"] = {{"open", type_bit(Type3d::kOpen)}, {"separation", type_bit(Type3d::kSeparation)},
                    {"stick", type_bit(Type3d::kStick)}, {"slip", type_bit(Type3d::kSlip)}};
  j["incomplete_cells"] = m.incomplete_cells;
  j["timed_out_cells"] = m.timed_out_cells;
  j["time_limit_reached"] = m.timed_out_cells > 0;
  const bool complete = m.incomplete_cells == 0;
  j["complete"] = complete;
  j["threads"] = m.threads;
  j["estimate"] = {{"seconds", seconds >= 0 ? nlohmann::json(seconds) : nlohmann::json()},
                   {"sampled_cells", sampled}};
  j["seconds"] = clock.seconds();

  bool plot_failed = false;
  nlohmann::json files = nlohmann::json::object();
  if (!r.out.empty()) {
    GridFiles out(r.out, files);
    try {
      out.add_npy("count", "|i1", m.rows, m.cols);
      out.add_npy("types", "|u1", m.rows, m.cols);
      out.add_npy("complete", "|u1", m.rows, m.cols);
      out.write_vector("x", m.x);
      out.write_vector("y", m.y);
      out.append({m.count.data(), m.types.data(), m.complete.data()}, m.cells());
      out.finish();
    } catch (...) {
      out.discard();
      throw;
    }
    files["json"] = fs::path(r.out).filename().string() + ".json";
    j["files"] = files;
    j["run"] = run_echo();
    write_text_file(r.out + ".json", [&](std::ostream& s) { s << json_text(j) << '\n'; });
    if (r.plot) {
      plot_failed = !run_map_plot(r.out, files);
      j["files"] = files;
      write_text_file(r.out + ".json", [&](std::ostream& s) { s << json_text(j) << '\n'; });
    }
  }
  if (m.timed_out_cells > 0)
    std::cerr << "cpkit map: time limit reached (--time-limit " << fmt(r.time_limit) << " s): "
              << m.timed_out_cells << " cells cut short (their count is what was found) or "
              << "not computed (count 0), flagged 0 in 'complete'\n";
  if (!complete)
    std::cerr << "cpkit map: " << m.incomplete_cells
              << " cells not proved complete (a merging pair of slip directions, an "
                 "undecided enumeration, or the time limit): flagged 0 in 'complete'\n";
  if (r.json) {
    print_json(j);
  } else {
    std::cout << r.kind << " map of " << N << (N == 1 ? " 3-D point" : " 3-D points") << " ("
              << r.path << "), ";
    if (r.kind != "param-param") std::cout << "load at point " << r.point << ", ";
    std::cout << (o.facets ? "faceted with " + std::to_string(o.facets) + " facets" : std::string("exact"))
              << ": " << m.cells() << " cells\n";
    if (r.kind == "sphere")
      std::cout << "  dF = (sin b cos g, sin b sin g, cos b): b in [" << fmt(p.grid.beta_from)
                << ", " << fmt(p.grid.beta_to) << "] (" << m.rows << " values) x g in (-pi, pi] ("
                << m.cols << " values)\n";
    else if (r.kind == "param-direction")
      std::cout << "  " << xname << " in [" << fmt(r.from) << ", " << fmt(r.to) << "] ("
                << m.rows << " values) x theta in [" << fmt(p.theta_from) << ", "
                << fmt(p.theta_to) << "] (" << m.cols << " values) at g = " << fmt(p.gamma) << '\n';
    else
      std::cout << "  " << xname << " in [" << fmt(r.from) << ", " << fmt(r.to) << "] x " << yname
                << " in [" << fmt(r.from2) << ", " << fmt(r.to2) << "]\n";
    std::cout << "counts:\n";
    for (const auto& [c, n] : m.count_cells) std::cout << "  " << count_text(c) << ": " << n << " cells\n";
    std::cout << "types:\n";
    for (unsigned mask = 0; mask < m.type_cells.size(); ++mask)
      if (m.type_cells[mask] > 0)
        std::cout << "  " << type_mask_string(mask) << ": " << m.type_cells[mask] << " cells\n";
    std::cout << "not proved complete: " << m.incomplete_cells << " cells\n";
    if (m.timed_out_cells > 0)
      std::cout << "time limit reached: " << m.timed_out_cells << " cells cut short or not "
                << "computed\n";
    if (!r.out.empty()) {
      std::cout << "wrote";
      for (const auto& [k, v] : files.items())
        std::cout << ' ' << (fs::path(r.out).parent_path() / v.get<std::string>()).string();
      std::cout << '\n';
    }
  }
  if (!complete) return kExitInconclusive;
  return plot_failed ? kExitInternal : kExitOk;
}

}  // namespace cpkit::cli
