// LCP / box LCP / MCP as MPCC (see mpcc_solvers.hpp), the Newton polish and the registry
// entries "ipopt" and "nlopt".
#include "cpkit/lcp/mpcc_solvers.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/finalize.hpp"
#include "cpkit/core/units.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/timer.hpp"
#include "uniform01.hpp"

namespace cpkit::lcp {

std::string ComplementarityMpccOptions::validate(Eigen::Index n) const {
  if (auto msg = mpcc.validate(); !msg.empty()) return msg;
  if (reference.size() != 0 && reference.size() != n)
    return "reference has size " + std::to_string(reference.size()) + ", expected " +
           std::to_string(n);
  if (!reference.allFinite()) return "reference has non-finite entries";
  return {};
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Dense Jacobian of F at x: the callback, else the sparse callback, else forward differences.
bool jacobian_of(const McpProblem& p, const Vec& x, Mat& J) {
  if (p.jacobian) return p.jacobian(x, J) && J.rows() == p.n && J.cols() == p.n && J.allFinite();
  if (p.sparse_jacobian) {
    SparseMat S;
    if (!p.sparse_jacobian(x, S) || S.rows() != p.n || S.cols() != p.n) return false;
    J = Mat(S);
    return J.allFinite();
  }
  Vec F0(p.n), F1(p.n);
  if (!p.F(x, F0) || !F0.allFinite()) return false;
  J.resize(p.n, p.n);
  Vec xh = x;
  for (Eigen::Index j = 0; j < p.n; ++j) {
    const double h = 1e-7 * (1 + std::abs(x(j)));
    xh(j) = x(j) + h;
    if (!p.F(xh, F1) || !F1.allFinite()) {  // try the other side (e.g. at a domain edge)
      xh(j) = x(j) - h;
      if (!p.F(xh, F1) || !F1.allFinite()) return false;
      J.col(j) = (F0 - F1) / h;
    } else {
      J.col(j) = (F1 - F0) / h;
    }
    xh(j) = x(j);
  }
  return true;
}

/// Evaluation cache shared by the MPCC callbacks (one solve, one thread).
struct FCache {
  const McpProblem* p = nullptr;
  Vec x_F, F, x_J;
  Mat J;
  bool ok_F = false, ok_J = false;
  bool eval_F(const Vec& x) {
    if (x_F.size() == x.size() && x_F == x) return ok_F;
    x_F = x;
    F.resize(p->n);
    ok_F = p->F(x, F) && F.size() == p->n && F.allFinite();
    return ok_F;
  }
  bool eval_J(const Vec& x) {
    if (x_J.size() == x.size() && x_J == x) return ok_J;
    x_J = x;
    ok_J = jacobian_of(*p, x, J);
    return ok_J;
  }
};

/// The MPCC of an MCP (layout in mpcc_solvers.hpp). Variables: x (n), then a_k, b_k per box
/// index k.
MpccProblem mcp_to_mpcc(const McpProblem& mcp, bool linear, const Vec& reference) {
  const Eigen::Index n = mcp.n;
  enum Kind { kLow, kUp, kFree, kBox };
  std::vector<Kind> kind(static_cast<std::size_t>(n));
  std::vector<Eigen::Index> box_slot(static_cast<std::size_t>(n), -1);
  Eigen::Index nb = 0, np = 0, nc = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool lf = std::isfinite(mcp.lower(i)), uf = std::isfinite(mcp.upper(i));
    Kind k = lf && uf ? kBox : lf ? kLow : uf ? kUp : kFree;
    kind[i] = k;
    if (k == kBox) box_slot[i] = nb++, np += 2, nc += 1;
    else if (k == kFree) nc += 1;
    else np += 1;
  }
  const Eigen::Index N = n + 2 * nb;
  auto cache = std::make_shared<FCache>();
  cache->p = &mcp;  // mcp outlives the MpccProblem (both live in one solve call)
  MpccProblem m;
  m.name = mcp.name;
  m.n = N;
  m.lower = Vec::Zero(N);
  m.upper = Vec::Constant(N, kInf);
  m.lower.head(n) = mcp.lower;
  m.upper.head(n) = mcp.upper;
  m.x0 = Vec::Zero(N);
  if (mcp.x0.size() == n) m.x0.head(n) = mcp.x0;
  m.m = nc;
  m.p = np;
  m.c_lower = Vec::Zero(nc);
  m.c_upper = Vec::Zero(nc);
  // Row maps.
  struct PairRow { Eigen::Index i; int side; };  // side: 0 lower (x-l _|_ F or a), 1 upper
  std::vector<PairRow> pairs;
  std::vector<Eigen::Index> crow;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (kind[i] == kLow) pairs.push_back({i, 0});
    if (kind[i] == kUp) pairs.push_back({i, 1});
    if (kind[i] == kBox) pairs.push_back({i, 0}), pairs.push_back({i, 1});
    if (kind[i] == kFree || kind[i] == kBox) crow.push_back(i);
  }
  const Vec l = mcp.lower, u = mcp.upper;
  m.G = [=](const Vec& y, Vec& G) {
    G.resize(np);
    for (Eigen::Index r = 0; r < np; ++r) {
      const auto [i, side] = pairs[r];
      G(r) = side == 0 ? y(i) - l(i) : u(i) - y(i);
    }
    return true;
  };
  m.G_jacobian = [=](const Vec&, Mat& JG) {
    JG.setZero(np, N);
    for (Eigen::Index r = 0; r < np; ++r) JG(r, pairs[r].i) = pairs[r].side == 0 ? 1.0 : -1.0;
    return true;
  };
  m.H = [=](const Vec& y, Vec& H) {
    if (!cache->eval_F(y.head(n))) return false;
    H.resize(np);
    for (Eigen::Index r = 0; r < np; ++r) {
      const auto [i, side] = pairs[r];
      if (kind[i] == kBox) H(r) = y(n + 2 * box_slot[i] + side);
      else H(r) = side == 0 ? cache->F(i) : -cache->F(i);
    }
    return true;
  };
  m.H_jacobian = [=](const Vec& y, Mat& JH) {
    JH.setZero(np, N);
    bool need_J = false;
    for (const auto& pr : pairs) need_J |= kind[pr.i] != kBox;
    if (need_J && !cache->eval_J(y.head(n))) return false;
    for (Eigen::Index r = 0; r < np; ++r) {
      const auto [i, side] = pairs[r];
      if (kind[i] == kBox) JH(r, n + 2 * box_slot[i] + side) = 1.0;
      else JH.row(r).head(n) = (side == 0 ? 1.0 : -1.0) * cache->J.row(i);
    }
    return true;
  };
  if (nc > 0) {
    m.constraints = [=](const Vec& y, Vec& c) {
      if (!cache->eval_F(y.head(n))) return false;
      c.resize(nc);
      for (Eigen::Index r = 0; r < nc; ++r) {
        const Eigen::Index i = crow[r];
        c(r) = cache->F(i);
        if (kind[i] == kBox) c(r) += -y(n + 2 * box_slot[i]) + y(n + 2 * box_slot[i] + 1);
      }
      return true;
    };
    m.constraint_jacobian = [=](const Vec& y, Mat& Jc) {
      if (!cache->eval_J(y.head(n))) return false;
      Jc.setZero(nc, N);
      for (Eigen::Index r = 0; r < nc; ++r) {
        const Eigen::Index i = crow[r];
        Jc.row(r).head(n) = cache->J.row(i);
        if (kind[i] == kBox) Jc(r, n + 2 * box_slot[i]) = -1, Jc(r, n + 2 * box_slot[i] + 1) = 1;
      }
      return true;
    };
  }
  if (reference.size() == n) {
    m.objective = [=](const Vec& y, double& f) {
      f = 0.5 * (y.head(n) - reference).squaredNorm();
      return true;
    };
    m.gradient = [=](const Vec& y, Vec& g) {
      g = Vec::Zero(N);
      g.head(n) = y.head(n) - reference;
      return true;
    };
  }
  if (linear) {  // every function is linear except the objective: its Hessian is I on x
    const bool has_objective = reference.size() == n;
    m.hessian = [=](const Vec&, double sigma, const Vec&, const Vec&, const Vec&, Mat& Hs) {
      Hs.setZero(N, N);
      if (has_objective) Hs.topLeftCorner(n, n).diagonal().setConstant(sigma);
      return true;
    };
  }
  return m;
}

/// Active-set Newton polish of an MCP point; true when x was improved.
bool newton_polish(const McpProblem& p, Vec& x) {
  auto residual = [&](const Vec& v, double& res) {
    Vec F(p.n);
    if (!p.F(v, F) || F.size() != p.n || !F.allFinite()) return false;
    res = mcp_residuals(p, v, F).natural;
    return true;
  };
  double best = 0;
  if (!residual(x, best)) return false;
  Vec y = x, F(p.n);
  Mat J;
  bool improved = false;
  for (int it = 0; it < 30; ++it) {
    if (!p.F(y, F) || !F.allFinite()) break;
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < p.n; ++i) {
      const double s = y(i) - F(i);
      if (s <= p.lower(i)) y(i) = p.lower(i);
      else if (s >= p.upper(i)) y(i) = p.upper(i);
      else free.push_back(i);
    }
    if (!free.empty()) {
      if (!p.F(y, F) || !F.allFinite() || !jacobian_of(p, y, J)) break;
      const auto nf = static_cast<Eigen::Index>(free.size());
      Mat Jff(nf, nf);
      Vec rhs(nf);
      for (Eigen::Index a = 0; a < nf; ++a) {
        rhs(a) = -F(free[a]);
        for (Eigen::Index b = 0; b < nf; ++b) Jff(a, b) = J(free[a], free[b]);
      }
      const Vec d = Jff.colPivHouseholderQr().solve(rhs);
      if (!d.allFinite()) break;
      for (Eigen::Index a = 0; a < nf; ++a) y(free[a]) += d(a);
    }
    double res = 0;
    if (!residual(y, res)) break;
    if (res < best) {
      best = res;
      x = y;
      improved = true;
    }
    if (res == 0 || (it > 0 && !improved)) break;
    if (res <= 1e-15) break;
  }
  return improved;
}

std::string trace_kind(const MpccSubproblem& s) {
  std::ostringstream o;
  o.precision(3);
  o << s.kind;
  if (s.kind == "scholtes") o << " t=" << s.parameter;
  if (s.kind == "penalty") o << " rho=" << s.parameter;
  o << ": " << s.nlp_status;
  return o.str();
}

/// Points beyond 1e10 (1 + ||x0||_inf + finite bounds) are treated as diverged.
bool within_divergence_bound(const Vec& z, const McpProblem& mcp) {
  double ref = 1 + (mcp.x0.size() == mcp.n ? mcp.x0.lpNorm<Eigen::Infinity>() : 0.0);
  for (Eigen::Index i = 0; i < mcp.n; ++i) {
    if (std::isfinite(mcp.lower(i))) ref = std::max(ref, std::abs(mcp.lower(i)));
    if (std::isfinite(mcp.upper(i))) ref = std::max(ref, std::abs(mcp.upper(i)));
  }
  return z.allFinite() && z.lpNorm<Eigen::Infinity>() <= 1e10 * ref;
}

using detail::uniform01;

Vec restart_point(const McpProblem& mcp, Eigen::Index N, std::mt19937_64& rng) {
  Vec y = Vec::Zero(N);
  for (Eigen::Index i = 0; i < mcp.n; ++i) {
    const double l = mcp.lower(i), u = mcp.upper(i);
    const double w = 1 + (mcp.x0.size() == mcp.n ? std::abs(mcp.x0(i)) : 0.0);
    const double r = uniform01(rng);
    if (std::isfinite(l) && std::isfinite(u)) y(i) = l + r * (u - l);
    else if (std::isfinite(l)) y(i) = l + r * w;
    else if (std::isfinite(u)) y(i) = u - r * w;
    else y(i) = (2 * r - 1) * w;
  }
  for (Eigen::Index j = mcp.n; j < N; ++j) y(j) = uniform01(rng);
  return y;
}

template <class Problem>
SolveResult solve_via_mpcc(const Problem& original, const McpProblem& mcp, bool linear,
                           const ComplementarityMpccOptions& options, MpccResult* details) {
  Stopwatch timer;
  MpccProblem mpcc = mcp_to_mpcc(mcp, linear, options.reference);
  std::mt19937_64 rng(options.seed);
  std::optional<SolveResult> best;
  MpccResult best_details;
  int nlps = 0;
  for (int attempt = 0; attempt <= options.restarts; ++attempt) {
    MpccOptions mo = options.mpcc;
    mo.common.time_limit_s = options.mpcc.common.time_limit_s - timer.seconds();
    if (attempt > 0) {
      if (!(mo.common.time_limit_s > 0)) break;
      mpcc.x0 = restart_point(mcp, mpcc.n, rng);
      if (attempt % 2 == 1)  // odd restarts use the other reformulation
        mo.reformulation = mo.reformulation == MpccReformulation::kScholtes
                               ? MpccReformulation::kPenalty
                               : MpccReformulation::kScholtes;
    }
    // Stop the sequence as soon as the Newton-polished point verifies on the original problem.
    mo.early_stop = [&](const Vec& y) {
      if (!options.newton_polish) return false;
      Vec z = y.head(mcp.n);
      newton_polish(mcp, z);
      if (!within_divergence_bound(z, mcp)) return false;
      SolveResult probe;
      probe.z = z;
      probe.status = Status::kSolved;
      return finalize(original, std::move(probe), options.mpcc.common).status == Status::kSolved;
    };
    MpccResult mr = solve_mpcc(mpcc, mo);
    nlps += static_cast<int>(mr.subproblems.size());
    SolveResult claim;
    claim.solver = std::string(to_string(options.mpcc.backend));
    claim.z = mr.x.head(mcp.n);
    claim.iterations = mr.iterations;
    claim.message = mr.message;
    // An early stop means the caller's test (Newton polish + finalize) already verified it.
    claim.status = is_solution(mr.status) || mr.stopped_early ? Status::kSolved : mr.status;
    if (options.newton_polish && newton_polish(mcp, claim.z))
      claim.message += "; active-set Newton polish applied";
    if (!within_divergence_bound(claim.z, mcp)) {
      // Never hand finalize() a diverged point (defence in depth, see docs/mpcc.md).
      claim.message += "; iterates diverged (||z||_inf = " +
                       std::to_string(claim.z.lpNorm<Eigen::Infinity>()) + "), point dropped";
      claim.z.resize(0);
      claim.status = Status::kNumericalFailure;
    }
    if (options.mpcc.common.record_trace) {
      int k = 0;
      for (const auto& s : mr.subproblems)
        claim.trace.push_back(
            TraceEntry{k++, s.complementarity, s.parameter, trace_kind(s), -1, -1});
    }
    if (mr.status == Status::kStalled && !mr.stopped_early)
      claim.message += "; the relaxation ended with complementarity violated";
    if (attempt > 0) claim.message += "; restart " + std::to_string(attempt) + " (seeded start)";
    SolveResult r = finalize(original, std::move(claim), options.mpcc.common);
    auto merit = [](const SolveResult& x) {
      return x.z.size() == 0 ? std::numeric_limits<double>::infinity() : x.residuals.natural;
    };
    const bool better = !best || (is_solution(r.status) && !is_solution(best->status)) ||
                        (is_solution(r.status) == is_solution(best->status) &&
                         merit(r) < merit(*best));
    if (better) {
      best = std::move(r);
      best_details = std::move(mr);
    }
    if (best->status == Status::kSolved) break;
  }
  SolveResult r = std::move(*best);
  r.message += "; " + std::to_string(nlps) + " NLP(s) in all";
  r.seconds = timer.seconds();
  if (details) *details = std::move(best_details);
  return r;
}

// A result computed in natural units, decided again on the caller's data (same verdict up to
// rounding: the acceptance test is unit-free).
template <class Problem>
SolveResult back_to_units(const Problem& original, SolveResult r, const LcpUnits& units,
                          const CommonOptions& common) {
  if (r.z.size()) r.z = z_from_units(r.z, units);
  return finalize(original, std::move(r), common);
}

McpProblem checked_mcp(McpProblem mcp) {
  if (mcp.lower.size() != mcp.n) mcp.lower = Vec::Zero(mcp.n);
  if (mcp.upper.size() != mcp.n) mcp.upper = Vec::Constant(mcp.n, kInf);
  return mcp;
}

// The NLP is posed in equilibrated natural units (units.hpp): its feasibility tolerances,
// relaxation parameters and divergence bound are then meaningful whatever units the caller
// used. The answer is mapped back and decided again on the caller's data. P: LcpProblem or
// BoxLcpProblem (lcp: its LCP part), as_mcp its MCP form.
template <class P, class AsMcp>
SolveResult solve_in_units(const P& problem, const LcpProblem& lcp, AsMcp as_mcp,
                           const ComplementarityMpccOptions& options, MpccResult* details) {
  const LcpUnits units = equilibrated_units(lcp);
  const P scaled = to_units(problem, units);
  ComplementarityMpccOptions o = options;
  if (o.reference.size()) o.reference = z_to_units(o.reference, units);
  const McpProblem mcp = checked_mcp(as_mcp(scaled));
  return back_to_units(problem, solve_via_mpcc(scaled, mcp, true, o, details), units,
                       options.mpcc.common);
}

ComplementarityMpccOptions defaults(NlpBackend backend, const CommonOptions& common) {
  ComplementarityMpccOptions o;
  o.mpcc.backend = backend;
  o.mpcc.common = common;
  return o;
}

}  // namespace

SolveResult solve_lcp_mpcc(const LcpProblem& problem, const ComplementarityMpccOptions& options,
                           MpccResult* details) {
  throw_if_invalid(problem.validate(), "LCP");
  throw_if_invalid(options.validate(problem.size()), "MPCC options");
  return solve_in_units(problem, problem, [](const LcpProblem& s) { return lcp_as_mcp(s); },
                        options, details);
}

SolveResult solve_box_lcp_mpcc(const BoxLcpProblem& problem,
                               const ComplementarityMpccOptions& options, MpccResult* details) {
  throw_if_invalid(problem.validate(), "box LCP");
  throw_if_invalid(options.validate(problem.size()), "MPCC options");
  return solve_in_units(problem, problem.lcp,
                        [](const BoxLcpProblem& s) { return box_lcp_as_mcp(s); }, options, details);
}

SolveResult solve_mcp_mpcc(const McpProblem& problem, const ComplementarityMpccOptions& options,
                           MpccResult* details) {
  throw_if_invalid(problem.validate(), "MCP");
  throw_if_invalid(options.validate(problem.size()), "MPCC options");
  const McpProblem mcp = checked_mcp(problem);
  return solve_via_mpcc(problem, mcp, false, options, details);
}

SolveResult solve_lcp_ipopt(const LcpProblem& problem, const CommonOptions& common) {
  return solve_lcp_mpcc(problem, defaults(NlpBackend::kIpopt, common));
}
SolveResult solve_mcp_ipopt(const McpProblem& problem, const CommonOptions& common) {
  return solve_mcp_mpcc(problem, defaults(NlpBackend::kIpopt, common));
}
SolveResult solve_lcp_nlopt(const LcpProblem& problem, const CommonOptions& common) {
  return solve_lcp_mpcc(problem, defaults(NlpBackend::kNlopt, common));
}
SolveResult solve_mcp_nlopt(const McpProblem& problem, const CommonOptions& common) {
  return solve_mcp_mpcc(problem, defaults(NlpBackend::kNlopt, common));
}

namespace {
SolverEntry mpcc_entry(NlpBackend backend) {
  SolverEntry e;
  const bool ipopt = backend == NlpBackend::kIpopt;
  e.info.name = ipopt ? "ipopt" : "nlopt";
  e.info.description =
      ipopt ? "MPCC (Scholtes relaxation) solved by Ipopt, then an active-set Newton polish "
              "[Scholtes 2001; Waechter-Biegler 2006]"
            : "MPCC (Scholtes relaxation) solved by NLopt SLSQP, then an active-set Newton polish "
              "[Scholtes 2001; Kraft 1988]";
  e.info.dense = true;
  e.info.sparse = true;  // through a dense copy of the Jacobian
  e.info.serialized = ipopt;
  e.solve_lcp = [backend](const LcpProblem& p, const CommonOptions& o) {
    return solve_lcp_mpcc(p, defaults(backend, o));
  };
  e.solve_box_lcp = [backend](const BoxLcpProblem& p, const CommonOptions& o) {
    return solve_box_lcp_mpcc(p, defaults(backend, o));
  };
  e.solve_mcp = [backend](const McpProblem& p, const CommonOptions& o) {
    return solve_mcp_mpcc(p, defaults(backend, o));
  };
  return e;
}
}  // namespace

SolverEntry ipopt_entry() { return mpcc_entry(NlpBackend::kIpopt); }
SolverEntry nlopt_entry() { return mpcc_entry(NlpBackend::kNlopt); }

}  // namespace cpkit::lcp
