// `cpkit rate`'s request: the option checks (with the messages the program has always printed),
// the three routes (one point, N points, a 3-D system) and the exit code.
#include "cpkit/rate_problem/requests/rate_request.hpp"

#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"
#include "../model/options_given.hpp"

namespace cpkit::rate {

namespace {

using detail::option;
using detail::Given;
using Note = std::function<void(const std::string&)>;

/// The options a one-point problem needs besides --dF (with --system they come from the file).
std::vector<Given> one_point_options(const RateRequest& a) {
  const ModelOptions& m = a.model;
  return {option("--state", a.state), option("--a11", m.a11), option("--a12", m.a12),
          option("--a22", m.a22), option("--mu", m.mu)};
}

/// How a system's load rate is described in messages (2-D and 3-D differ).
struct LoadRateWords {
  const char* layout;       ///< the order of the numbers
  const char* points;       ///< "points" or "point(s)"
  const char* none_suffix;  ///< appended to "2N numbers" when there is no load rate
};

/// The load rate of an N-point system: --dF (per_point x N numbers) or else the file's "dF".
Eigen::VectorXd system_load_rate(const std::vector<double>& arg,
                                 const std::optional<Eigen::VectorXd>& from_file, int per_point,
                                 int N, const std::string& path, const LoadRateWords& words) {
  const std::string n = std::to_string(per_point);
  if (arg.empty()) {
    if (from_file) return *from_file;
    throw InputError("no load rate: give --dF (" + n + "N numbers" + words.none_suffix +
                     ") or \"dF\" in " + path);
  }
  if (static_cast<int>(arg.size()) != per_point * N)
    throw InputError("--dF needs " + n + "N = " + std::to_string(per_point * N) + " numbers (" +
                     words.layout + ") for the " + std::to_string(N) + " " + words.points +
                     " of " + path + ", got " + std::to_string(arg.size()));
  return Eigen::Map<const Eigen::VectorXd>(arg.data(), per_point * N);
}

/// Options that would have no effect in the chosen state are errors, never silence; material
/// parameters a user describes once and sweeps over states are accepted with a note (issue 27).
void check_state_options(const RateRequest& a, const Note& note) {
  const std::string st = a.state.value_or("");
  if (st != "d" && a.sgn_PT)
    throw InputError("--sgnPT has no effect in state " + st + ": only state d (sliding) has a "
                     "sign of P_T");
  if (st == "a" || st == "b")
    for (const Given& o : {option("--k_a", a.model.k_a), option("--P_s", a.model.P_s)})
      if (o.given && note)
        note(std::string("note: ") + o.name + " does not enter state " + st +
             " (P_N = 0 there, so no wear: kappa = k_a P_N / (3 P_s) enters states c "
             "and d); accepted and echoed");
}

void run_system_3d(const RateRequest& a, const SystemFile& file, RateOutcome& out) {
  if (a.time_limit && !(*a.time_limit > 0 && *a.time_limit <= 1e9))
    throw InputError("--time-limit must be a positive number of seconds (at most 1e9), got " +
                     num_text(*a.time_limit));
  if (a.time_limit && a.facets == 0)
    throw InputError("--time-limit applies with --facets K (the faceted enumeration); the exact "
                     "one-point route is solved in bounded time");
  // One budget for the whole solve (every separation case of the N-point problem).
  const double time_limit = a.time_limit.value_or(60.0);
  const std::string& path = file.source;
  const ContactSystem3d sys = parse_contact_system_3d(file);
  const int N = sys.n_points();
  if (a.method != "enumerate")
    throw InputError("--method " + a.method + " is not available for 3-D points: the solution set "
                     "is computed exactly (or with --facets K as a faceted LCP by enumeration)");
  if (N > 1 && a.facets == 0)
    throw InputError(path + ": " + std::to_string(N) + " coupled 3-D points are solved with the "
                     "faceted friction ellipses: give --facets K (e.g. 16; docs/contact_3d.md)");
  out.dF = system_load_rate(a.dF, sys.dF, 3, N, path,
                            {"T_X T_Y N per point", "point(s)", ": T_X T_Y N per point"});
  if (N == 1 && a.facets != 0 && sys.points[0].state.state != 'b')
    throw InputError(std::string("--facets applies to state b (grazing); state ") +
                     sys.points[0].state.state +
                     " has a linear rate problem, solved exactly without it");
  out.route = RateOutcome::Route::kSystem3d;
  out.path = path;
  out.name = sys.name;
  out.n_points = N;
  out.facets = a.facets;
  out.first_state = sys.points[0].state.state;
  const SystemRateRoute3d& s =
      *(out.system_3d = solve_system_rate_3d(sys, out.dF, a.facets, time_limit));
  out.exit_code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  if (!s.complete) {
    out.notes.push_back("not proved complete: " + s.message);
    out.exit_code = kExitInconclusive;
  }
}

void run_system(const RateRequest& a, RateOutcome& out) {
  const std::string& path = a.system;
  out.path = path;
  // read once (a pipe can be read only once), then by its dimension; or given already read
  const SystemFile file = a.file ? *a.file : read_system_file(path);
  if (file.dim == 3) return run_system_3d(a, file, out);
  if (a.time_limit)
    throw InputError("--time-limit applies to the faceted 3-D rate problems (\"dim\": 3 and "
                     "--facets K); " + path + " is a 2-D system");
  if (a.facets != 0)
    throw InputError("--facets applies to 3-D points (\"dim\": 3 in the system file, "
                     "docs/contact_3d.md); " + path + " is a 2-D system");
  const ContactSystem sys = parse_contact_system(file);
  const int N = sys.n_points();
  out.dF = system_load_rate(a.dF, sys.dF, 2, N, path, {"T_1 N_1 T_2 N_2 ...", "points", ""});
  const auto method = rate_method_from_string(a.method);
  if (!method || *method == RateMethod::kAnalytic)
    throw InputError("--method with --system must be enumerate, lemke, fb-newton or ipopt, got '" +
                     a.method + "'");
  // A limit that depends on N and the states, checked before the N^3 precomputation (a
  // 1000-point system was refused only after minutes; issue 24, item 12).
  if (const int m = system_map_lcp_size(sys);
      *method == RateMethod::kEnumerate && m > lcp::kMaxEnumerationSize)
    throw InputError(path + ": the rate LCP has size " + std::to_string(m) +
                     " (3 per point in state b, 1 per point in state d); the complete "
                     "enumeration takes at most " + std::to_string(lcp::kMaxEnumerationSize) +
                     " (--method lemke, fb-newton or ipopt find one verified solution)");
  out.route = RateOutcome::Route::kSystem;
  out.name = sys.name;
  out.n_points = N;
  const SystemRateSolutionSet& s = *(out.system = solve_rate_problem(sys, out.dF, *method));
  const bool single = *method != RateMethod::kEnumerate;
  out.exit_code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  if (single && s.disagreement) {
    out.notes.push_back(a.method + "'s solution is not in the enumerated solution set");
    out.exit_code = kExitDisagreement;
  } else if (!single && !s.complete) {
    out.notes.push_back("the enumeration is not conclusive: " + s.message);
    out.exit_code = kExitInconclusive;
  }
}

void run_one_point(const RateRequest& a, RateOutcome& out, const Note& note) {
  if (a.time_limit)
    throw InputError("--time-limit applies to the faceted 3-D rate problems (--system FILE "
                     "with \"dim\": 3 and --facets K); the one-point 2-D problem is solved in "
                     "bounded time");
  if (a.facets != 0)
    throw InputError("--facets applies to 3-D points (--system FILE with \"dim\": 3, "
                     "docs/contact_3d.md)");
  std::vector<Given> required = one_point_options(a);
  required.push_back({"--dF", !a.dF.empty()});
  detail::require_given(required, " is required (or give --system FILE)");
  // the criterion's name, then the values (as the program has always checked them)
  const ContactParameters p = model_parameters(a.model);
  ContactState st;
  const auto label = state_from_string(*a.state);
  if (!label) throw InputError("--state must be a, b, c or d, got '" + *a.state + "'");
  st.label = *label;
  st.P_N = a.P_N;
  st.sgn_PT = a.sgn_PT.value_or(1);
  throw_if_invalid(st.validate(p), "contact state");
  if (a.dF.size() != 2) throw InputError("--dF needs two values: DFT DFN");
  const LoadRate f{a.dF[0], a.dF[1]};
  const auto method = rate_method_from_string(a.method);
  if (!method)
    throw InputError("--method must be enumerate, analytic, lemke, fb-newton or ipopt, got '" +
                     a.method + "'");
  const CheckedRateSolution& checked =
      *(out.one_point = solve_rate_problem_checked(p, st, f, *method));
  const RateSolutionSet& s = checked.set;
  out.exit_code = s.solutions.empty() ? kExitNoSolution : kExitOk;
  // a single solver that found nothing: said before the result is printed (as always)
  if (checked.reference && s.solutions.empty() && note)
    note(s.message + "; the enumeration has " +
         (checked.reference->count() < 0 ? std::string("infinitely many")
                                         : std::to_string(checked.reference->count())) +
         " solution(s)");
  if (!checked.problem.empty()) {
    out.notes.push_back(checked.problem);
    out.exit_code = checked.inconclusive ? kExitInconclusive : kExitDisagreement;
  }
}

}  // namespace

RateOutcome run_rate_request(const RateRequest& a, const Note& note) {
  check_state_options(a, note);
  RateOutcome out;
  out.method = a.method;
  out.state = a.state.value_or("");
  if (a.system.empty()) {
    run_one_point(a, out, note);
    return out;
  }
  detail::refuse_given(one_point_options(a), " is a one-point option; with --system the state "
                                             "and parameters come from the system file");
  run_system(a, out);
  return out;
}

}  // namespace cpkit::rate
