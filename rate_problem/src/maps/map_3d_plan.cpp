// The plan, the run and the up-front cost of a 3-D map (maps/map_3d_plan.hpp), moved out of
// the program (maps/map_request_run.cpp runs the request, report/map_text.cpp words the summary).
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"

#include <algorithm>
#include <cmath>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::rate {

namespace {

constexpr double kPi = 3.141592653589793;

/// A map axis of the request: --paramS NAME (the map parameter table's), --fromS, --toS, --nS.
Map3dAxis axis_of(const std::string& param, double from, double to, int n, int n_points,
                  const std::string& suffix) {
  Map3dAxis a;
  a.param = parse_map_3d_parameter(param, n_points);
  a.from = from;
  a.to = to;
  a.n = n;
  if (a.n < 1 || a.n > 1000000) throw InputError("--n" + suffix + " must be in [1, 1000000]");
  if (a.n > 1 && !(from < to))
    throw InputError("--from" + suffix + " must be < --to" + suffix);
  return a;
}

/// The route (--facets) and its limits, --point and --others into p.options.
void set_route(const Map3dRequest& r, Map3dPlan& p) {
  const int N = p.sys.n_points();
  Map3dOptions& o = p.options;
  if (r.facets) {
    if (*r.facets < 3 || *r.facets > kMaxFacets)
      throw InputError("--facets must be in [3, " + std::to_string(kMaxFacets) + "], got " +
                       std::to_string(*r.facets));
    o.facets = *r.facets;
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
      throw InputError(r.system.value_or("") + ": " + std::to_string(nb) + " grazing points (state b); the "
                       "faceted route takes at most " + std::to_string(kMaxGrazing3d) +
                       " (2^n_b separation cases per cell)");
    if (nd + o.facets * nb > lcp::kMaxEnumerationSize)
      throw InputError(r.system.value_or("") + ": the faceted LCP would have size n_d + K n_b = " +
                       std::to_string(nd + o.facets * nb) + " > " +
                       std::to_string(lcp::kMaxEnumerationSize) + ": use fewer --facets");
  }
  const int point = r.point.value_or(1);
  if (point < 1 || point > N)
    throw InputError("--point must be in [1, " + std::to_string(N) + "], got " +
                     std::to_string(point));
  o.point = point - 1;
  // The other points' load rates: the file's dF when it has one (a grazing point with a zero
  // load rate is a degenerate LCP: slow, and not proved complete), else 0; --others chooses.
  o.others_from_file = r.others ? *r.others == "file" : (N > 1 && p.sys.dF.has_value());
  if (o.others_from_file && !p.sys.dF)
    throw InputError("--others file needs \"dF\" in the system file (the other points' load "
                     "rates)");
  if (o.others_from_file && N == 1) throw InputError("--others has no effect with one point");
  o.threads = r.threads.value_or(0);
}

/// --kind sphere: the grid of b (--n, --from, --to) and g (--n2).
void set_sphere_grid(const Map3dRequest& r, Map3dPlan& p) {
  p.grid.n_beta = r.n.value_or(91);
  p.grid.n_gamma = r.n2.value_or(180);
  p.grid.beta_from = r.from.value_or(p.grid.beta_from);
  p.grid.beta_to = r.to.value_or(p.grid.beta_to);
  if (p.grid.n_beta < 1 || p.grid.n_beta > 1000000) throw InputError("--n must be in [1, 1000000]");
  if (p.grid.n_gamma < 1 || p.grid.n_gamma > 1000000)
    throw InputError("--n2 must be in [1, 1000000]");
  if (p.grid.beta_from < 0 || p.grid.beta_from > kPi || p.grid.beta_to < 0 ||
      p.grid.beta_to > kPi)
    throw InputError("--from/--to (the range of b, rad) must lie in [0, pi]");
  if (!(p.grid.beta_from < p.grid.beta_to)) throw InputError("--from must be < --to");
  p.cells = static_cast<int64_t>(p.grid.n_beta) * p.grid.n_gamma;
  p.cells_text = std::to_string(p.grid.n_beta) + " x " + std::to_string(p.grid.n_gamma) +
                 " cells (--n x --n2)";
  p.fewer = "use a smaller --n or --n2";
  p.xname = "beta";
  p.yname = "gamma";
  p.input["n"] = p.grid.n_beta;
  p.input["n2"] = p.grid.n_gamma;
  p.input["beta_from"] = p.grid.beta_from;
  p.input["beta_to"] = p.grid.beta_to;
  p.input["others"] = p.options.others_from_file ? "file" : "zero";
}

/// --kind param-direction: the directions (--theta-n, --theta-from, --theta-to, --gamma).
void set_directions(const Map3dRequest& r, Map3dPlan& p) {
  p.theta_n = r.theta_n.value_or(360);
  if (p.theta_n < 1 || p.theta_n > 1000000) throw InputError("--theta-n must be in [1, 1000000]");
  p.theta_from = r.theta_from.value_or(p.theta_from);
  p.theta_to = r.theta_to.value_or(p.theta_to);
  if (!(p.theta_to > p.theta_from) || p.theta_to - p.theta_from > 2 * kPi + 1e-12)
    throw InputError("--theta-from/--theta-to: need 0 < theta_to - theta_from <= 2 pi");
  p.gamma = r.gamma.value_or(0.0);
  p.cells = static_cast<int64_t>(p.a1.n) * p.theta_n;
  p.cells_text =
      std::to_string(p.a1.n) + " x " + std::to_string(p.theta_n) + " cells (--n x --theta-n)";
  p.fewer = "use a smaller --n or --theta-n";
  p.yname = "theta";
  p.input["theta_n"] = p.theta_n;
  p.input["theta_from"] = p.theta_from;
  p.input["theta_to"] = p.theta_to;
  p.input["gamma"] = p.gamma;
  p.input["others"] = p.options.others_from_file ? "file" : "zero";
}

/// --kind param-param: the second axis, at the file's dF.
void set_second_axis(const Map3dRequest& r, Map3dPlan& p) {
  const int N = p.sys.n_points();
  p.a2 = axis_of(r.param2.value_or(""), r.from2.value_or(0), r.to2.value_or(0), r.n2.value_or(100), N, "2");
  if (!p.sys.dF)
    throw InputError("--kind param-param with a dim 3 system is computed at the file's "
                     "load rate: the system file needs \"dF\"");
  p.cells = static_cast<int64_t>(p.a1.n) * p.a2.n;
  p.cells_text = std::to_string(p.a1.n) + " x " + std::to_string(p.a2.n) + " cells (--n x --n2)";
  p.fewer = "use a smaller --n or --n2";
  p.yname = p.a2.param.name();
  p.input["param2"] = p.yname;
  p.input["from2"] = r.from2.value_or(0);
  p.input["to2"] = r.to2.value_or(0);
  p.input["n2"] = p.a2.n;
  const Eigen::VectorXd& d = *p.sys.dF;
  p.input["dF"] = std::vector<double>(d.data(), d.data() + d.size());
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

}  // namespace

void check_map_3d_request(const MapRequest& r, int processes) {
  const std::string kind = r.kind.value_or("");
  if (kind.empty())
    throw InputError("maps of a dim 3 system need --kind sphere, param-direction or param-param "
                     "(the 2-D direction map has no 3-D counterpart: --kind sphere maps the "
                     "sphere of load directions)");
  if (kind != "sphere" && kind != "param-direction" && kind != "param-param")
    throw InputError("--kind with a dim 3 system must be sphere, param-direction or param-param, "
                     "got '" + kind + "'");
  const std::vector<std::string> allowed = allowed_options(kind);
  std::string list;
  for (const auto& o : allowed) list += (list.empty() ? "" : ", ") + o;
  for (const auto& o : map_options_given(r))
    if (std::find(allowed.begin(), allowed.end(), o) == allowed.end())
      throw InputError(o + " has no effect with a dim 3 system and --kind " + kind +
                       " (the model comes from the system file; options: " + list +
                       ", --json, --plot)");
  std::vector<std::pair<const char*, bool>> needed;
  if (kind != "sphere")
    needed = {{"--param", r.param.has_value()}, {"--from", r.from.has_value()},
              {"--to", r.to.has_value()}};
  if (kind == "param-param")
    needed.insert(needed.end(), {{"--param2", r.param2.has_value()},
                                 {"--from2", r.from2.has_value()}, {"--to2", r.to2.has_value()}});
  for (const auto& [name, given] : needed)
    if (!given) throw InputError("--kind " + kind + " with a dim 3 system needs " + name);
  if (kind == "sphere" && (r.from.has_value() != r.to.has_value()))
    throw InputError("--from and --to (the range of b, rad) go together");
  const std::pair<const char*, const std::optional<double>&> reals[] = {
      {"--from", r.from},   {"--to", r.to},         {"--from2", r.from2},
      {"--to2", r.to2},     {"--theta-from", r.theta_from}, {"--theta-to", r.theta_to},
      {"--gamma", r.gamma}, {"--time-limit", r.time_limit}};
  for (const auto& [name, v] : reals)
    if (v && !std::isfinite(*v)) throw InputError(std::string(name) + " must be finite");
  if (!(r.time_limit.value_or(kMapTimeLimitDefault) > 0))
    throw InputError("--time-limit must be a positive number of seconds");
  if (r.format && *r.format != "npy")
    throw InputError("--format: 3-D maps are written as .npy arrays only, got '" + *r.format + "'");
  const bool no_out = r.out.value_or("").empty();
  if (r.format && no_out) throw InputError("--format needs --out PREFIX");
  if (r.plot && no_out) throw InputError("--plot needs --out PREFIX");
  const int threads = r.threads.value_or(0);
  if (threads < 0 || threads > 1024)
    throw InputError("--threads must be in [0, 1024] (0: all cores), got " + std::to_string(threads));
  if (r.others && *r.others != "zero" && *r.others != "file")
    throw InputError("--others must be zero or file, got '" + *r.others + "'");
  if (processes > 1)
    throw InputError("3-D maps run on the threads of one process: run them without mpirun "
                     "(--threads)");
}

Map3dPlan make_map_3d_plan(const Map3dRequest& r) {
  Map3dPlan p;
  p.kind = r.kind.value_or("");
  p.sys = parse_contact_system_3d(r.file);
  const int N = p.sys.n_points();
  set_route(r, p);
  const Map3dOptions& o = p.options;
  p.input = {{"system", r.system.value_or("")}, {"name", p.sys.name}, {"n_points", N},
             {"point", r.point.value_or(1)},
             {"route", o.facets ? "faceted" : "exact"},
             {"facets", o.facets ? nlohmann::json(o.facets) : nlohmann::json()}};
  if (p.kind == "sphere") {
    set_sphere_grid(r, p);
    return p;
  }
  p.a1 = axis_of(r.param.value_or(""), r.from.value_or(0), r.to.value_or(0), r.n.value_or(100),
                 N, "");
  p.xname = p.a1.param.name();
  p.input["param"] = p.xname;
  p.input["from"] = r.from.value_or(0);
  p.input["to"] = r.to.value_or(0);
  p.input["n"] = p.a1.n;
  if (p.kind == "param-direction")
    set_directions(r, p);
  else
    set_second_axis(r, p);
  return p;
}

Map3d compute_map_3d(const Map3dPlan& p, const Map3dOptions& o, const Map3dProgress& progress) {
  if (p.kind == "sphere") return compute_sphere_map_3d(p.sys, p.grid, o, progress);
  if (p.kind == "param-direction")
    return compute_param_direction_map_3d(p.sys, p.a1, p.theta_n, p.theta_from, p.theta_to,
                                          p.gamma, o, progress);
  return compute_param_param_map_3d(p.sys, p.a1, p.a2, o, progress);
}

double estimate_map_3d_seconds(const Map3dPlan& p, int threads, int64_t& sampled,
                               const Stopwatch& clock, double time_limit) {
  Map3dPlan s = p;
  Map3dOptions one = p.options;
  one.threads = 1;
  if (p.kind == "sphere") {
    s.grid.n_beta = std::min(p.grid.n_beta, 4);
    s.grid.n_gamma = std::min(p.grid.n_gamma, 8);
  } else if (p.kind == "param-direction") {
    s.a1.n = std::min(p.a1.n, 3);
    s.theta_n = std::min(p.theta_n, 8);
  } else {
    s.a1.n = std::min(p.a1.n, 3);
    s.a2.n = std::min(p.a2.n, 6);
  }
  if (s.rows() == p.rows() && s.cols() == p.cols()) {
    sampled = 0;  // the sample would be the map itself: computed once, within the deadline
    return -1;
  }
  double t = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    // The second run only when the first left most of the budget.
    if (rep == 1 && t > 0.25 * (time_limit - clock.seconds())) break;
    one.time_limit_s = time_limit - clock.seconds();
    const Stopwatch c;
    const Map3d m = one.time_limit_s > 0 ? compute_map_3d(s, one) : Map3d{};
    if (!(one.time_limit_s > 0) || m.timed_out_cells > 0)
      throw InputError("the map has " + p.cells_text + "; a timed sample of " +
                       std::to_string(std::max<int64_t>(1, m.cells())) +
                       " of them alone ran past --time-limit " + num_text(time_limit, 4) +
                       " s (the time limit was reached): " + p.fewer +
                       (p.options.facets ? ", fewer --facets or fewer grazing points" : "") +
                       ", or raise --time-limit");
    t = std::min(t, c.seconds());
    sampled = m.cells();
  }
  return t / static_cast<double>(std::max<int64_t>(1, sampled)) * static_cast<double>(p.cells) /
         threads;
}

double map_3d_output_bytes(const Map3dPlan& p) {
  return 3.0 * static_cast<double>(p.cells) + 8.0 * (p.rows() + p.cols()) + 5 * 4096;
}

}  // namespace cpkit::rate
