// NLopt backend of the MPCC subproblems: SLSQP (Kraft 1988) on the same NLP rows as Ipopt.
// NLopt's C++ API throws (roundoff_limited, forced_stop, invalid_argument, bad_alloc,
// runtime_error): every exception is caught here and mapped to an NlpOutcome.
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <vector>

#include "mpcc_nlp.hpp"

namespace cpkit::lcp::detail {
namespace {

struct Context {
  const NlpEvaluator* nlp;
  NlpOutcome* out;
  std::vector<Eigen::Index> rows;  // NLP row of each NLopt constraint
  std::vector<double> sign;        // +1: g - bound <= 0 / = 0;  -1: bound - g <= 0
  std::vector<double> bound;
};

double objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  auto* ctx = static_cast<Context*>(data);
  const Vec xv = Eigen::Map<const Vec>(x.data(), static_cast<Eigen::Index>(x.size()));
  double f = 0;
  if (!ctx->nlp->objective(xv, f)) {
    ctx->out->eval_failed = true;
    throw nlopt::forced_stop();
  }
  if (!grad.empty()) {
    Vec g;
    if (!ctx->nlp->gradient(xv, g)) {
      ctx->out->eval_failed = true;
      throw nlopt::forced_stop();
    }
    Eigen::Map<Vec>(grad.data(), g.size()) = g;
  }
  ++ctx->out->iterations;
  return f;
}

void constraints(unsigned m, double* result, unsigned n, const double* x, double* grad,
                 void* data) {
  auto* ctx = static_cast<Context*>(data);
  const Vec xv = Eigen::Map<const Vec>(x, n);
  Vec g;
  if (!ctx->nlp->constraints(xv, g)) {
    ctx->out->eval_failed = true;
    throw nlopt::forced_stop();
  }
  for (unsigned k = 0; k < m; ++k)
    result[k] = ctx->sign[k] * (g(ctx->rows[k]) - ctx->bound[k]);
  if (grad != nullptr) {
    Mat J;
    if (!ctx->nlp->jacobian(xv, J)) {
      ctx->out->eval_failed = true;
      throw nlopt::forced_stop();
    }
    for (unsigned k = 0; k < m; ++k)
      for (unsigned j = 0; j < n; ++j) grad[k * n + j] = ctx->sign[k] * J(ctx->rows[k], j);
  }
}

std::string result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "SUCCESS";
    case nlopt::STOPVAL_REACHED: return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED: return "FTOL_REACHED";
    case nlopt::XTOL_REACHED: return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED: return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED: return "MAXTIME_REACHED";
    default: return "nlopt result " + std::to_string(static_cast<int>(r));
  }
}

}  // namespace

NlpOutcome solve_nlp_nlopt(const NlpEvaluator& nlp, const Vec& x0, const MpccOptions& options,
                           double time_limit_s) {
  NlpOutcome out;
  out.x = x0;
  const auto n = static_cast<unsigned>(nlp.n());
  Context eq{&nlp, &out, {}, {}, {}}, ineq{&nlp, &out, {}, {}, {}};
  for (Eigen::Index r = 0; r < nlp.rows(); ++r) {
    const double lo = nlp.g_lower()(r), hi = nlp.g_upper()(r);
    if (lo == hi) {
      eq.rows.push_back(r), eq.sign.push_back(1.0), eq.bound.push_back(lo);
      continue;
    }
    if (std::isfinite(lo)) ineq.rows.push_back(r), ineq.sign.push_back(-1.0), ineq.bound.push_back(lo);
    if (std::isfinite(hi)) ineq.rows.push_back(r), ineq.sign.push_back(1.0), ineq.bound.push_back(hi);
  }
  std::vector<double> lb(nlp.x_lower().data(), nlp.x_lower().data() + n);
  std::vector<double> ub(nlp.x_upper().data(), nlp.x_upper().data() + n);
  std::vector<double> x(x0.data(), x0.data() + n);
  for (unsigned i = 0; i < n; ++i) x[i] = std::min(std::max(x[i], lb[i]), ub[i]);
  // NLopt updates x in place before throwing: the last iterate is kept in every case.
  auto keep_x = [&] {
    Vec xv = Eigen::Map<const Vec>(x.data(), n);
    if (xv.allFinite()) out.x = xv;
  };
  try {
    nlopt::opt opt(nlopt::LD_SLSQP, n);
    opt.set_lower_bounds(lb);
    opt.set_upper_bounds(ub);
    opt.set_min_objective(objective, &ineq);
    const double ctol = std::max(1e-12, options.feasibility_tol * 1e-2);
    if (!eq.rows.empty())
      opt.add_equality_mconstraint(constraints, &eq, std::vector<double>(eq.rows.size(), ctol));
    if (!ineq.rows.empty())
      opt.add_inequality_mconstraint(constraints, &ineq,
                                     std::vector<double>(ineq.rows.size(), ctol));
    opt.set_ftol_rel(options.nlp_tol);
    opt.set_xtol_rel(options.nlp_tol);
    opt.set_maxeval(options.common.max_iterations > 0 ? options.common.max_iterations : 1000);
    if (time_limit_s > 0 && std::isfinite(time_limit_s)) opt.set_maxtime(time_limit_s);
    double f = 0;
    const nlopt::result r = opt.optimize(x, f);
    out.status = result_name(r);
    out.converged = r == nlopt::SUCCESS || r == nlopt::FTOL_REACHED || r == nlopt::XTOL_REACHED ||
                    r == nlopt::STOPVAL_REACHED;
    out.time_limit = r == nlopt::MAXTIME_REACHED;
    keep_x();
  } catch (const nlopt::roundoff_limited&) {
    keep_x();
    out.status = "roundoff_limited";  // the point may still be usable: the driver measures it
  } catch (const nlopt::forced_stop&) {
    if (!out.eval_failed) keep_x();
    out.status = out.eval_failed ? "forced_stop (callback outside its domain)" : "forced_stop";
  } catch (const std::invalid_argument& e) {
    out.status = std::string("invalid_argument: ") + e.what();
  } catch (const std::bad_alloc&) {
    out.status = "bad_alloc";
  } catch (const std::exception& e) {
    out.status = std::string("failure: ") + e.what();
  }
  return out;
}

}  // namespace cpkit::lcp::detail
