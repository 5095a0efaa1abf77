// The request of `cpkit map` and the one-point map it describes (maps/map_request.hpp), moved
// out of the program: the preset, the options over it, and the refusal of options that would
// have no effect (never a hidden default, never silence).
#include "cpkit/rate_problem/maps/map_request.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <tuple>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/memory_limit.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "../model/options_given.hpp"

namespace cpkit::rate {

std::vector<std::string> map_options_given(const MapRequest& a) {
  const std::pair<const char*, bool> all[] = {
      {"--C_T", a.C_T.has_value()},         {"--P_N", a.P_N.has_value()},
      {"--P_s", a.P_s.has_value()},         {"--a11", a.a11.has_value()},
      {"--a12", a.a12.has_value()},         {"--a22", a.a22.has_value()},
      {"--criterion", a.criterion.has_value()}, {"--facets", a.facets.has_value()},
      {"--format", a.format.has_value()},   {"--from", a.from.has_value()},
      {"--from2", a.from2.has_value()},     {"--gamma", a.gamma.has_value()},
      {"--k_a", a.k_a.has_value()},         {"--kind", a.kind.has_value()},
      {"--max-output", a.max_output.has_value()}, {"--method", a.method.has_value()},
      {"--mu", a.mu.has_value()},           {"--n", a.n.has_value()},
      {"--n2", a.n2.has_value()},           {"--others", a.others.has_value()},
      {"--out", a.out.has_value()},         {"--param", a.param.has_value()},
      {"--param2", a.param2.has_value()},   {"--point", a.point.has_value()},
      {"--preset", a.preset.has_value()},   {"--resume", a.resume.has_value()},
      {"--sgnPT", a.sgnPT.has_value()},     {"--state", a.state.has_value()},
      {"--system", a.system.has_value()},   {"--theta-from", a.theta_from.has_value()},
      {"--theta-n", a.theta_n.has_value()}, {"--theta-to", a.theta_to.has_value()},
      {"--threads", a.threads.has_value()}, {"--time-limit", a.time_limit.has_value()},
      {"--to", a.to.has_value()},           {"--to2", a.to2.has_value()}};
  std::vector<std::string> names;
  for (const auto& [name, given] : all)
    if (given) names.push_back(name);
  return names;
}

namespace {

using detail::Given;
using detail::option;

void require_finite(double v, const char* name) {
  if (!std::isfinite(v)) throw InputError(std::string("--") + name + " must be finite");
}


/// Options that would have no effect are errors (never hidden defaults, never silence).
void check_options_have_effect(const MapRequest& a, const MapSetup& s,
                                const std::function<void(const std::string&)>& note) {
  auto on_axis = [&](const std::string& name) {
    auto is = [&name](const std::optional<std::string>& p) {
      return p && (*p == name || (name == "a12" && *p == "a12/a11"));
    };
    return is(a.param) || is(a.param2);
  };
  for (const Given o : {option("--a11", a.a11), option("--a12", a.a12), option("--a22", a.a22),
                        option("--mu", a.mu), option("--C_T", a.C_T), option("--k_a", a.k_a),
                        option("--P_s", a.P_s), option("--P_N", a.P_N)})
    if (o.given && on_axis(o.name + 2))
      throw InputError(std::string(o.name) + " has no effect: " + (o.name + 2) +
                       " varies along the map's parameter axis (--param/--param2)");
  if (a.preset.value_or("").empty()) {
    std::string missing;
    for (const Given o : {option("--a11", a.a11), option("--a12", a.a12),
                          option("--a22", a.a22), option("--mu", a.mu)})
      if (!o.given && !on_axis(o.name + 2))
        missing += (missing.empty() ? "" : " ") + std::string(o.name);
    if (!missing.empty())
      throw InputError("cpkit map needs a model: --preset NAME (--list-presets shows them) or "
                       "--a11 --a12 --a22 --mu (missing: " + missing + ")");
  }
  auto none_of = [&](std::initializer_list<Given> opts, const std::string& why) {
    for (const Given o : opts)
      if (o.given) throw InputError(std::string(o.name) + " has no effect " + why);
  };
  const Given second_axis[] = {option("--param2", a.param2), option("--from2", a.from2),
                               option("--to2", a.to2), option("--n2", a.n2)};
  if (s.kind == MapKind::kDirection)
    none_of({option("--param", a.param), option("--from", a.from), option("--to", a.to),
             option("--n", a.n), second_axis[0], second_axis[1], second_axis[2], second_axis[3],
             option("--threads", a.threads)},
            "in a direction map (it has no parameter axis; use --kind param-direction or "
            "param-param)");
  if (s.kind == MapKind::kParamDirection)
    none_of({second_axis[0], second_axis[1], second_axis[2], second_axis[3]},
            "in a param-direction map (one parameter axis; use --kind param-param)");
  const StateLabel st = s.state.label;
  if (st == StateLabel::kA || st == StateLabel::kB) {
    none_of({option("--P_N", a.P_N)},
            std::string("in state ") + std::string(to_string(st)) +
                " (P_N = 0 there: the normal force enters only states c and d)");
    // Material parameters a user describes once and sweeps over states: accepted and echoed.
    for (const Given o : {option("--k_a", a.k_a), option("--P_s", a.P_s)})
      if (o.given && note)
        note(std::string(o.name) + " does not enter state " + std::string(to_string(st)) +
             " (P_N = 0 there, so no wear: kappa = k_a P_N / (3 P_s) enters states c "
             "and d); accepted and echoed in the model");
  }
  if (st != StateLabel::kD) none_of({option("--sgnPT", a.sgnPT)}, "outside state d (the sliding state)");
}

}  // namespace

MapSetup make_map_setup(const MapRequest& a,
                        const std::function<void(const std::string&)>& note) {
  MapSetup s;
  if (!a.preset.value_or("").empty()) {
    const auto p = find_map_preset(*a.preset);
    if (!p) {
      std::string names;
      for (const auto& x : map_presets()) names += (names.empty() ? "" : ", ") + x.name;
      throw InputError("unknown preset '" + *a.preset + "' (known: " + names + ")");
    }
    s.params = p->params;
    s.state = p->state;
    s.kind = p->kind;
    s.axis = p->axis;
    s.axis2 = p->axis2;
    s.have_axis = s.have_axis2 = true;
    s.theta_n = p->theta_n;
  }
  if (a.kind) {
    const auto k = map_kind_from_string(*a.kind);
    if (!k) throw InputError("--kind must be direction, param-direction or param-param, got '" +
                             *a.kind + "'");
    s.kind = *k;
  }
  if (a.state) {
    const auto l = state_from_string(*a.state);
    if (!l) throw InputError("--state must be a, b, c or d, got '" + *a.state + "'");
    s.state.label = *l;
  }
  if (a.criterion) {
    const auto c = criterion_from_string(*a.criterion);
    if (!c)
      throw InputError("--criterion must be 38 (Coulomb, default) or 35 (softening), got '" +
                       *a.criterion + "'");
    s.params.criterion = *c;
  }
  struct {
    const char* name;
    const std::optional<double>& value;
    double& target;
  } const fields[] = {{"--a11", a.a11, s.params.a11}, {"--a12", a.a12, s.params.a12},
                      {"--a22", a.a22, s.params.a22}, {"--mu", a.mu, s.params.mu},
                      {"--C_T", a.C_T, s.params.C_T}, {"--k_a", a.k_a, s.params.k_a},
                      {"--P_s", a.P_s, s.params.P_s}, {"--P_N", a.P_N, s.state.P_N}};
  for (const auto& f : fields)
    if (f.value) {
      require_finite(*f.value, f.name + 2);
      f.target = *f.value;
    }
  if (a.sgnPT) {
    if (*a.sgnPT != 1 && *a.sgnPT != -1) throw InputError("--sgnPT must be +1 or -1");
    s.state.sgn_PT = *a.sgnPT;
  }
  check_options_have_effect(a, s, note);
  throw_if_invalid(s.params.validate(), "model parameters");
  throw_if_invalid(s.state.validate(s.params), "contact state");

  // An axis: --paramS NAME over the preset's, --fromS, --toS, --nS (S: "" or "2").
  auto set_axis = [&](MapAxis& axis, bool& have, const std::optional<std::string>& name,
                      const std::optional<double>& from, const std::optional<double>& to,
                      const std::optional<int>& n, const std::string& S) {
    const std::string o_param = "--param" + S, o_from = "--from" + S, o_to = "--to" + S,
                      o_n = "--n" + S;
    if (name) {
      const auto p = map_parameter_from_string(*name);  // the table's names and aliases
      if (!p) (void)check_map_parameter(*name, kMapOnePoint, 1, o_param);  // throws, naming it
      if (!p) throw InputError(o_param + ": unknown parameter '" + *name + "'");
      if (!have || axis.param != *p) {
        if (!from || !to) throw InputError(o_param + " " + *name + " needs " + o_from + " and " + o_to);
        axis.n = 200;
      }
      axis.param = *p;
      have = true;
    }
    if (from) axis.from = *from;
    if (to) axis.to = *to;
    if (n) axis.n = *n;
    if ((from || to || n) && !have)
      throw InputError(o_from + "/" + o_to + "/" + o_n + " need " + o_param);
    require_finite(axis.from, o_from.c_str() + 2);
    require_finite(axis.to, o_to.c_str() + 2);
  };
  set_axis(s.axis, s.have_axis, a.param, a.from, a.to, a.n, "");
  set_axis(s.axis2, s.have_axis2, a.param2, a.from2, a.to2, a.n2, "2");
  if (a.theta_n) {
    // Only a param-direction map samples directions; a direction map computes its critical
    // directions exactly and a param-param map classifies each cell from its exact direction map.
    if (s.kind != MapKind::kParamDirection)
      throw InputError("--theta-n applies to --kind param-direction only (a " +
                       std::string(to_string(s.kind)) +
                       " map computes the critical directions exactly, without sampling)");
    s.theta_n = *a.theta_n;
  }
  if (s.kind != MapKind::kDirection && !s.have_axis)
    throw InputError(std::string(to_string(s.kind)) + " map needs --param NAME --from X --to Y");
  if (s.kind == MapKind::kParamParam && !s.have_axis2)
    throw InputError("param-param map needs --param2 NAME --from2 X --to2 Y");
  return s;
}

SystemGridPlan make_system_grid_plan(const SystemMapRequest& r) {
  SystemGridPlan p;
  p.sys = parse_contact_system(r.file);
  // Limits that depend on N and the states, before any work in proportion to N.
  check_system_map_lcp_size(p.sys, "a map of its cells");
  const int N = p.sys.n_points();
  auto axis_of = [N](const std::string& param, double from, double to, int n) {
    SystemMapAxis a;
    a.param = parse_system_map_parameter(param, N);
    a.from = from;
    a.to = to;
    a.n = n;
    return a;
  };
  p.axis = axis_of(r.param, r.from, r.to, r.n);
  const bool pd = r.kind == "param-direction";
  if (!pd) p.axis2 = axis_of(r.param2, r.from2, r.to2, r.n2);
  p.options.threads = r.threads;
  if (pd) {
    p.options.theta_from = r.theta_from;
    p.options.theta_to = r.theta_to;
    if (std::string e = p.options.validate(); !e.empty())
      throw InputError("--theta-from/--theta-to: " + e);
  }
  Eigen::VectorXd e1, e2;
  system_map_patterns(p.sys, e1, e2);
  auto list = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  p.input = {{"system", r.path}, {"name", p.sys.name}, {"n_points", N},
             {"param", p.axis.param.name()}, {"from", r.from}, {"to", r.to}, {"n", r.n},
             {"patterns", {list(e1), list(e2)}}};
  if (pd) {
    p.input.update({{"theta_n", r.theta_n}, {"theta_from", r.theta_from},
                    {"theta_to", r.theta_to}});
    p.cells_text = std::to_string(r.n) + " x " + std::to_string(r.theta_n) +
                   " cells (--n x --theta-n)";
    p.fewer = "use a smaller --n or --theta-n";
  } else {
    p.input.update({{"param2", p.axis2.param.name()}, {"from2", r.from2}, {"to2", r.to2},
                    {"n2", r.n2}});
    p.cells_text = std::to_string(r.n) + " x " + std::to_string(r.n2) + " cells (--n x --n2)";
    p.fewer = "use a smaller --n or --n2";
  }
  return p;
}

SystemMapRequest system_map_request(const MapRequest& a, SystemFile file, int processes) {
  const std::string kind = a.kind.value_or("direction");
  const std::string out = a.out.value_or(""), format = a.format.value_or(kMapFormatDefault);
  const double time_limit = a.time_limit.value_or(kMapTimeLimitDefault);
  const int threads = a.threads.value_or(0);
  std::vector<std::string> allowed = {"--system", "--kind", "--out", "--json", "--threads"};
  const double max_output =
      parse_byte_size(a.max_output.value_or(kMapMaxOutputDefault), "--max-output");
  const Given first_axis[] = {option("--param", a.param), option("--from", a.from),
                              option("--to", a.to)};
  const Given second_axis[] = {option("--param2", a.param2), option("--from2", a.from2),
                               option("--to2", a.to2)};
  std::vector<Given> needed;
  if (kind == "param-direction")
    needed.assign(std::begin(first_axis), std::end(first_axis));
  else if (kind == "param-param") {
    needed.assign(std::begin(first_axis), std::end(first_axis));
    needed.insert(needed.end(), std::begin(second_axis), std::end(second_axis));
  } else if (kind != "direction")
    throw InputError("--kind with --system must be direction, param-direction or param-param, "
                     "got '" + kind + "'");
  for (const Given& o : needed) allowed.push_back(o.name);
  if (kind != "direction")
    for (const char* o : {"--n", "--format", "--time-limit", "--max-output", "--resume"})
      allowed.push_back(o);
  if (kind == "param-direction")
    for (const char* o : {"--theta-n", "--theta-from", "--theta-to"}) allowed.push_back(o);
  if (kind == "param-param") allowed.push_back("--n2");
  std::string list;
  for (const auto& o : allowed) list += (list.empty() ? "" : ", ") + o;
  for (const auto& name : map_options_given(a))
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
      throw InputError(name + " does not apply with --system --kind " + kind +
                       " (the state, parameters and load patterns come from the system file; "
                       "options: " + list + (kind == "direction" ? "" : ", --plot") + ")");
  for (const Given& o : needed)
    if (!o.given) throw InputError("--system --kind " + kind + " needs " + o.name);
  if (a.plot && kind == "direction")
    throw InputError("--plot with --system applies to --kind param-direction and param-param");
  if (a.plot && out.empty()) throw InputError("--plot needs --out PREFIX");
  if (a.resume.value_or(false) && out.empty())
    throw InputError("--resume needs --out PREFIX (the finished chunks are kept in PREFIX.parts)");
  if (kind == "direction" && processes > 1)
    throw InputError("a direction map is one exact computation, not a grid of cells: run it "
                     "without mpirun (--threads uses the cores of one machine)");
  if (a.format && out.empty())
    throw InputError("--format needs --out PREFIX (without --out only the summary is printed)");
  if (format != "npy" && format != "csv")
    throw InputError("--format must be npy or csv, got '" + format + "'");
  if (!(time_limit > 0) || !std::isfinite(time_limit))
    throw InputError("--time-limit must be a positive number of seconds");
  if (threads < 0 || threads > 1024)
    throw InputError("--threads must be in [0, 1024] (0: all cores), got " +
                     std::to_string(threads));
  SystemMapRequest r;
  r.path = a.system.value_or("");
  r.file = std::move(file);
  r.kind = kind;
  r.max_output = max_output;
  std::tie(r.out, r.format, r.threads, r.time_limit) = std::tie(out, format, threads, time_limit);
  std::tie(r.json, r.plot) = std::tie(a.json, a.plot);
  r.resume = a.resume.value_or(false);
  r.param = a.param.value_or("");
  r.param2 = a.param2.value_or("");
  r.from = a.from.value_or(0);
  r.to = a.to.value_or(0);
  r.from2 = a.from2.value_or(0);
  r.to2 = a.to2.value_or(0);
  r.n = a.n.value_or(r.n);
  r.n2 = a.n2.value_or(r.n2);
  r.theta_n = a.theta_n.value_or(r.theta_n);
  r.theta_range = a.theta_from || a.theta_to;
  r.theta_from = a.theta_from.value_or(r.theta_from);
  r.theta_to = a.theta_to.value_or(r.theta_to);
  return r;
}

}  // namespace cpkit::rate
