// The N-point rate problem (rate_problem/rate/system_rate.hpp): every solution for a load
// rate dF, and the counts over many load directions (the fast summary path, one call). The
// system is the parsed _cpkit.ContactSystemData (bind_system.cpp), not re-read per call.
#include <cmath>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

namespace cpkit::py {

namespace {

pyb::dict rates_dict(const rate::SystemRates& r) {
  pyb::dict d;
  d["dP_T"] = to_numpy(r.dP_T);
  d["dP_N"] = to_numpy(r.dP_N);
  d["dw_T"] = to_numpy(r.dw_T);
  d["dw_N"] = to_numpy(r.dw_N);
  d["dw_Ti"] = to_numpy(r.dw_Ti);
  d["dw_w"] = to_numpy(r.dw_w);
  return d;
}

pyb::list type_list(const std::vector<rate::SolutionType>& types) {
  pyb::list out;
  for (auto t : types) out.append(std::string(rate::to_string(t)));
  return out;
}

pyb::dict solve_system_rate(const rate::ContactSystem& sys, const Vec& dF, const std::string& method) {
  const auto m = rate::rate_method_from_string(method);
  if (!m) throw InputError("method must be one of enumerate, lemke, fb-newton, ipopt, got '" + method + "'");
  rate::SystemRateSolutionSet set =
      without_gil([&] { return rate::solve_rate_problem(sys, dF, *m); });
  pyb::dict d;
  pyb::list sols;
  for (const auto& s : set.solutions) {
    pyb::dict sd;
    sd["types"] = type_list(s.types);
    sd["kind"] = std::string(rate::to_string(s.kind));
    sd["start"] = rates_dict(s.start);
    sd["start_closed"] = s.start_closed;
    if (s.kind == rate::RateSolution::Kind::kSegment) {
      sd["end"] = rates_dict(s.end);
      sd["end_closed"] = s.end_closed;
    }
    if (s.kind == rate::RateSolution::Kind::kRay) sd["direction"] = rates_dict(s.direction);
    sols.append(sd);
  }
  d["solutions"] = sols;
  d["infinite"] = set.infinite;
  d["complete"] = set.complete;
  d["count"] = set.count();
  d["message"] = set.message;
  d["residual"] = set.residual;
  d["disagreement"] = set.disagreement;
  return d;
}

/// Count, number of distinct type tuples and reliability for dF = cos(theta) e1 + sin(theta) e2
/// at every theta, by the precomputed fast path (GIL released for the loop).
pyb::dict system_direction_counts(const rate::ContactSystem& sys, const Vec& e1, const Vec& e2,
                                  const Vec& theta) {
  const Eigen::Index n = 2 * sys.n_points();
  if (e1.size() != n || e2.size() != n)
    throw InputError("load patterns e1, e2 must have 2N = " + std::to_string(n) + " entries, got " +
                     std::to_string(e1.size()) + " and " + std::to_string(e2.size()));
  if (!e1.allFinite() || !e2.allFinite() || !theta.allFinite())
    throw InputError("load patterns and directions must be finite");
  check_memory(6.0 * static_cast<double>(theta.size()), "the direction counts of " +
                                                          std::to_string(theta.size()) + " directions");
  const rate::SystemRatePrecomputed pre = rate::precompute_system_rate(sys);
  pyb::array_t<int> count(theta.size()), tuples(theta.size());
  pyb::array_t<bool> reliable(theta.size());
  {
    auto c = count.mutable_unchecked<1>();
    auto t = tuples.mutable_unchecked<1>();
    auto r = reliable.mutable_unchecked<1>();
    pyb::gil_scoped_release release;
    Vec dF(n);
    for (Eigen::Index j = 0; j < theta.size(); ++j) {
      dF = std::cos(theta[j]) * e1 + std::sin(theta[j]) * e2;
      const rate::SystemRateSummary s = rate::summarize_rate_problem(pre, dF);
      c(j) = s.count;
      t(j) = s.n_tuples;
      r(j) = s.reliable;
    }
  }
  pyb::dict d;
  d["count"] = count;
  d["n_tuples"] = tuples;
  d["reliable"] = reliable;
  return d;
}

}  // namespace

void bind_system_rate(pyb::module_& m) {
  m.def("solve_system_rate", &solve_system_rate);
  m.def("system_direction_counts", &system_direction_counts);
}

}  // namespace cpkit::py
