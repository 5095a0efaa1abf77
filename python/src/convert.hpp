#pragma once
// Conversions shared by the bindings: C++ results -> plain Python data (dicts, lists, numpy
// arrays), so that every result the module returns can be pickled and compared without cpkit.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/rate_problem/model/contact_state.hpp"
#include "cpkit/rate_problem/model/parameters.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/model/wear.hpp"

namespace cpkit::py {

namespace pyb = pybind11;

/// f() run with the GIL released (other Python threads go on meanwhile), its result returned.
/// f must not touch Python objects; its exceptions propagate once the GIL is held again.
template <class F>
auto without_gil(F&& f) -> decltype(f()) {
  pyb::gil_scoped_release release;
  return f();
}

/// A Python list of f(x) for each x of `seq`, in order (f returns a Python object or anything
/// pybind11 converts).
template <class Seq, class F>
pyb::list list_of(const Seq& seq, F&& f) {
  pyb::list out;
  for (const auto& x : seq) out.append(f(x));
  return out;
}

/// A numpy column of get(x) for each record x of a series (the simulations' time series).
template <class T, class F>
pyb::array_t<double> column(const std::vector<T>& s, F get) {
  pyb::array_t<double> a(static_cast<pyb::ssize_t>(s.size()));
  auto m = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < s.size(); ++i) m(static_cast<pyb::ssize_t>(i)) = get(s[i]);
  return a;
}

/// A numpy copy of an Eigen vector (owns its data: safe after the C++ object is gone).
pyb::array_t<double> to_numpy(const Vec& v);
/// A numpy copy of a std::vector.
inline pyb::array_t<double> to_numpy(const std::vector<double>& v) {
  return pyb::array_t<double>(static_cast<pyb::ssize_t>(v.size()), v.data());
}

/// The common solver options of the Python calls, validated (InputError naming the option);
/// tol_acceptable below tol is raised to tol.
CommonOptions common_options(double tol, double tol_acceptable, int max_iterations,
                             double time_limit);
/// The registered solver `name` of `kind`; else InputError "solver: unknown <what> 'name'
/// (valid: ...)" listing the solvers of that kind.
const SolverEntry& find_solver(const std::string& name, ProblemKind kind,
                               const std::string& what = "solver");

/// SolveResult as a dict with the field names of core/report.hpp's JSON.
pyb::dict to_dict(const SolveResult& r);
pyb::dict to_dict(const Residuals& r);

/// Solution type names of a type mask, in SolutionType order ("separation", "stick", ...).
pyb::list type_names(unsigned mask);

/// ContactParameters from any object with the attributes a11, a12, a22, mu, C_T, k_a, P_s and
/// criterion ("38"/"coulomb" or "35"/"softening"): cpkit.ContactParameters. Validated
/// (InputError -> ValueError naming the field).
rate::ContactParameters parameters_from(const pyb::handle& o);
/// ContactState from an object with label ("a".."d"), P_N, sgn_PT (cpkit.ContactState), or a
/// bare label string. Validated against `params`.
rate::ContactState state_from(const pyb::handle& o, const rate::ContactParameters& params);

/// The wear law by its Python name ("archard", "mroz-stupkiewicz") with the Mroz-Stupkiewicz
/// constant k_M; InputError (ValueError) for another name.
rate::WearModel wear_from(const std::string& law, double k_M);

/// Rates as a dict {dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w} (the CLI's JSON names).
pyb::dict to_dict(const rate::Rates& r);

/// The module's memory bound, as the command line's (apps/memory_limit.hpp): a result that
/// would need more than 1 GiB is refused up front with InputError naming `what` and the size.
void check_memory(double bytes, const std::string& what);

/// A finite double from a Python number; ValueError naming `what` otherwise.
double finite_number(const pyb::handle& o, const char* what);

}  // namespace cpkit::py
