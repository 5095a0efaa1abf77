// Solvers of one implicit step of a 3-D contact point: docs/contact_3d.md, "Solvers of the 3-D
// step". SOC Fischer-Burmeister semismooth Newton, Ipopt MPCC, faceted LCP/NCP, chain and
// multistart. Everything runs in normalized units (forces / F0, stiffnesses / |A|, lengths /
// (F0 / |A|)); every answer is verified on the original problem by step_3d_residual.
#include "cpkit/rate_problem/step/step_solvers_3d.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "cpkit/lcp/mpcc.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "step_3d_newton.hpp"
#include "step_3d_normalized.hpp"
#include "step_3d_terms.hpp"
#include "step_3d_verdict.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

using Normalized = detail::Normalized3d<1>;

/// The problem in its own units (step_3d_units, as the exact enumeration and N points).
Normalized normalize(const Step3dProblem& pr) {
  return detail::normalize_3d<1>(detail::step_3d_units(pr.params.A, pr.DF, &pr.state, 1),
                                 pr.params.A, pr.DF, 1,
                                 [&pr](int) -> const Step3dProblem& { return pr; });
}

/// Physical values of a normalized iterate, verified on the original problem.
Step3dValues physical(const Step3dProblem& pr, const Normalized& n, const Vec4& z) noexcept {
  return step_3d_values(pr, n.F0 * z.head<2>(), n.F0 * z(2), n.L0 * n.E(0) * z(3));
}

/// The one-point kernel of the shared Newton solve (step_3d_newton.hpp).
struct PointKernel : detail::NormalizedKernel3d<1> {
  const Step3dProblem& pr;
  double residual(const Vec4& z) const noexcept { return step_3d_residual(pr, physical(pr, n, z)); }
  void finalize(const Vec4& z, Step3dSolveResult& out, const CommonOptions& o) const {
    out.solution.values = physical(pr, n, z);
    finalize_step_3d(pr, out, o);
  }
};

/// The semismooth Newton iteration from z (normalized); fills `out` (not `seconds`).
void newton(const Step3dProblem& pr, const Normalized& n, const Vec4& z, const CommonOptions& o,
            Step3dSolveResult& out) {
  detail::newton_3d<Vec4, Mat4>(PointKernel{{n}, pr}, z, o, out);
}

void check(const Step3dProblem& pr) {
  throw_if_invalid(pr.validate(), "step");
}

Vec4 normalized_start(const Normalized& n, const Step3dStart* s) {
  return s == nullptr ? n.z0 : detail::normalized_start_3d(n, s);
}

}  // namespace

CommonOptions step_3d_solver_options() {
  CommonOptions o;
  o.tol = 1e-9;
  o.tol_acceptable = 1e-9;
  o.max_iterations = 100;
  o.time_limit_s = 10;
  return o;
}

void finalize_step_3d(const Step3dProblem& problem, Step3dSolveResult& r,
                      const CommonOptions& options) {
  r.solution = make_step_3d_solution(problem, r.solution.values);
  detail::decide_step_3d(r, &r.solution.values, 1, r.solution.residual, options);
}

void sort_and_dedup_step_3d(const Step3dProblem& problem, std::vector<Step3dSolution>& sols) {
  const double F0 = normalize(problem).F0;
  std::vector<Step3dSolution> out;
  for (const auto& s : sols)
    detail::add_distinct(out, s, [F0](const Step3dSolution& a, const Step3dSolution& b) {
      return detail::same_point_solution_3d(a.values, b.values, F0);
    });
  std::stable_sort(out.begin(), out.end(), [](const Step3dSolution& a, const Step3dSolution& b) {
    if (a.type != b.type) return static_cast<int>(a.type) < static_cast<int>(b.type);
    if (a.type == SolutionType::kSlip) return a.slip_angle < b.slip_angle;
    return false;
  });
  sols = std::move(out);
}

namespace {
/// The problem in normalised units after the checks every single-start solver makes.
Normalized checked_normalized(const Step3dProblem& problem, const CommonOptions& options) {
  check(problem);
  throw_if_invalid(options.validate(), "options");
  return normalize(problem);
}
}  // namespace

Step3dSolveResult solve_step_3d_fb_soc(const Step3dProblem& problem,
                                       const CommonOptions& options,
                                        const Step3dStart* start) {
  const auto t0 = std::chrono::steady_clock::now();
  const Normalized n = checked_normalized(problem, options);
  Step3dSolveResult out;
  out.solver = "fb-soc";
  newton(problem, n, normalized_start(n, start), options, out);
  out.seconds = detail::seconds_since(t0);
  return out;
}

Step3dSolveResult solve_step_3d_ipopt(const Step3dProblem& problem,
                                      const CommonOptions& options,
                                       const Step3dStart* start) {
  const auto t0 = std::chrono::steady_clock::now();
  const Normalized n = checked_normalized(problem, options);
  const Vec4 xs = normalized_start(n, start);
  Step3dSolveResult out;
  out.solver = "ipopt";
  // u = D Dw_T^i = u0 + U x (2 x 4), q = D^-1 P_T1
  const Eigen::Matrix2d D = n.al.asDiagonal(), Dinv = n.al.cwiseInverse().asDiagonal();
  const Eigen::Vector2d u0 = D * n.ui0;
  Eigen::Matrix<double, 2, 4> U = Eigen::Matrix<double, 2, 4>::Zero();
  U.leftCols<3>() = D * n.Ui.leftCols<3>();
  lcp::MpccProblem m;
  m.n = 4;
  m.lower = Vec::Constant(4, -kInf);
  m.upper = Vec::Constant(4, kInf);
  m.lower(2) = 0;
  m.lower(3) = 0;
  m.x0 = Vec(xs);
  m.x0(2) = std::max(m.x0(2), 0.0);
  m.x0(3) = std::max(m.x0(3), 0.0);
  const Vec ref = m.x0;
  m.objective = [ref](const Vec& x, double& f) {
    f = 0.5 * (x - ref).squaredNorm();
    return true;
  };
  m.gradient = [ref](const Vec& x, Vec& g) {
    g = x - ref;
    return true;
  };
  m.m = 2;  // normality: mu P_N1 u - lambda q = 0
  m.constraints = [&n, u0, U, Dinv](const Vec& x, Vec& c) {
    const Eigen::Vector2d u = u0 + U * x.head<4>();
    const Eigen::Vector2d q = Dinv * x.head<2>();
    c = n.mu(0) * x(2) * u - x(3) * q;
    return true;
  };
  m.constraint_jacobian = [&n, u0, U, Dinv](const Vec& x, Mat& J) {
    const Eigen::Vector2d u = u0 + U * x.head<4>();
    const Eigen::Vector2d q = Dinv * x.head<2>();
    J = n.mu(0) * x(2) * U;
    J.col(2) += n.mu(0) * u;
    J.leftCols(2) -= x(3) * Dinv;
    J.col(3) -= q;
    return true;
  };
  m.c_lower = Vec::Zero(2);
  m.c_upper = Vec::Zero(2);
  m.p = 2;  // (P_N1, -g1), (lambda, mu^2 P_N1^2 - |q|^2)
  m.G = [](const Vec& x, Vec& G) {
    G = Vec(2);
    G << x(2), x(3);
    return true;
  };
  m.G_jacobian = [](const Vec&, Mat& J) {
    J = Mat::Zero(2, 4);
    J(0, 2) = 1;
    J(1, 3) = 1;
    return true;
  };
  m.H = [&n, Dinv](const Vec& x, Vec& H) {
    const Eigen::Vector3d P1 = x.head<3>();
    H = Vec(2);
    H(0) = -(n.gc(0) + n.gz.leftCols<3>().dot(P1) - n.cw(0) * x(2) * x(3));
    H(1) = n.mu(0) * n.mu(0) * x(2) * x(2) - (Dinv * x.head<2>()).squaredNorm();
    return true;
  };
  m.H_jacobian = [&n, Dinv](const Vec& x, Mat& J) {
    J = Mat::Zero(2, 4);
    J.block<1, 3>(0, 0) = -n.gz.leftCols<3>();
    J(0, 2) += n.cw(0) * x(3);
    J(0, 3) = n.cw(0) * x(2);
    const Eigen::Vector2d q = Dinv * x.head<2>();
    J(1, 0) = -2 * q(0) * Dinv(0, 0);
    J(1, 1) = -2 * q(1) * Dinv(1, 1);
    J(1, 2) = 2 * n.mu(0) * n.mu(0) * x(2);
    return true;
  };
  m.name = "step_3d";
  lcp::MpccOptions mo;
  mo.common.time_limit_s = options.time_limit_s;
  mo.common.max_iterations = options.max_iterations;
  mo.polish = false;
  CommonOptions polish = options;
  polish.max_iterations = 50;
  Step3dSolveResult best;
  best.solver = "ipopt";
  bool found = false;
  int polish_iterations = 0;
  auto try_polish = [&](const Vec& x) {
    if (found || !x.allFinite() || x.size() != 4) return found;
    Step3dSolveResult r;
    r.solver = "ipopt";
    newton(problem, n, Vec4(x.head<4>()), polish, r);
    polish_iterations += r.iterations;
    if (r.status == Status::kSolved) {
      best = r;
      found = true;
    }
    return found;
  };
  mo.early_stop = [&](const Vec& x) { return try_polish(x); };
  lcp::MpccResult mr;
  try {
    mr = lcp::solve_mpcc(m, mo);
    if (!found) try_polish(mr.x);
  } catch (const InputError& e) {
    out.message = std::string("ipopt: ") + e.what();
  }
  if (found) {
    out.solution = best.solution;
    out.status = Status::kSolved;  // claimed; finalize_step_3d below decides
    out.merit = best.merit;
    out.message = "MPCC (Scholtes relaxation, Ipopt) point polished by FB-SOC Newton";
    finalize_step_3d(problem, out, options);
  } else {
    const Status failure = mr.status == Status::kTimeLimit ? Status::kTimeLimit : Status::kStalled;
    if (mr.x.size() == 4) {
      const Vec4 z(mr.x.head<4>());
      out.solution.values = physical(problem, n, z);
      finalize_step_3d(problem, out, options);  // residual and z of the NLP point
    } else {
      out.solution.residual = kInf;
    }
    // The unpolished NLP point is information, never a verified answer.
    out.status = failure;
    if (out.message.empty())
      out.message = "ipopt: no verified solution (" + mr.message + ")";
  }
  out.iterations = mr.iterations + polish_iterations;
  out.seconds = detail::seconds_since(t0);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Faceted step.

namespace {

/// The polygon: unit outward normals n_j and supports h_j of the facets of the inscribed
/// polygon with vertices D (cos theta_i, sin theta_i).
void polygon(const Eigen::Vector2d& al, int k, Eigen::Matrix<double, 2, Eigen::Dynamic>& Nh,
             Eigen::Matrix<double, 2, Eigen::Dynamic>& N, Eigen::VectorXd& h) {
  std::vector<Eigen::Vector2d> vert(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) {
    const double th = 2 * kPi * i / k;
    vert[i] = al.asDiagonal() * Eigen::Vector2d(std::cos(th), std::sin(th));
  }
  N.resize(2, k);
  Nh.resize(2, k);
  h.resize(k);
  for (int j = 0; j < k; ++j) {
    const Eigen::Vector2d e = vert[(j + 1) % k] - vert[j];
    N.col(j) = Eigen::Vector2d(e(1), -e(0)).normalized();
    h(j) = N.col(j).dot(vert[j]);
    Nh.col(j) = N.col(j) / h(j);
  }
}

/// Equilibrium for given (P_N1, lambda): s = (DP_T, Dw) from the 5x5 system
///   DP_T + A_T. Dw = DF_T,  A_N. Dw = DF_N + P_N0 - P_N1,  Dw_T - C DP_T = Nh lambda,
/// affine: s = S0 + SN P_N1 + SL lambda.
struct FacetMap {
  Eigen::Matrix<double, 5, 1> S0, SN;
  Eigen::Matrix<double, 5, Eigen::Dynamic> SL;
};

FacetMap facet_map(const Normalized& n, const Eigen::Matrix<double, 2, Eigen::Dynamic>& Nh) {
  Eigen::Matrix<double, 5, 5> E = Eigen::Matrix<double, 5, 5>::Zero();
  E.block<2, 2>(0, 0).setIdentity();
  E.block<2, 3>(0, 2) = n.A.topRows<2>();
  E.block<1, 3>(2, 2) = n.A.row(2);
  E.block<2, 2>(3, 0) = -n.C(0) * Eigen::Matrix2d::Identity();
  E.block<2, 2>(3, 2).setIdentity();
  const Eigen::FullPivLU<Eigen::Matrix<double, 5, 5>> lu(E);
  Eigen::Matrix<double, 5, 1> b0 = Eigen::Matrix<double, 5, 1>::Zero(), bN = b0;
  b0 << n.DF(0), n.DF(1), n.DF(2) + n.P0(2), 0, 0;
  bN(2) = -1;
  const int k = static_cast<int>(Nh.cols());
  Eigen::Matrix<double, 5, Eigen::Dynamic> BL = Eigen::Matrix<double, 5, Eigen::Dynamic>::Zero(5, k);
  BL.bottomRows<2>() = Nh;
  FacetMap f;
  f.S0 = lu.solve(b0);
  f.SN = lu.solve(bN);
  f.SL = lu.solve(BL);
  return f;
}

/// Physical values (original units) of the faceted solution (P_N1, lambda) normalized.
Step3dValues facet_values(const Step3dProblem& pr, const Normalized& n, const FacetMap& f,
                          const Eigen::Matrix<double, 2, Eigen::Dynamic>& Nh, double PN,
                          const Eigen::VectorXd& lam) {
  const Eigen::Matrix<double, 5, 1> s = f.S0 + f.SN * PN + f.SL * lam;
  Step3dValues v;
  const double sum = lam.sum();
  v.DP_T = n.F0 * s.head<2>();
  v.P_T1 = pr.state.P_T0 + v.DP_T;
  v.P_N1 = n.F0 * PN;
  v.DP_N = v.P_N1 - pr.state.P_N0;
  v.Dw_T = n.L0 * s.segment<2>(2);
  v.Dw_N = n.L0 * s(4);
  v.Dw_Ti = n.L0 * (Nh * lam);
  v.Dw_w = n.L0 * n.cw(0) * PN * sum;
  v.g1 = pr.state.g0 + v.Dw_N - v.Dw_w;
  v.lambda = n.L0 * n.E(0) * sum;
  if (PN == 0) v.lambda = (pr.params.alpha.array() * v.Dw_Ti.array()).matrix().norm();
  return v;
}

}  // namespace

FacetedStep3dResult solve_step_3d_faceted(const Step3dProblem& problem, int k, int n_starts,
                                          std::uint64_t seed) {
  check(problem);
  if (k < 3 || k > lcp::kMaxEnumerationSize)
    throw InputError("facets must be in [3, " + std::to_string(lcp::kMaxEnumerationSize) +
                     "], got " + std::to_string(k));
  if (n_starts < 1) throw InputError("n_starts must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  const Normalized n = normalize(problem);
  Eigen::Matrix<double, 2, Eigen::Dynamic> N, Nh;
  Eigen::VectorXd h;
  polygon(n.al, k, Nh, N, h);
  const FacetMap f = facet_map(n, Nh);
  FacetedStep3dResult out;
  out.facets = k;
  std::vector<Step3dSolution> sols;
  auto add = [&](double PN, const Eigen::VectorXd& lam) {
    sols.push_back(make_step_3d_solution(problem, facet_values(problem, n, f, Nh, PN, lam)));
  };
  // w_j = mu P_N1 - Nh_j . (P_T0 + DP_T), affine in (P_N1, lambda)
  if (n.cw(0) == 0) {
    out.lcp = true;
    out.size = k;
    // Separation (P_N1 = 0, P_T1 = 0: every multiplier free): directly, when g1 <= 0.
    {
      // P_T1 = 0 requires DP_T = -P_T0; equilibrium with P1 = 0 gives Dw = A^-1 (DF + P0)
      const double gN1 = n.gc(0);  // g1 at P1 = 0
      // g1 = g0 + (A^-1 (DF + P0))_N in normalised units: "<= 0" up to the rounding of that
      // sum (its terms' size, not a fixed 1e-12)
      const Eigen::Vector3d P0 = n.P0;
      const double g_terms = std::abs(n.g0(0)) + n.gz.leftCols<3>().cwiseAbs().dot((n.DF + P0).cwiseAbs());
      if (gN1 <= 64 * 2.220446049250313e-16 * g_terms) {
        Step3dValues v = step_3d_values(problem, Eigen::Vector2d::Zero(), 0.0, 0.0);
        v.lambda = (problem.params.alpha.array() * v.Dw_Ti.array()).matrix().norm();
        sols.push_back(make_step_3d_solution(problem, v));
      }
    }
    // Contact (g1 = 0): P_N1 from the gap row, then an LCP of size k in lambda. With
    // s = S0 + SN P_N1 + SL lambda, g1 = g0 + Dw_N = g0 + s(4) = 0:
    //   P_N1 = -(g0 + S0(4) + SL.row(4) lambda) / SN(4)   (SN(4) != 0: A SPD).
    const double sn = f.SN(4);
    const double pn0 = -(n.g0(0) + f.S0(4)) / sn;
    const Eigen::RowVectorXd pnl = -f.SL.row(4) / sn;
    // DP_T = S0T + SNT P_N1 + SLT lambda
    const Eigen::Vector2d dpt0 = f.S0.head<2>() + f.SN.head<2>() * pn0;
    const Eigen::Matrix<double, 2, Eigen::Dynamic> dptl = f.SL.topRows<2>() + f.SN.head<2>() * pnl;
    LcpProblem lcp;
    lcp.M = n.mu(0) * Eigen::VectorXd::Ones(k) * pnl - Nh.transpose() * dptl;
    lcp.q = n.mu(0) * pn0 * Eigen::VectorXd::Ones(k) - Nh.transpose() * (n.P0.head<2>() + dpt0);
    lcp::EnumerationOptions eo;
    const lcp::SolutionSet zs = lcp::enumerate_all(lcp, eo);
    out.nodes = zs.nodes;
    out.set.complete = zs.complete;
    out.set.message = zs.message;
    for (const auto& e : zs.solutions) {
      const double PN = std::max(0.0, pn0 + pnl.dot(e.z));
      add(PN, e.z);
    }
    // A piece of positive dimension is one physical point when its rays move no physical
    // quantity (weights of the facet normals that cancel) and its vertices coincide.
    for (const auto& piece : zs.pieces) {
      bool one = true;
      for (const auto& ray : piece.rays) {
        const Eigen::Vector2d flow = Nh * ray;
        one = one && flow.cwiseAbs().maxCoeff() <= 1e-9 && std::abs(pnl.dot(ray)) <= 1e-9;
      }
      const auto& v0 = zs.solutions[piece.vertices.front()].z;
      for (int vi : piece.vertices) {
        const auto& z = zs.solutions[vi].z;
        one = one && (Nh * (z - v0)).cwiseAbs().maxCoeff() <= 1e-8 &&
              std::abs(pnl.dot(z - v0)) <= 1e-8;
      }
      if (!one) {
        out.set.complete = false;
        if (out.set.message.empty())
          out.set.message = "the faceted step has a continuum of physical solutions (a polygon "
                            "face aligned with the load): listed by its extreme points only";
      }
    }
  } else {
    // With wear: NCP of size 1 + k in (P_N1, lambda):
    //   F_0 = -g1 = -(g0 + s(4)) + cw P_N1 sum(lambda),  F_j = mu P_N1 - Nh_j . (P_T0 + DP_T).
    out.lcp = false;
    out.size = k + 1;
    const int m = k + 1;
    Mat M(m, m);
    Vec q(m);
    M(0, 0) = -f.SN(4);
    M.block(0, 1, 1, k) = -f.SL.row(4);
    q(0) = -(n.g0(0) + f.S0(4));
    M.block(1, 0, k, 1) = n.mu(0) * Eigen::VectorXd::Ones(k) - Nh.transpose() * f.SN.head<2>();
    M.block(1, 1, k, k) = -Nh.transpose() * f.SL.topRows<2>();
    q.tail(k) = -Nh.transpose() * (n.P0.head<2>() + f.S0.head<2>());
    const double cw = n.cw(0);
    McpProblem mcp = make_ncp(
        m,
        [M, q, cw, k](const Vec& z, Vec& F) {
          F = M * z + q;
          F(0) += cw * z(0) * z.tail(k).sum();
          return true;
        },
        [M, cw, k](const Vec& z, Mat& J) {
          J = M;
          J(0, 0) += cw * z.tail(k).sum();
          J.block(0, 1, 1, k).array() += cw * z(0);
          return true;
        },
        "faceted_step_3d");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    CommonOptions co;
    co.tol = 1e-11;
    co.time_limit_s = 10;
    const SolverEntry* fbn = lcp::solvers().find("fb-newton");
    const SolverEntry* ipo = lcp::solvers().find("ipopt");
    for (int s = 0; s < n_starts; ++s) {
      Vec x0 = Vec::Zero(m);
      if (s == 0) {
        x0(0) = n.P0(2);
      } else {
        x0(0) = U(rng) < 0.2 ? 0.0 : std::exp(-4 + 5.5 * U(rng));
        const int j = static_cast<int>(U(rng) * k) % k;
        x0(1 + j) = std::exp(-4 + 5.5 * U(rng));
      }
      for (const SolverEntry* e : {fbn, ipo}) {
        if (e == nullptr || !e->solve_mcp) continue;
        if (e == ipo && s >= 2) continue;
        mcp.x0 = x0;
        const SolveResult r = e->solve_mcp(mcp, co);
        if (is_solution(r.status) && r.z.size() == m)
          add(std::max(0.0, r.z(0)), Eigen::VectorXd(r.z.tail(k).cwiseMax(0.0)));
      }
    }
    out.set.complete = false;
    out.set.message = "with wear the faceted step is a nonlinear complementarity problem, solved "
                      "from " + std::to_string(n_starts) + " starts: other solutions may exist";
  }
  sort_and_dedup_step_3d(problem, sols);
  out.set.solutions = std::move(sols);
  out.seconds = detail::seconds_since(t0);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Chain and multistart.

std::string Step3dChainOptions::validate() const {
  if (chain.empty()) return "chain must not be empty";
  for (const auto& c : chain)
    if (c != "exact" && c != "fb-soc" && c != "ipopt")
      return "chain: unknown link '" + c + "' (valid: exact, fb-soc, ipopt)";
  if (const std::string e = solver.validate(); !e.empty()) return "solver: " + e;
  return {};
}

Step3dChainResult solve_step_3d(const Step3dProblem& problem, const Step3dChainOptions& options) {
  check(problem);
  throw_if_invalid(options.validate(), "options");
  Step3dChainResult out;
  for (const auto& link : options.chain) {
    const auto t0 = std::chrono::steady_clock::now();
    Attempt a;
    a.solver = link;
    a.residual = kInf;
    Step3dSolution sol;
    if (link == "exact") {
      const Step3dSolutionSet s = enumerate_step_3d(problem);
      const Step3dSolution* best = nullptr;
      double bd = kInf;
      for (const auto& x : s.solutions) {
        const double d = std::hypot((x.values.P_T1 - problem.state.P_T0).norm(),
                                    x.values.P_N1 - problem.state.P_N0);
        if (x.residual <= options.solver.tol && d < bd) {
          bd = d;
          best = &x;
        }
      }
      a.status = Status::kStalled;  // nothing found (not a proof of infeasibility: no certificate)
      if (best != nullptr) {
        sol = *best;
        a.status = Status::kSolved;  // enumerate_step_3d's verdict: residual <= tol above
        a.residual = best->residual;
        a.message = std::to_string(s.count()) + " solution(s)" +
                    (s.complete ? "" : " (not proved complete: " + s.message + ")") +
                    "; the one nearest the start state";
      } else {
        a.message = s.complete ? "no solution (complete enumeration)"
                               : "none found (not proved complete: " + s.message + ")";
      }
    } else {
      const Step3dSolveResult r = link == "fb-soc"
                                      ? solve_step_3d_fb_soc(problem, options.solver)
                                      : solve_step_3d_ipopt(problem, options.solver);
      a.status = r.status;
      a.residual = r.solution.residual;
      a.iterations = r.iterations;
      a.message = r.message;
      sol = r.solution;
    }
    a.seconds = detail::seconds_since(t0);
    out.attempts.push_back(a);
    out.status = a.status;
    out.solution = sol;
    if (a.status == Status::kSolved) {
      out.solver = link;
      break;
    }
  }
  if (out.status != Status::kSolved) {
    out.solution = Step3dSolution{};
    out.message = "no link of the chain found a verified solution";
    for (const auto& a : out.attempts) out.message += "; " + a.solver + ": " + a.message;
  }
  return out;
}

Step3dSolutionSet multistart_step_3d(const Step3dProblem& problem, int n_starts,
                                     std::uint64_t seed) {
  check(problem);
  if (n_starts < 0) throw InputError("n_starts must be >= 0");
  const Normalized n = normalize(problem);
  std::mt19937_64 rng(seed);
  std::vector<Step3dSolution> sols;
  const CommonOptions o = step_3d_solver_options();
  int fb_ok = 0, ip_ok = 0, fb_runs = 0, ip_runs = 0;
  for (int i = 0; i <= n_starts; ++i) {
    const Vec4 z = i == 0 ? n.z0
                          : detail::random_start_3d<Vec4>(PointKernel{{n}, problem}, rng);
    Step3dStart s;
    s.P_T1 = n.F0 * z.head<2>();
    s.P_N1 = n.F0 * z(2);
    s.lambda = n.L0 * n.E(0) * z(3);
    const Step3dSolveResult r = solve_step_3d_fb_soc(problem, o, &s);
    ++fb_runs;
    if (r.status == Status::kSolved) {
      ++fb_ok;
      sols.push_back(r.solution);
    }
    if (i % 4 == 0) {
      const Step3dSolveResult q = solve_step_3d_ipopt(problem, o, &s);
      ++ip_runs;
      if (q.status == Status::kSolved) {
        ++ip_ok;
        sols.push_back(q.solution);
      }
    }
  }
  sort_and_dedup_step_3d(problem, sols);
  Step3dSolutionSet set;
  set.solutions = std::move(sols);
  set.complete = false;
  set.message = "multistart (" + std::to_string(fb_ok) + "/" + std::to_string(fb_runs) +
                " FB-SOC and " + std::to_string(ip_ok) + "/" + std::to_string(ip_runs) +
                " Ipopt runs verified): local solvers cannot prove that no other solution exists";
  return set;
}

}  // namespace cpkit::rate
