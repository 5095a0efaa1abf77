#include "convert.hpp"

#include <cmath>
#include <cstdio>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::py {

pyb::array_t<double> to_numpy(const Vec& v) {
  pyb::array_t<double> a(v.size());
  auto m = a.mutable_unchecked<1>();
  for (Eigen::Index i = 0; i < v.size(); ++i) m(i) = v[i];
  return a;
}

CommonOptions common_options(double tol, double tol_acceptable, int max_iterations,
                             double time_limit) {
  CommonOptions o;
  o.tol = tol;
  o.tol_acceptable = tol_acceptable < tol ? tol : tol_acceptable;
  o.max_iterations = max_iterations;
  o.time_limit_s = time_limit;
  throw_if_invalid(o.validate(), "options");
  return o;
}

const SolverEntry& find_solver(const std::string& name, ProblemKind kind, const std::string& what) {
  const SolverEntry* e = lcp::solvers().find(name);
  if (e == nullptr || !e->accepts(kind)) {
    std::string valid;
    for (const auto& n : lcp::solvers().names(kind)) valid += (valid.empty() ? "" : ", ") + n;
    throw InputError("solver: unknown " + what + " '" + name + "' (valid: " + valid + ")");
  }
  return *e;
}

pyb::dict to_dict(const Residuals& r) {
  pyb::dict d;
  d["natural"] = r.natural;
  d["natural_abs"] = r.natural_abs;
  d["complementarity"] = r.complementarity;
  d["min_z"] = r.min_z;
  d["min_w"] = r.min_w;
  d["worst_index"] = static_cast<long long>(r.worst_index);
  d["scale"] = r.scale;
  d["z_scale"] = r.z_scale;
  d["rounding"] = r.rounding;
  d["finite"] = r.finite;
  return d;
}

pyb::dict to_dict(const SolveResult& r) {
  pyb::dict d;
  d["status"] = std::string(to_string(r.status));
  d["solver"] = r.solver;
  d["z"] = to_numpy(r.z);
  d["w"] = to_numpy(r.w);
  d["residuals"] = to_dict(r.residuals);
  d["iterations"] = r.iterations;
  d["function_evals"] = r.function_evals;
  d["jacobian_evals"] = r.jacobian_evals;
  d["seconds"] = r.seconds;
  if (r.certificate) {
    pyb::dict c;
    c["y"] = to_numpy(r.certificate->y);
    c["checked"] = r.certificate->checked;
    c["exact"] = r.certificate->exact;
    c["q_dot_y"] = r.certificate->q_dot_y;
    c["max_MTy"] = r.certificate->max_MTy;
    d["certificate"] = c;
  } else {
    d["certificate"] = pyb::none();
  }
  d["ray"] = r.ray ? pyb::object(to_numpy(*r.ray)) : pyb::object(pyb::none());
  d["basis"] = r.basis;
  d["attempts"] = list_of(r.attempts, [](const Attempt& a) {
    pyb::dict ad;
    ad["solver"] = a.solver;
    ad["status"] = std::string(to_string(a.status));
    ad["residual"] = a.residual;
    ad["seconds"] = a.seconds;
    ad["message"] = a.message;
    return ad;
  });
  d["message"] = r.message;
  return d;
}

pyb::list type_names(unsigned mask) {
  pyb::list out;
  for (int t = 0; t <= static_cast<int>(rate::SolutionType::kSlipMinus); ++t)
    if (mask & (1u << t)) out.append(std::string(rate::to_string(static_cast<rate::SolutionType>(t))));
  return out;
}

double finite_number(const pyb::handle& o, const char* what) {
  double v = 0;
  try {
    v = o.cast<double>();
  } catch (const pyb::cast_error&) {
    throw pyb::type_error(std::string(what) + " must be a number, got " +
                          std::string(pyb::str(pyb::type::handle_of(o).attr("__name__"))));
  }
  if (!std::isfinite(v)) throw InputError(std::string(what) + " must be finite, got " + std::to_string(v));
  return v;
}

void check_memory(double bytes, const std::string& what) {
  constexpr double kLimit = 1024.0 * 1024.0 * 1024.0;
  if (bytes > kLimit) {
    char size[32];
    std::snprintf(size, sizeof size, "%.3g GiB", bytes / kLimit);
    throw InputError(what + " would need about " + size +
                     " of memory; the limit is 1 GiB: use fewer cells or steps");
  }
}

namespace {
double number_attr(const pyb::handle& o, const char* name) {
  if (!pyb::hasattr(o, name))
    throw pyb::type_error(std::string("contact parameters need the attribute '") + name + "'");
  return finite_number(o.attr(name), name);
}
}  // namespace

rate::WearModel wear_from(const std::string& law, double k_M) {
  const auto w = rate::wear_law_from_string(law);
  if (!w) throw InputError("wear_law must be 'archard' or 'mroz-stupkiewicz', got '" + law + "'");
  return rate::WearModel{*w, k_M};
}

rate::ContactParameters parameters_from(const pyb::handle& o) {
  rate::ContactParameters p;
  p.a11 = number_attr(o, "a11");
  p.a12 = number_attr(o, "a12");
  p.a22 = number_attr(o, "a22");
  p.mu = number_attr(o, "mu");
  p.C_T = number_attr(o, "C_T");
  p.k_a = number_attr(o, "k_a");
  p.P_s = number_attr(o, "P_s");
  const std::string crit = pyb::str(o.attr("criterion"));
  const auto c = rate::criterion_from_string(crit);
  if (!c) throw InputError("criterion must be '38' (coulomb) or '35' (softening), got '" + crit + "'");
  p.criterion = *c;
  throw_if_invalid(p.validate(), "contact parameters");
  return p;
}

rate::ContactState state_from(const pyb::handle& o, const rate::ContactParameters& params) {
  rate::ContactState s;
  std::string label;
  if (pyb::isinstance<pyb::str>(o)) {
    label = o.cast<std::string>();
  } else {
    label = pyb::str(o.attr("label"));
    s.P_N = number_attr(o, "P_N");
    const double sgn = number_attr(o, "sgn_PT");
    if (sgn != 1 && sgn != -1) throw InputError("sgn_PT must be +1 or -1, got " + std::to_string(sgn));
    s.sgn_PT = static_cast<int>(sgn);
  }
  const auto l = rate::state_from_string(label);
  if (!l) throw InputError("state must be one of a, b, c, d, got '" + label + "'");
  s.label = *l;
  throw_if_invalid(s.validate(params), "contact state");
  return s;
}

pyb::dict to_dict(const rate::Rates& r) {
  pyb::dict d;
  d["dP_T"] = r.dP_T;
  d["dP_N"] = r.dP_N;
  d["dw_T"] = r.dw_T;
  d["dw_N"] = r.dw_N;
  d["dw_Ti"] = r.dw_Ti;
  d["dw_w"] = r.dw_w;
  return d;
}

}  // namespace cpkit::py
