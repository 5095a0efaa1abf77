// `cpkit map`: non-existence and non-uniqueness maps of the rate problem (docs/maps.md).
// Thin: parse, call the library (cpkit/rate_problem/{direction_map,grid_map,map_output}.hpp),
// write CSV/JSON, run the plotting script.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <initializer_list>
#include <map>
#include <vector>
#include <memory>
#include <thread>
#include <sstream>

#include "cli_common.hpp"
#include "map_chunks.hpp"
#include "map_files.hpp"
#include "map_system.hpp"
#include "map_system_3d.hpp"
#include "mpi_session.hpp"
#include "cli_options.hpp"
#include "cpkit/core/errors.hpp"
#include "data_files.hpp"
#include "run_program.hpp"
#include "machine_resources.hpp"
#include "memory_limit.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/map_presets.hpp"
#include "cpkit/rate_problem/maps/npy_writer.hpp"
#include "cpkit/rate_problem/system/contact_system_3d.hpp"

namespace cpkit::cli {


namespace {

namespace fs = std::filesystem;
using namespace cpkit::rate;

struct MapArgs {
  std::string preset, kind, state, method = "enumerate", out, param, param2, criterion;
  std::string system;  // --system FILE: the N-point direction map (map_system.cpp)
  std::string format = "npy";
  double time_limit = 600;  // seconds of cells the estimate may reach (--time-limit)
  // The defaults shown by --help are the values used (a test compares them with the run echo);
  // options whose default depends on the map (--n, --theta-to, ...) show none.
  double a11 = 0, a12 = 0, a22 = 0, mu = 0, C_T = 0, k_a = 0, P_s = 1, P_N = 0;
  int sgnPT = 1;
  double from = 0, to = 0, from2 = 0, to2 = 0, theta_from = 0, theta_to = 0;
  int n = 0, n2 = 0, theta_n = 360, threads = 0;
  std::string max_output = "4G";  // --max-output SIZE (byte_size.hpp)
  bool plot = false, json = false, list_presets = false, resume = false;
  // 3-D systems only (map_system_3d.cpp): --facets K, --point i, --others zero|file, --gamma G
  int facets = 0, point = 1;
  std::string others;  // --others: zero or file (default: file when the file has dF)
  double gamma = 0;
  // Which options were given (CLI11 Option pointers).
  std::map<std::string, CLI::Option*> opt;
  bool given(const std::string& name) const {
    auto it = opt.find(name);
    return it != opt.end() && it->second->count() > 0;
  }
};

std::string fmt(double x, int digits = 4) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

std::string types_text(unsigned mask) {
  std::string s = types_to_string(mask);
  for (auto& c : s)
    if (c == '|') c = ',';
  std::string out;
  for (char c : s) {
    out += c;
    if (c == ',') out += ' ';
  }
  return out;
}

std::string count_text(int count) {
  if (count < 0) return "a continuum of solutions";
  if (count == 0) return "no solution";
  return std::to_string(count) + (count == 1 ? " solution" : " solutions");
}

void require_finite(double v, const char* name) {
  if (!std::isfinite(v)) throw InputError(std::string("--") + name + " must be finite");
}

/// The model, kind and axes from the preset (if any) and the explicit options.
struct MapSetup {
  ContactParameters params;
  ContactState state;
  MapKind kind = MapKind::kDirection;
  MapAxis axis, axis2;
  bool have_axis = false, have_axis2 = false;
  int theta_n = 360;
};

/// Options that would have no effect are errors (never hidden defaults, never silence).
void check_options_have_effect(const MapArgs& a, const MapSetup& s) {
  auto on_axis = [&](const std::string& name) {
    return (a.given("--param") && (a.param == name || (name == "a12" && a.param == "a12/a11"))) ||
           (a.given("--param2") && (a.param2 == name || (name == "a12" && a.param2 == "a12/a11")));
  };
  for (const char* o : {"--a11", "--a12", "--a22", "--mu", "--C_T", "--k_a", "--P_s", "--P_N"})
    if (a.given(o) && on_axis(o + 2))
      throw InputError(std::string(o) + " has no effect: " + (o + 2) +
                       " varies along the map's parameter axis (--param/--param2)");
  if (a.preset.empty()) {
    std::string missing;
    for (const char* o : {"--a11", "--a12", "--a22", "--mu"})
      if (!a.given(o) && !on_axis(o + 2)) missing += (missing.empty() ? "" : " ") + std::string(o);
    if (!missing.empty())
      throw InputError("cpkit map needs a model: --preset NAME (--list-presets shows them) or "
                       "--a11 --a12 --a22 --mu (missing: " + missing + ")");
  }
  auto none_of = [&](std::initializer_list<const char*> opts, const std::string& why) {
    for (const char* o : opts)
      if (a.given(o)) throw InputError(std::string(o) + " has no effect " + why);
  };
  if (s.kind == MapKind::kDirection)
    none_of({"--param", "--from", "--to", "--n", "--param2", "--from2", "--to2", "--n2",
             "--threads"},
            "in a direction map (it has no parameter axis; use --kind param-direction or "
            "param-param)");
  if (s.kind == MapKind::kParamDirection)
    none_of({"--param2", "--from2", "--to2", "--n2"},
            "in a param-direction map (one parameter axis; use --kind param-param)");
  const StateLabel st = s.state.label;
  if (st == StateLabel::kA || st == StateLabel::kB) {
    none_of({"--P_N"}, std::string("in state ") + std::string(to_string(st)) +
                           " (P_N = 0 there: the normal force enters only states c and d)");
    // Material parameters a user describes once and sweeps over states: accepted and echoed.
    for (const char* o : {"--k_a", "--P_s"})
      if (a.given(o) && mpi::rank() == 0)
        std::cerr << "cpkit map: note: " << o << " does not enter state " << to_string(st)
                  << " (P_N = 0 there, so no wear: kappa = k_a P_N / (3 P_s) enters states c "
                     "and d); accepted and echoed in the model\n";
  }
  if (st != StateLabel::kD) none_of({"--sgnPT"}, "outside state d (the sliding state)");
}

MapSetup build_setup(const MapArgs& a) {
  MapSetup s;
  if (!a.preset.empty()) {
    const auto p = find_map_preset(a.preset);
    if (!p) {
      std::string names;
      for (const auto& x : map_presets()) names += (names.empty() ? "" : ", ") + x.name;
      throw InputError("unknown preset '" + a.preset + "' (known: " + names + ")");
    }
    s.params = p->params;
    s.state = p->state;
    s.kind = p->kind;
    s.axis = p->axis;
    s.axis2 = p->axis2;
    s.have_axis = s.have_axis2 = true;
    s.theta_n = p->theta_n;
  }
  if (a.given("--kind")) {
    const auto k = map_kind_from_string(a.kind);
    if (!k) throw InputError("--kind must be direction, param-direction or param-param, got '" +
                             a.kind + "'");
    s.kind = *k;
  }
  if (a.given("--state")) {
    const auto l = state_from_string(a.state);
    if (!l) throw InputError("--state must be a, b, c or d, got '" + a.state + "'");
    s.state.label = *l;
  }
  if (a.given("--criterion")) {
    const auto c = criterion_from_string(a.criterion);
    if (!c)
      throw InputError("--criterion must be 38 (Coulomb, default) or 35 (softening), got '" +
                       a.criterion + "'");
    s.params.criterion = *c;
  }
  struct {
    const char* name;
    const double* value;
    double* target;
  } const fields[] = {{"--a11", &a.a11, &s.params.a11}, {"--a12", &a.a12, &s.params.a12},
                      {"--a22", &a.a22, &s.params.a22}, {"--mu", &a.mu, &s.params.mu},
                      {"--C_T", &a.C_T, &s.params.C_T}, {"--k_a", &a.k_a, &s.params.k_a},
                      {"--P_s", &a.P_s, &s.params.P_s}, {"--P_N", &a.P_N, &s.state.P_N}};
  for (const auto& f : fields)
    if (a.given(f.name)) {
      require_finite(*f.value, f.name + 2);
      *f.target = *f.value;
    }
  if (a.given("--sgnPT")) {
    if (a.sgnPT != 1 && a.sgnPT != -1) throw InputError("--sgnPT must be +1 or -1");
    s.state.sgn_PT = a.sgnPT;
  }
  check_options_have_effect(a, s);
  throw_if_invalid(s.params.validate(), "model parameters");
  throw_if_invalid(s.state.validate(s.params), "contact state");

  auto set_axis = [&](MapAxis& axis, bool& have, const std::string& name, const char* o_param,
                      const char* o_from, const char* o_to, const char* o_n, double from,
                      double to, int n) {
    if (a.given(o_param)) {
      const auto p = map_parameter_from_string(name);
      if (!p)
        throw InputError(std::string(o_param) + ": unknown parameter '" + name + "' (known: " +
                         map_parameter_names() + ")");
      if (!have || axis.param != *p) {
        if (!a.given(o_from) || !a.given(o_to))
          throw InputError(std::string(o_param) + " " + name + " needs " + o_from + " and " + o_to);
        axis.n = 200;
      }
      axis.param = *p;
      have = true;
    }
    if (a.given(o_from)) axis.from = from;
    if (a.given(o_to)) axis.to = to;
    if (a.given(o_n)) axis.n = n;
    if ((a.given(o_from) || a.given(o_to) || a.given(o_n)) && !have)
      throw InputError(std::string(o_from) + "/" + o_to + "/" + o_n + " need " + o_param);
    require_finite(axis.from, o_from + 2);
    require_finite(axis.to, o_to + 2);
  };
  set_axis(s.axis, s.have_axis, a.param, "--param", "--from", "--to", "--n", a.from, a.to, a.n);
  set_axis(s.axis2, s.have_axis2, a.param2, "--param2", "--from2", "--to2", "--n2", a.from2,
           a.to2, a.n2);
  if (a.given("--theta-n")) {
    // Only a param-direction map samples directions; a direction map computes its critical
    // directions exactly and a param-param map classifies each cell from its exact direction map.
    if (s.kind != MapKind::kParamDirection)
      throw InputError("--theta-n applies to --kind param-direction only (a " +
                       std::string(to_string(s.kind)) +
                       " map computes the critical directions exactly, without sampling)");
    s.theta_n = a.theta_n;
  }
  if (s.kind != MapKind::kDirection && !s.have_axis)
    throw InputError(std::string(to_string(s.kind)) + " map needs --param NAME --from X --to Y");
  if (s.kind == MapKind::kParamParam && !s.have_axis2)
    throw InputError("param-param map needs --param2 NAME --from2 X --to2 Y");
  // MapAxis::validate() names the fields n, from, to: here they are options.
  if (s.kind != MapKind::kDirection)
    throw_if_invalid_option(s.axis.validate(), {{"n", "--n"}, {"from", "--from"}, {"to", "--to"}});
  if (s.kind == MapKind::kParamParam)
    throw_if_invalid_option(s.axis2.validate(),
                            {{"n", "--n2"}, {"from", "--from2"}, {"to", "--to2"}});
  if (s.kind == MapKind::kParamDirection && (s.theta_n < 1 || s.theta_n > 1000000))
    throw InputError("--theta-n must be in [1, 1000000]");
  return s;
}

/// The model in one line; quantities that vary along a map axis are shown as "(axis)".
std::string model_text(const ContactParameters& p, const ContactState& s,
                       const std::vector<MapParameter>& axes = {}) {
  auto on_axis = [&](std::initializer_list<MapParameter> ps) {
    for (auto a : axes)
      for (auto q : ps)
        if (a == q) return true;
    return false;
  };
  auto v = [&](const char* name, double x, std::initializer_list<MapParameter> ps) {
    return std::string(name) + " = " + (on_axis(ps) ? std::string("(axis)") : fmt(x));
  };
  using P = MapParameter;
  std::string t = "state " + std::string(to_string(s.label)) + ", " +
                  v("a11", p.a11, {P::kA11}) + ", " + v("a12", p.a12, {P::kA12, P::kA12OverA11}) +
                  ", " + v("a22", p.a22, {P::kA22}) + ", " + v("mu", p.mu, {P::kMu}) + ", " +
                  v("C_T", p.C_T, {P::kCT});
  if (s.label == StateLabel::kC || s.label == StateLabel::kD)
    t += ", " + v("P_N", s.P_N, {P::kPN}) + ", " + v("k_a", p.k_a, {P::kKa, P::kKappa}) + ", " +
         v("P_s", p.P_s, {P::kPs}) + ", " +
         v("kappa", p.kappa(s.P_N), {P::kKappa, P::kKa, P::kPN, P::kPs}) +
         (s.label == StateLabel::kD ? ", sgn P_T = " + std::to_string(s.sgn_PT) : "");
  if (p.criterion == Criterion::kSoftening)
    t += ", criterion (35)" +
         std::string(s.label == StateLabel::kD ? " (mu_eff = mu - 2 kappa)" : "");
  return t;
}

void print_direction_text(const DirectionMap& m) {
  std::cout << "sectors (theta in rad from +dF_T towards +dF_N; open arcs):\n";
  for (const auto& s : m.sectors)
    std::cout << "  (" << std::fixed << std::setprecision(4) << s.theta_from << ", " << s.theta_to
              << ")" << std::defaultfloat << "  " << count_text(s.summary.count)
              << (s.summary.types ? ": " + types_text(s.summary.types) : "") << '\n';
  if (!m.critical.empty()) std::cout << "critical directions:\n";
  for (const auto& c : m.critical) {
    std::string cond;
    for (const auto& x : c.conditions) cond += (cond.empty() ? "" : ", ") + x;
    std::cout << "  " << std::fixed << std::setprecision(4) << c.theta << std::defaultfloat
              << " (" << cond << ")  " << count_text(c.summary.count)
              << (c.summary.types ? ": " + types_text(c.summary.types) : "") << '\n';
  }
  for (const auto& s : m.sectors)
    if (s.summary.count != 1)
      // An open interval: the sectors are open arcs, their end directions are critical and
      // have their own counts (listed above).
      std::cout << "summary: " << count_text(s.summary.count) << " for theta in (" << std::fixed
                << std::setprecision(2) << s.theta_from << ", " << s.theta_to << ")"
                << std::defaultfloat << '\n';
  for (const auto& c : m.critical)
    if (c.summary.count <= 0)
      std::cout << "summary: " << count_text(c.summary.count) << " at theta = " << std::fixed
                << std::setprecision(4) << c.theta << std::defaultfloat << '\n';
  bool all_unique = true;
  for (const auto& s : m.sectors) all_unique = all_unique && s.summary.count == 1;
  for (const auto& c : m.critical) all_unique = all_unique && c.summary.count == 1;
  if (all_unique) std::cout << "summary: exactly one solution for every direction\n";
}

void report_unreliable(int64_t n, const std::string& what) {
  if (n == 0) return;
  std::cerr << "cpkit map: " << n << ' ' << what
            << " where the enumeration met sign tests too close to call (their count may be "
               "wrong near a type boundary; 'unreliable' in the JSON)\n";
}

void report_disagreements(int64_t n, const std::string& what) {
  if (n == 0) return;
  std::cerr << "cpkit map: " << n << ' ' << what
            << " where the analytic and the enumeration routes disagree (see 'disagree' in the "
               "CSV / 'enumerate' in the JSON)\n";
}

/// Up-front cost of a grid map: time of the cell phase extrapolated from a small timed sample
/// of the same map (one thread), the memory it keeps, the size of what it writes.
struct GridEstimate {
  double cells = 0, seconds = 0, memory = 0, output = 0;
  int threads = 1;
};

GridEstimate estimate_grid_sampled(const MapSetup& s, const MapOptions& options, bool csv,
                                   bool writing);

int worker_threads(int requested, int rows) {
  int t = requested > 0 ? requested : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(t, rows));
}

GridEstimate estimate_grid(const MapSetup& s, const MapOptions& options, bool csv, bool writing) {
  try {
    return estimate_grid_sampled(s, options, csv, writing);
  } catch (const InputError&) {
    // A sampled row is not a valid model: the map itself reports the first invalid grid value.
    GridEstimate e;
    e.seconds = -1;
    return e;
  }
}

GridEstimate estimate_grid_sampled(const MapSetup& s, const MapOptions& options, bool csv,
                                   bool writing) {
  GridEstimate e;
  MapOptions one = options;
  one.threads = 1;
  const bool cross = options.method != RateMethod::kEnumerate;
  const double cross_bytes = cross ? 1 : 0;
  if (s.kind == MapKind::kParamDirection) {
    const double n = s.axis.n, tn = s.theta_n;
    e.cells = n * tn;
    e.threads = worker_threads(options.threads, s.axis.n);
    MapAxis sa = s.axis;
    sa.n = std::min(s.axis.n, 8);
    const int ts = std::min(s.theta_n, 1024);
    const std::vector<double> theta = map_theta_values(ts);
    std::ostringstream text;
    // Each sample is timed twice and the faster run kept (a busy machine inflates one run).
    double t1 = 1e300, t0 = 1e300;
    for (int rep = 0; rep < 2; ++rep) {
      const Stopwatch c1;
      compute_param_direction_map(s.params, s.state, sa, ts, one, {},
                                  [&](const ParamDirectionRows& r) {
                                    if (csv && rep == 0) write_csv_rows(sa, theta, r, text);
                                  });
      t1 = std::min(t1, c1.seconds());
      // The per-row part (critical directions, set-up): one direction per row.
      const Stopwatch c0;
      compute_param_direction_map(s.params, s.state, sa, 1, one, {}, [](const ParamDirectionRows&) {});
      t0 = std::min(t0, c0.seconds());
    }
    const double per_row = t0 / sa.n;
    const double per_cell = std::max(0.0, t1 - t0) / (sa.n * std::max(1, ts - 1));
    e.seconds = (n * per_row + e.cells * per_cell) / e.threads;
    const double block =
        std::min(n, std::max<double>(grid_block_rows(s.theta_n), 4 * e.threads)) * tn;
    e.memory = block * (3 + (csv ? 60 : 0)) + tn * (8 + 16 + (csv ? 40 : 0)) +
               n * (sizeof(ContactParameters) + sizeof(ContactState) + 100 +
                    8 * (sizeof(CriticalDirectionPoint) + 16));
    if (writing)
      e.output = csv ? e.cells * static_cast<double>(text.str().size()) / (sa.n * ts)
                     : e.cells * (2 + cross_bytes) + 8 * (n + tn) + 5 * 128;
    // The finished chunks stay in PREFIX.parts until the outputs are complete (map_chunks.hpp).
    if (writing) e.output += e.cells * (2 + cross_bytes);
  } else {
    const double n1 = s.axis.n, n2 = s.axis2.n;
    e.cells = n1 * n2;
    e.threads = worker_threads(options.threads, s.axis.n);
    MapAxis a1 = s.axis, a2 = s.axis2;
    a1.n = std::min(s.axis.n, 3);
    a2.n = std::min(s.axis2.n, 6);
    std::ostringstream text;
    double t = 1e300;
    for (int rep = 0; rep < 2; ++rep) {
      const Stopwatch c1;
      compute_param_param_map(s.params, s.state, a1, a2, one, {}, [&](const ParamParamRows& r) {
        if (csv && rep == 0) write_csv_rows(a1, a2, r, text);
      });
      t = std::min(t, c1.seconds());
    }
    e.seconds = t / (a1.n * a2.n) * e.cells / e.threads;
    const double block =
        std::min(n1, std::max<double>(grid_block_rows(s.axis2.n), 4 * e.threads)) * n2;
    e.memory = block * (5 + (csv ? 80 : 0)) + (n1 + n2) * (100 + 4 * sizeof(CriticalValue));
    if (writing)
      e.output = csv ? e.cells * static_cast<double>(text.str().size()) / (a1.n * a2.n)
                     : e.cells * (4 + cross_bytes) + 8 * (n1 + n2) + 7 * 128;
    if (writing) e.output += e.cells * (4 + cross_bytes);  // and the checkpoint's chunks
  }
  return e;
}

/// Refuses (exit 2) a grid map that cannot fit this machine's memory or the output's disk.
void check_grid_fits(const MapSetup& s, const GridEstimate& e, const std::string& out_dir,
                     bool csv, double time_limit, double max_output) {
  // Rank 0 decides for the job (an estimate differs between ranks); if it refuses, mpirun
  // ends the others.
  if (mpi::rank() != 0) return;
  const std::string cells =
      s.kind == MapKind::kParamDirection
          ? std::to_string(s.axis.n) + " x " + std::to_string(s.theta_n) + " cells (--n x --theta-n)"
          : std::to_string(s.axis.n) + " x " + std::to_string(s.axis2.n) + " cells (--n x --n2)";
  const std::string fewer =
      s.kind == MapKind::kParamDirection ? "use a smaller --n or --theta-n" : "use a smaller --n or --n2";
  if (e.seconds > time_limit)
    throw InputError("the map has " + cells + " and would need about " + fmt(e.seconds, 3) +
                     " s of computing on " + std::to_string(e.threads) +
                     " threads (estimated from a timed sample), more than --time-limit " +
                     fmt(time_limit) + ": " + fewer + ", or raise --time-limit");
  double limit = static_cast<double>(kMemoryLimitBytes);
  const double avail = available_memory_bytes();
  if (avail > 0) limit = std::min(limit, 0.8 * avail);
  if (e.memory > limit)
    throw InputError("the map has " + cells + " and would need about " + byte_text(e.memory) +
                     " of memory; " + byte_text(limit) + " is available: " + fewer);
  if (e.output > max_output)
    throw InputError("the map has " + cells + " and its output would take about " +
                     byte_text(e.output) + " (estimated), more than --max-output " +
                     byte_text(max_output) + ": " + fewer +
                     (csv ? ", drop --format csv (the .npy output takes 1-5 bytes per cell)" : "") +
                     ", or raise --max-output");
  if (e.output > 0) {
    const double free = free_disk_bytes(out_dir);
    if (free >= 0 && e.output > 0.95 * free)
      throw InputError("the map has " + cells + " and its output would take about " +
                       byte_text(e.output) + " but only " + byte_text(free) + " is free in '" +
                       (out_dir.empty() ? "." : out_dir) + "': " + fewer +
                       (csv ? ", or drop --format csv (the .npy output takes 1-5 bytes per cell)"
                            : ""));
  }
}

int run_map(const MapArgs& a) {
  if (a.list_presets) {
    for (const auto& p : map_presets())
      std::cout << p.name << " (" << to_string(p.kind) << "): " << p.description << '\n';
    return kExitOk;
  }
  // The system file is read once (a pipe can be read only once) and dispatched on its dim.
  std::optional<rate::SystemFile> file;
  if (a.given("--system")) file = rate::read_system_file(a.system);
  if (file && file->dim == 3) {
    Map3dRequest r;
    r.path = a.system;
    r.file = *file;
    r.kind = a.given("--kind") ? a.kind : "";
    r.out = a.out;
    r.param = a.param;
    r.param2 = a.param2;
    r.others = a.others;
    r.format = a.format;
    r.json = a.json;
    r.plot = a.plot;
    r.from = a.from;
    r.to = a.to;
    r.from2 = a.from2;
    r.to2 = a.to2;
    r.theta_from = a.theta_from;
    r.theta_to = a.theta_to;
    r.gamma = a.gamma;
    r.time_limit = a.time_limit;
    r.max_output = parse_byte_size(a.max_output, "--max-output");
    r.n = a.n;
    r.n2 = a.n2;
    r.theta_n = a.theta_n;
    r.threads = a.threads;
    r.facets = a.facets;
    r.point = a.point;
    for (const auto& [name, o] : a.opt)
      if (o->count() > 0) r.given.push_back(name);
    return run_map_system_3d(r);
  }
  for (const char* o : {"--facets", "--point", "--others", "--gamma"})
    if (a.given(o))
      throw InputError(std::string(o) + " applies to maps of 3-D systems (--system FILE with "
                       "\"dim\": 3)");
  if (a.given("--system")) {
    const std::string kind = a.given("--kind") ? a.kind : "direction";
    std::vector<std::string> allowed = {"--system", "--kind", "--out", "--json", "--threads"};
    const double max_output = parse_byte_size(a.max_output, "--max-output");
    std::vector<std::string> needed;
    if (kind == "param-direction")
      needed = {"--param", "--from", "--to"};
    else if (kind == "param-param")
      needed = {"--param", "--from", "--to", "--param2", "--from2", "--to2"};
    else if (kind != "direction")
      throw InputError("--kind with --system must be direction, param-direction or param-param, "
                       "got '" + kind + "'");
    allowed.insert(allowed.end(), needed.begin(), needed.end());
    if (kind != "direction")
      for (const char* o : {"--n", "--format", "--time-limit", "--max-output", "--resume"})
        allowed.push_back(o);
    if (kind == "param-direction")
      for (const char* o : {"--theta-n", "--theta-from", "--theta-to"}) allowed.push_back(o);
    if (kind == "param-param") allowed.push_back("--n2");
    std::string list;
    for (const auto& o : allowed) list += (list.empty() ? "" : ", ") + o;
    for (const auto& [name, o] : a.opt)
      if (o->count() > 0 && std::find(allowed.begin(), allowed.end(), name) == allowed.end())
        throw InputError(name + " does not apply with --system --kind " + kind +
                         " (the state, parameters and load patterns come from the system file; "
                         "options: " + list + (kind == "direction" ? "" : ", --plot") + ")");
    for (const auto& o : needed)
      if (!a.given(o)) throw InputError("--system --kind " + kind + " needs " + o);
    if (a.plot && kind == "direction")
      throw InputError("--plot with --system applies to --kind param-direction and param-param");
    if (a.plot && a.out.empty()) throw InputError("--plot needs --out PREFIX");
    if (a.resume && a.out.empty())
      throw InputError("--resume needs --out PREFIX (the finished chunks are kept in PREFIX.parts)");
    if (kind == "direction" && mpi::size() > 1)
      throw InputError("a direction map is one exact computation, not a grid of cells: run it "
                       "without mpirun (--threads uses the cores of one machine)");
    if (a.given("--format") && a.out.empty())
      throw InputError("--format needs --out PREFIX (without --out only the summary is printed)");
    if (a.format != "npy" && a.format != "csv")
      throw InputError("--format must be npy or csv, got '" + a.format + "'");
    if (!(a.time_limit > 0) || !std::isfinite(a.time_limit))
      throw InputError("--time-limit must be a positive number of seconds");
    if (a.threads < 0 || a.threads > 1024)
      throw InputError("--threads must be in [0, 1024] (0: all cores), got " +
                       std::to_string(a.threads));
    SystemMapRequest r;
    r.path = a.system;
    r.file = *file;
    r.kind = kind;
    r.out = a.out;
    r.json = a.json;
    r.plot = a.plot;
    r.resume = a.resume;
    r.format = a.format;
    r.threads = a.threads;
    r.time_limit = a.time_limit;
    r.max_output = max_output;
    r.param = a.param;
    r.from = a.from;
    r.to = a.to;
    r.param2 = a.param2;
    r.from2 = a.from2;
    r.to2 = a.to2;
    if (a.given("--n")) r.n = a.n;
    if (a.given("--n2")) r.n2 = a.n2;
    if (a.given("--theta-n")) r.theta_n = a.theta_n;
    r.theta_range = a.given("--theta-from") || a.given("--theta-to");
    if (a.given("--theta-from")) r.theta_from = a.theta_from;
    if (a.given("--theta-to")) r.theta_to = a.theta_to;
    std::unique_ptr<PrefixLock> lock;  // held until the map is written
    if (!r.out.empty()) lock = claim_map_prefix(r.out, {{"--system", r.path}});
    return run_map_system(r);
  }
  const MapSetup s = build_setup(a);
  const double max_output = parse_byte_size(a.max_output, "--max-output");
  if (s.kind == MapKind::kDirection && mpi::size() > 1)
    throw InputError("a direction map is one exact computation, not a grid of cells: run it "
                     "without mpirun");
  if (a.resume && (s.kind == MapKind::kDirection || a.out.empty()))
    throw InputError("--resume applies to grid maps written with --out PREFIX (the finished "
                     "chunks are kept in PREFIX.parts)");
  MapOptions options;
  const auto method = rate_method_from_string(a.method);
  if (!method) throw InputError("--method must be enumerate or analytic, got '" + a.method + "'");
  options.method = *method;
  if (a.threads > 1024)
    throw InputError("--threads must be at most 1024 (0: all cores), got " +
                     std::to_string(a.threads));
  options.threads = a.threads;
  // Zoom on a thin band of directions (sampled directions of a param-direction map only).
  for (const char* o : {"--theta-from", "--theta-to"})
    if (a.given(o) && s.kind != MapKind::kParamDirection)
      throw InputError(std::string(o) + " applies to --kind param-direction only (a " +
                       std::string(to_string(s.kind)) +
                       " map computes the critical directions exactly, without sampling)");
  if (a.given("--theta-from")) options.theta_from = a.theta_from;
  if (a.given("--theta-to")) options.theta_to = a.theta_to;
  throw_if_invalid_option(options.validate(), {{"theta_from", "--theta-from"},
                                               {"theta_to", "--theta-to"},
                                               {"threads", "--threads"}});
  if (a.plot && a.out.empty()) throw InputError("--plot needs --out PREFIX");
  if (a.format != "npy" && a.format != "csv")
    throw InputError("--format must be npy or csv, got '" + a.format + "'");
  if (a.given("--format") && s.kind == MapKind::kDirection && a.format != "csv")
    throw InputError("--format npy applies to the grid maps (param-direction, param-param); a "
                     "direction map is written as CSV and JSON");
  if (a.given("--format") && a.out.empty())
    throw InputError("--format needs --out PREFIX (without --out only the summary is printed)");
  const bool csv = a.format == "csv";
  if (!(a.time_limit > 0) || !std::isfinite(a.time_limit))
    throw InputError("--time-limit must be a positive number of seconds");
  std::unique_ptr<PrefixLock> lock;  // held until the map is written
  if (!a.out.empty()) lock = claim_map_prefix(a.out, {});

  nlohmann::json j;
  j["kind"] = std::string(to_string(s.kind));
  if (!a.preset.empty()) j["preset"] = a.preset;
  j["cpkit_version"] = CPKIT_VERSION;
  j["method"] = a.method;
  j["run"] = run_echo();
  j["model"] = model_to_json(s.params, s.state);
  nlohmann::json files = nlohmann::json::object();
  const std::string prefix = a.out;
  const std::string name = prefix.empty() ? "" : fs::path(prefix).filename().string();
  int64_t disagreements = 0;
  const Stopwatch clock;
  std::function<void()> print_text;

  if (s.kind == MapKind::kDirection) {
    const DirectionMap m = compute_direction_map(s.params, s.state, options);
    j.update(to_json(m));
    j["seconds"] = clock.seconds();
    disagreements = m.disagreements;
    report_disagreements(m.disagreements, "directions");
    report_unreliable(m.unreliable, "evaluations");
    if (m.inconsistent_sectors > 0)
      std::cerr << "cpkit map: " << m.inconsistent_sectors
                << " sectors are not uniform (a missed critical direction?)\n";
    if (!prefix.empty()) {
      write_text_file(prefix + ".csv", [&](std::ostream& o) { write_csv(m, o); });
      files["csv"] = name + ".csv";
    }
    print_text = [m, &s] {
      std::cout << "direction map, " << model_text(s.params, s.state) << '\n';
      print_direction_text(m);
    };
  } else {
    // Grid maps: estimate, refuse what cannot fit, then stream the cells to the files.
    GridEstimate est = estimate_grid(s, options, csv, !prefix.empty());
    est.seconds /= mpi::size();  // the ranks share the cells
    check_grid_fits(s, est, prefix.empty() ? "" : fs::path(prefix).parent_path().string(), csv,
                    a.time_limit, max_output);
    // Every grid value next (cheaper than a cell; after the refusals, which need no pass over
    // the grid): the first invalid one is named before any cell is computed, whichever rank
    // or chunk would meet it first.
    validate_map_grid(s.params, s.state, s.axis,
                      s.kind == MapKind::kParamParam ? &s.axis2 : nullptr);
    j["estimate"] = {{"seconds", est.seconds}, {"memory_bytes", est.memory},
                     {"output_bytes", est.output}, {"threads", est.threads}};
    if (est.seconds > 1.0 || est.output > 1e9)
      std::cerr << "cpkit map: " << fmt(est.cells, 3) << " cells: about " << fmt(est.seconds, 2)
                << " s of cells on " << est.threads << " threads, " << byte_text(est.memory)
                << " of memory"
                << (prefix.empty() ? std::string()
                                   : ", " + byte_text(est.output) + " of output (" + a.format + ")")
                << '\n';
    j["format"] = a.format;
    nlohmann::json bits = nlohmann::json::object();
    for (unsigned b = 0; b < 8; ++b)
      if (types_to_string(1u << b) != "none") bits[types_to_string(1u << b)] = 1u << b;
    j["type_bits"] = bits;
    const bool cross = options.method != RateMethod::kEnumerate;
    GridFiles out(prefix, files);
    auto axis_values = [](const MapAxis& ax) {
      std::vector<double> v(static_cast<std::size_t>(ax.n));
      for (int i = 0; i < ax.n; ++i) v[i] = ax.value(i);
      return v;
    };

    // The rows are computed in chunks (map_chunks.hpp): spread over the ranks of an MPI job,
    // kept in PREFIX.parts for --resume, consumed in row order; the outputs are those of one
    // pass over the map.
    nlohmann::json manifest = {{"cpkit_version", CPKIT_VERSION}, {"kind", j["kind"]},
                               {"model", j["model"]}, {"method", a.method}, {"format", a.format},
                               {"axis", {{"param", to_string(s.axis.param)}, {"from", s.axis.from},
                                         {"to", s.axis.to}, {"n", s.axis.n}}}};
    ChunkRunStats stats;
    if (s.kind == MapKind::kParamDirection) {
      const std::vector<double> theta =
          map_theta_values(s.theta_n, options.theta_from, options.theta_to);
      manifest["theta"] = {{"n", s.theta_n}, {"from", options.theta_from}, {"to", options.theta_to}};
      // Rank 0 alone writes: the files are opened when the first chunk arrives.
      bool opened = false;
      auto open_files = [&] {
        if (!prefix.empty() && !csv) {
          out.add_npy("count", "|i1", s.axis.n, s.theta_n);
          out.add_npy("types", "|u1", s.axis.n, s.theta_n);
          if (cross) out.add_npy("disagree", "|u1", s.axis.n, s.theta_n);
          out.write_vector("x", axis_values(s.axis));
          out.write_vector("theta", theta);
        } else if (!prefix.empty()) {
          write_csv_header(s.axis, cross, out.open_csv());
        }
        opened = true;
      };
      const ChunkPlan plan = plan_chunks(s.axis.n, s.theta_n);
      auto compute = [&](int k) {
        MapChunk c;
        c.index = k;
        c.row_begin = plan.begin(k);
        c.row_end = plan.end(k);
        std::string cnt, typ, dis;
        const ParamDirectionMap part = compute_param_direction_map(
            s.params, s.state, s.axis, s.theta_n, options, {},
            [&](const ParamDirectionRows& r) {
              const std::size_t cells = static_cast<std::size_t>(r.row_end - r.row_begin) *
                                        static_cast<std::size_t>(s.theta_n);
              cnt.append(reinterpret_cast<const char*>(r.count), cells);
              typ.append(reinterpret_cast<const char*>(r.types), cells);
              if (r.disagree) dis.append(reinterpret_cast<const char*>(r.disagree), cells);
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
      // The whole map's summary, merged from the chunks in row order.
      ParamDirectionMap m;
      m.axis = s.axis;
      m.theta_n = s.theta_n;
      m.theta_from = options.theta_from;
      m.theta_to = options.theta_to;
      m.theta = theta;
      m.cross_checked = cross;
      m.threads = worker_threads(options.threads, s.axis.n);
      std::map<int, GridClassBox> boxes;
      std::vector<std::pair<int, int>> shown;  // the first disagreeing cells (for stderr)
      auto consume = [&](const MapChunk& c) {
        if (!opened) open_files();
        const std::size_t cells = static_cast<std::size_t>(c.row_end - c.row_begin) *
                                  static_cast<std::size_t>(s.theta_n);
        if (c.arrays.size() != (cross ? 3u : 2u))
          throw InputError("corrupt map chunk " + std::to_string(c.index));
        for (const auto& arr : c.arrays)
          if (arr.size() != cells) throw InputError("corrupt map chunk " + std::to_string(c.index));
        ParamDirectionRows r;
        r.row_begin = c.row_begin;
        r.row_end = c.row_end;
        r.count = reinterpret_cast<const int8_t*>(c.arrays[0].data());
        r.types = reinterpret_cast<const uint8_t*>(c.arrays[1].data());
        r.disagree = cross ? reinterpret_cast<const uint8_t*>(c.arrays[2].data()) : nullptr;
        out.append({r.count, r.types, r.disagree}, static_cast<int64_t>(cells));
        if (out.has_csv()) write_csv_rows(s.axis, theta, r, out.csv());
        for (std::size_t k = 0; r.disagree && k < cells && shown.size() < 10; ++k)
          if (r.disagree[k])
            shown.emplace_back(r.row_begin + static_cast<int>(k / s.theta_n),
                               static_cast<int>(k % s.theta_n));
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
      try {
        stats = run_map_chunks(prefix, a.resume, manifest, plan, compute, consume,
                               make_map_progress());
        if (mpi::rank() != 0) return kExitOk;  // rank 0 writes and prints
        out.finish();
      } catch (...) {
        out.discard();
        throw;
      }
      for (const auto& [code, b] : boxes) m.classes.push_back(b);
      m.seconds = clock.seconds();
      j.update(to_json(m));
      add_run_figures(j, stats);
      disagreements = m.disagreements;
      report_disagreements(m.disagreements, "cells");
      report_unreliable(m.unreliable, "cells");
      for (const auto& [i, k] : shown)
        std::cerr << "  " << to_string(m.axis.param) << " = " << m.axis.value(i)
                  << ", theta = " << m.theta[k] << '\n';
      if (!prefix.empty()) {
        write_text_file(prefix + "_critical.csv", [&](std::ostream& o) { write_critical_csv(m, o); });
        files["critical_csv"] = name + "_critical.csv";
      }
      const nlohmann::json summary = j;
      print_text = [summary, &s, &a] {
        const auto& ax = summary["axis"];
        std::cout << "param-direction map, " << model_text(s.params, s.state, {s.axis.param})
                  << "\n  "
                  << ax["param"].get<std::string>() << " in [" << fmt(ax["from"].get<double>())
                  << ", " << fmt(ax["to"].get<double>()) << "] x theta in "
                  << (a.given("--theta-from") || a.given("--theta-to")
                          ? "[" + fmt(summary["theta_from"].get<double>()) + ", " +
                                fmt(summary["theta_to"].get<double>()) + "]: "
                          : std::string("[0, 2 pi): "))
                  << summary["cells"] << " cells, " << fmt(summary["seconds"].get<double>(), 3)
                  << " s, " << summary["threads"] << " threads\n";
        for (const auto& c : summary["classes"]) {
          const int count = c["count"].is_string() ? -1 : c["count"].get<int>();
          std::cout << "  " << count_text(count) << ": " << c["cells"] << " cells, "
                    << ax["param"].get<std::string>() << " in [" << fmt(c["x_min"].get<double>())
                    << ", " << fmt(c["x_max"].get<double>()) << "], theta in ["
                    << fmt(c["theta_min"].get<double>(), 3) << ", "
                    << fmt(c["theta_max"].get<double>(), 3) << "]\n";
        }
        for (const auto& c : summary["critical_values"])
          std::cout << "  critical: " << c["name"].get<std::string>() << " at "
                    << ax["param"].get<std::string>() << " = " << fmt(c["x"].get<double>(), 10)
                    << '\n';
      };
    } else {
      if (!prefix.empty() && !csv)
        j["class_codes"] = {{"unique", 0}, {"non-unique", 1}, {"no-solution", 2},
                            {"none-and-several", 3}};
      bool opened = false;  // rank 0 alone writes, from the first chunk on
      auto open_files = [&] {
        if (!prefix.empty() && !csv) {
          out.add_npy("class", "|u1", s.axis.n, s.axis2.n);
          out.add_npy("min_count", "|i1", s.axis.n, s.axis2.n);
          out.add_npy("max_count", "|i1", s.axis.n, s.axis2.n);
          out.add_npy("types", "|u1", s.axis.n, s.axis2.n);
          if (cross) out.add_npy("disagree", "|u1", s.axis.n, s.axis2.n);
          out.write_vector("x", axis_values(s.axis));
          out.write_vector("y", axis_values(s.axis2));
        } else if (!prefix.empty()) {
          write_csv_header(s.axis, s.axis2, cross, out.open_csv());
        }
        opened = true;
      };
      manifest["axis2"] = {{"param", to_string(s.axis2.param)}, {"from", s.axis2.from},
                           {"to", s.axis2.to}, {"n", s.axis2.n}};
      const ChunkPlan plan = plan_chunks(s.axis.n, s.axis2.n);
      auto compute = [&](int k) {
        MapChunk c;
        c.index = k;
        c.row_begin = plan.begin(k);
        c.row_end = plan.end(k);
        std::string cls, lo, hi, typ, dis;
        const ParamParamMap part = compute_param_param_map(
            s.params, s.state, s.axis, s.axis2, options, {},
            [&](const ParamParamRows& r) {
              const std::size_t cells = static_cast<std::size_t>(r.row_end - r.row_begin) *
                                        static_cast<std::size_t>(s.axis2.n);
              cls.append(reinterpret_cast<const char*>(r.cls), cells);
              lo.append(reinterpret_cast<const char*>(r.min_count), cells);
              hi.append(reinterpret_cast<const char*>(r.max_count), cells);
              typ.append(reinterpret_cast<const char*>(r.types), cells);
              if (r.disagree) dis.append(reinterpret_cast<const char*>(r.disagree), cells);
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
      ParamParamMap m;
      m.axis1 = s.axis;
      m.axis2 = s.axis2;
      m.cross_checked = cross;
      m.threads = worker_threads(options.threads, s.axis.n);
      std::map<int, GridClassBox> boxes;
      auto consume = [&](const MapChunk& c) {
        if (!opened) open_files();
        const std::size_t cells = static_cast<std::size_t>(c.row_end - c.row_begin) *
                                  static_cast<std::size_t>(s.axis2.n);
        if (c.arrays.size() != (cross ? 5u : 4u))
          throw InputError("corrupt map chunk " + std::to_string(c.index));
        for (const auto& arr : c.arrays)
          if (arr.size() != cells) throw InputError("corrupt map chunk " + std::to_string(c.index));
        ParamParamRows r;
        r.row_begin = c.row_begin;
        r.row_end = c.row_end;
        r.cls = reinterpret_cast<const uint8_t*>(c.arrays[0].data());
        r.min_count = reinterpret_cast<const int8_t*>(c.arrays[1].data());
        r.max_count = reinterpret_cast<const int8_t*>(c.arrays[2].data());
        r.types = reinterpret_cast<const uint8_t*>(c.arrays[3].data());
        r.disagree = cross ? reinterpret_cast<const uint8_t*>(c.arrays[4].data()) : nullptr;
        out.append({r.cls, r.min_count, r.max_count, r.types, r.disagree},
                   static_cast<int64_t>(cells));
        if (out.has_csv()) write_csv_rows(s.axis, s.axis2, r, out.csv());
        const nlohmann::json& sum = c.summary;
        merge_boxes(boxes, sum.at("boxes"));
        m.disagreements += sum.at("disagreements").get<int64_t>();
        m.inconsistent_sectors += sum.at("inconsistent_sectors").get<int64_t>();
        m.unreliable += sum.at("unreliable").get<int64_t>();
        for (const auto& v : sum.at("critical_curve"))
          m.critical_curve.push_back(
              {v.at(0).get<std::string>(), v.at(1).get<double>(), v.at(2).get<double>()});
      };
      try {
        stats = run_map_chunks(prefix, a.resume, manifest, plan, compute, consume,
                               make_map_progress());
        if (mpi::rank() != 0) return kExitOk;
        out.finish();
      } catch (...) {
        out.discard();
        throw;
      }
      for (const auto& [code, b] : boxes) m.classes.push_back(b);
      m.seconds = clock.seconds();
      j.update(to_json(m));
      add_run_figures(j, stats);
      disagreements = m.disagreements;
      report_disagreements(m.disagreements, "cells");
      report_unreliable(m.unreliable, "direction-map evaluations");
      if (!prefix.empty()) {
        write_text_file(prefix + "_critical.csv", [&](std::ostream& o) { write_critical_csv(m, o); });
        files["critical_csv"] = name + "_critical.csv";
      }
      const nlohmann::json summary = j;
      print_text = [summary, &s] {
        const auto& ax = summary["axis"];
        const auto& ay = summary["axis2"];
        std::cout << "param-param map, "
                  << model_text(s.params, s.state, {s.axis.param, s.axis2.param}) << "\n  "
                  << ax["param"].get<std::string>() << " x " << ay["param"].get<std::string>()
                  << ": " << summary["cells"] << " cells, "
                  << fmt(summary["seconds"].get<double>(), 3) << " s\n";
        for (const auto& c : summary["classes"])
          std::cout << "  " << c["class"].get<std::string>() << ": " << c["cells"] << " cells, "
                    << ax["param"].get<std::string>() << " in [" << fmt(c["x_min"].get<double>())
                    << ", " << fmt(c["x_max"].get<double>()) << "], "
                    << ay["param"].get<std::string>() << " in [" << fmt(c["y_min"].get<double>())
                    << ", " << fmt(c["y_max"].get<double>()) << "]\n";
      };
    }
  }

  bool plot_failed = false;
  if (!prefix.empty()) {
    files["json"] = name + ".json";
    j["files"] = files;
    write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
    if (a.plot) {
      plot_failed = !run_map_plot(prefix, files);
      j["files"] = files;
      write_text_file(prefix + ".json", [&](std::ostream& o) { o << json_text(j) << '\n'; });
    }
    // The outputs are complete: the finished chunks kept for --resume are no longer needed.
    if (s.kind != MapKind::kDirection) remove_checkpoint(prefix + ".parts");
  }
  if (a.json) {
    print_json(j);
  } else {
    print_text();
    if (!prefix.empty()) {
      std::cout << "wrote";
      for (const auto& [k, v] : files.items()) std::cout << ' ' << (fs::path(prefix).parent_path() / v.get<std::string>()).string();
      std::cout << '\n';
    }
  }
  if (disagreements > 0) return kExitDisagreement;
  return plot_failed ? kExitInternal : kExitOk;  // the picture was asked for and is missing
}

}  // namespace

void add_map_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<MapArgs>();
  auto* cmd = app.add_subcommand(
      "map", "Non-existence / non-uniqueness maps of the rate problem over load directions and "
             "parameters (docs/maps.md)");
  auto& o = args->opt;
  o["--preset"] = cmd->add_option("--preset", args->preset,
                                  "fig5a, fig5b, state-d, state-d-mu-kappa (--list-presets)");
  cmd->add_flag("--list-presets", args->list_presets, "list the presets and exit");
  o["--kind"] = cmd->add_option("--kind", args->kind, "direction | param-direction | param-param | sphere (3-D systems)");
  o["--state"] = cmd->add_option("--state", args->state, "contact state a|b|c|d (default b)");
  o["--a11"] = cmd->add_option("--a11", args->a11, "stiffness a11 (or the preset's)")->default_str("");
  o["--a12"] = cmd->add_option("--a12", args->a12, "stiffness a12 (or the preset's)")->default_str("");
  o["--a22"] = cmd->add_option("--a22", args->a22, "stiffness a22 (or the preset's)")->default_str("");
  o["--mu"] = cmd->add_option("--mu", args->mu, "friction coefficient (or the preset's)")
                   ->default_str("");
  o["--C_T"] = cmd->add_option("--C_T", args->C_T, "tangential compliance (with --preset: the preset's)");
  o["--k_a"] = cmd->add_option("--k_a", args->k_a, "Archard wear coefficient (with --preset: the preset's)");
  o["--P_s"] = cmd->add_option("--P_s", args->P_s, "hardness (with --preset: the preset's)");
  o["--P_N"] = cmd->add_option("--P_N", args->P_N, "normal force (states c, d; with --preset: the preset's)")
                    ->default_str("");
  o["--sgnPT"] = cmd->add_option("--sgnPT", args->sgnPT, "sign of P_T in state d (+1/-1)");
  o["--criterion"] = cmd->add_option("--criterion", args->criterion,
                                     "friction-and-wear criterion: 38 (Coulomb, default) or 35 "
                                     "(softening; state d uses mu_eff = mu - 2 kappa)");
  o["--param"] = cmd->add_option("--param", args->param,
                                 "first axis: mu, a11, a12, a22, a12/a11, C_T, k_a, P_s, P_N, kappa");
  o["--from"] = cmd->add_option("--from", args->from, "first axis start")->default_str("");
  o["--to"] = cmd->add_option("--to", args->to, "first axis end")->default_str("");
  o["--n"] = cmd->add_option("--n", args->n,
                             "first axis values (default 200, with --preset the preset's; "
                             "--system: 100; 3-D --kind sphere: 91 elevations)")
                 ->default_str("");
  o["--param2"] = cmd->add_option("--param2", args->param2, "second axis (param-param)");
  o["--from2"] = cmd->add_option("--from2", args->from2, "second axis start")->default_str("");
  o["--to2"] = cmd->add_option("--to2", args->to2, "second axis end")->default_str("");
  o["--n2"] = cmd->add_option("--n2", args->n2,
                              "second axis values (default 200, with --preset the preset's; "
                              "--system: 100; 3-D --kind sphere: 180 azimuths)")
                  ->default_str("");
  o["--theta-n"] = cmd->add_option("--theta-n", args->theta_n,
                                   "directions of a param-direction map (rejected for the "
                                   "other kinds)");
  o["--theta-from"] = cmd->add_option("--theta-from", args->theta_from,
                                      "param-direction: first direction sampled, rad");
  o["--theta-to"] = cmd->add_option("--theta-to", args->theta_to,
                                    "param-direction: last direction sampled, rad (default 2 pi; "
                                    "at most --theta-from + 2 pi)")
                        ->default_str("");
  o["--method"] = cmd->add_option("--method", args->method,
                                  "enumerate | analytic (also cross-checks with enumerate)");
  o["--threads"] = cmd->add_option("--threads", args->threads, "worker threads (0: all cores)");
  o["--out"] = cmd->add_option("--out", args->out,
                               "write PREFIX.json and the cells: grid maps PREFIX_<array>.npy "
                               "(or PREFIX.csv with --format csv) + PREFIX_critical.csv; "
                               "direction maps PREFIX.csv");
  o["--time-limit"] = cmd->add_option(
      "--time-limit", args->time_limit,
      "grid maps: refuse up front when the estimated time of the cells exceeds this many "
      "seconds");
  o["--max-output"] = cmd->add_option(
      "--max-output", args->max_output,
      "grid maps written with --out: refuse up front when the estimated output exceeds SIZE "
      "bytes (suffix K, M, G, T: powers of 1024; e.g. 500M, 10G)")
                             ->type_name("SIZE");
  o["--format"] = cmd->add_option("--format", args->format,
                                  "cells of a grid map: npy (numpy arrays of codes + axis "
                                  "vectors) | csv (one line per cell)");
  o["--system"] = cmd->add_option("--system", args->system,
                                  "N-point system file (docs/file_formats.md): maps of "
                                  "dF = cos(theta) e1 + sin(theta) e2; --kind direction (default), "
                                  "param-direction, param-param; --param mu, C_T, k_a, P_N, "
                                  "coupling or mu@i, ...");
  o["--facets"] = cmd->add_option("--facets", args->facets,
                                  "3-D systems: the faceted route with K facets (3..64; required "
                                  "for N > 1 points; default for one point: exact)")
                        ->default_str("");
  o["--point"] = cmd->add_option("--point", args->point,
                                 "3-D systems: the loaded point of --kind sphere/param-direction "
                                 "and the point whose types are mapped (1..N)");
  o["--others"] = cmd->add_option("--others", args->others,
                                  "3-D systems, N > 1: the other points' load rates, zero "
                                  "or file (the file's dF; default: file when the file has a "
                                  "dF, else zero)");
  o["--gamma"] = cmd->add_option("--gamma", args->gamma,
                                 "3-D param-direction: azimuth G of the meridian plane of load "
                                 "directions, dF = (cos t cos G, cos t sin G, sin t)");
  cmd->add_flag("--plot", args->plot, "also draw PREFIX.png and PREFIX.svg (needs --out, matplotlib)");
  cmd->add_flag("--json", args->json, "print the JSON summary on stdout");
  o["--resume"] = cmd->add_flag("--resume", args->resume,
                                "N-point grid maps: continue an interrupted map from the chunks "
                                "finished in PREFIX.parts (same map, same --out)");
  cmd->callback([args, &ctx] { ctx.exit_code = run_map(*args); });
}

}  // namespace cpkit::cli
