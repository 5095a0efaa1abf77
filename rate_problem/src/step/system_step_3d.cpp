// One implicit step of N coupled 3-D contact points (system_step_3d.hpp): residual, semismooth
// Newton on the per-point FB / SOC-FB functions (fischer_burmeister.hpp, as one point) and a
// multistart. Everything runs in units normalized by the system's force and stiffness scales;
// every answer is verified on the original problem by system_step_3d_residual.
#include "cpkit/rate_problem/step/system_step_3d.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "step_3d_terms.hpp"
#include "step_3d_newton.hpp"
#include "step_3d_normalized.hpp"
#include "step_3d_verdict.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

/// The system's units (step_3d_units): forces F0, stiffness K0, lengths L0 = F0 / K0.
detail::Units scales_of(const SystemStep3dProblem& p) noexcept {
  return detail::step_3d_units(p.system.A, p.DF, p.states.data(), p.states.size());
}

bool sizes_ok(const SystemStep3dProblem& p) noexcept {
  const int N = p.n_points();
  return N >= 1 && p.system.A.rows() == 3 * N && p.system.A.cols() == 3 * N &&
         static_cast<int>(p.states.size()) == N && p.DF.size() == 3 * N;
}

/// `ellipse`: detail::ellipse_unit of the point's alpha (the multiplier's unit).
Step3dValues normalized_values(const Step3dValues& v, const detail::Units& s, double ellipse) noexcept {
  const double length = 1 / s.length;
  return detail::scaled_values(v, 1 / s.force, length, length / ellipse);
}

using Normalized = detail::Normalized3d<Eigen::Dynamic>;

Normalized normalize(const SystemStep3dProblem& pr) {
  return detail::normalize_3d<Eigen::Dynamic>(scales_of(pr), pr.system.A, pr.DF, pr.n_points(),
                                              [&pr](int i) { return pr.point_problem(i); });
}

std::vector<Step3dValues> physical(const SystemStep3dProblem& pr, const Normalized& n,
                                   const Vec& z) {
  Vec P1(3 * n.N), lam(n.N);
  for (int i = 0; i < n.N; ++i) {
    P1.segment<3>(3 * i) = n.F0 * z.segment<3>(4 * i);
    lam(i) = n.L0 * n.E(i) * z(4 * i + 3);
  }
  return system_step_3d_values(pr, P1, lam);
}

/// The verdict, as finalize_step_3d (step_3d_verdict.hpp): the solution recomputed from the
/// values and the data, judged by system_step_3d_residual.
void finalize_system(const SystemStep3dProblem& pr, const std::vector<Step3dValues>& values,
                     SystemStep3dSolveResult& r, const CommonOptions& o) {
  r.solution = make_system_step_3d_solution(pr, values);
  detail::decide_step_3d(r, values.data(), values.size(), r.solution.residual, o);
}

/// The N-point kernel of the shared Newton solve (step_3d_newton.hpp).
struct SystemKernel : detail::NormalizedKernel3d<Eigen::Dynamic> {
  const SystemStep3dProblem& pr;
  double residual(const Vec& z) const { return system_step_3d_residual(pr, physical(pr, n, z)); }
  void finalize(const Vec& z, SystemStep3dSolveResult& out, const CommonOptions& o) const {
    finalize_system(pr, physical(pr, n, z), out, o);
  }
};

void check(const SystemStep3dProblem& pr) { throw_if_invalid(pr.validate(), "step"); }

bool same_solution(const SystemStep3dSolution& a, const SystemStep3dSolution& b, double F0) {
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (!detail::same_point_solution_3d(a.points[i].values, b.points[i].values, F0)) return false;
  return true;
}

}  // namespace

std::string SystemStep3dProblem::validate() const {
  const int N = n_points();
  if (N < 1) return "the system has no points";
  if (system.A.rows() != 3 * N || system.A.cols() != 3 * N)
    return "A is " + std::to_string(system.A.rows()) + " x " + std::to_string(system.A.cols()) +
           ", expected 3N x 3N = " + std::to_string(3 * N) + " x " + std::to_string(3 * N);
  if (static_cast<int>(states.size()) != N)
    return std::to_string(states.size()) + " start states for " + std::to_string(N) + " points";
  if (DF.size() != 3 * N)
    return "DF has " + std::to_string(DF.size()) + " entries, expected 3N = " + std::to_string(3 * N);
  if (!system.A.allFinite()) return "A is not finite";
  const double a = system.A.cwiseAbs().maxCoeff();
  if (!((system.A - system.A.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * a))
    return "A is not symmetric";
  const Eigen::LDLT<Mat> ldlt(system.A / a);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() ||
      !(ldlt.vectorD().minCoeff() > 1e-14 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    return "A is not positive definite";
  for (int i = 0; i < N; ++i)
    if (const std::string e = point_problem(i).validate(); !e.empty())
      return "point " + std::to_string(i + 1) + ": " + e;
  return {};
}

Step3dProblem SystemStep3dProblem::point_problem(int i) const {
  Step3dProblem p;
  p.params = system.point_parameters(i);
  p.wear = wear;
  p.state = states.at(static_cast<std::size_t>(i));
  p.DF = DF.segment<3>(3 * i);
  return p;
}

std::vector<Step3dValues> system_step_3d_values(const SystemStep3dProblem& p, const Vec& P1,
                                                const Vec& lambda) {
  const int N = p.n_points();
  if (!sizes_ok(p) || P1.size() != 3 * N || lambda.size() != N)
    throw InputError("step: system_step_3d_values: sizes do not match the system (N = " +
                     std::to_string(N) + ")");
  Vec P0(3 * N);
  for (int i = 0; i < N; ++i) {
    const Step3dState& s = p.states[static_cast<std::size_t>(i)];
    P0.segment<3>(3 * i) << s.P_T0, s.P_N0;
  }
  const Vec DP = P1 - P0;
  const Vec Dw = p.system.A.ldlt().solve(p.DF - DP);
  std::vector<Step3dValues> out(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    const Step3dProblem q = p.point_problem(i);
    Step3dValues& v = out[static_cast<std::size_t>(i)];
    v.P_T1 = P1.segment<2>(3 * i);
    v.P_N1 = P1(3 * i + 2);
    v.lambda = lambda(i);
    v.DP_T = DP.segment<2>(3 * i);
    v.DP_N = DP(3 * i + 2);
    v.Dw_T = Dw.segment<2>(3 * i);
    v.Dw_N = Dw(3 * i + 2);
    v.Dw_Ti = v.Dw_T - q.params.C_T * v.DP_T;
    v.Dw_w = q.wear_coefficient() * std::max(v.P_N1, 0.0) * v.lambda;
    v.g1 = q.state.g0 + v.Dw_N - v.Dw_w;
  }
  return out;
}

namespace {
/// Per-point local terms and the equilibrium term (normalized units); false for wrong sizes.
bool residual_terms(const SystemStep3dProblem& p, const std::vector<Step3dValues>& values,
                    std::vector<double>& local, double& equilibrium) {
  const int N = p.n_points();
  if (!sizes_ok(p) || static_cast<int>(values.size()) != N) return false;
  const detail::Units s = scales_of(p);
  Vec DP(3 * N), Dw(3 * N);
  local.assign(static_cast<std::size_t>(N), 0.0);
  for (int i = 0; i < N; ++i) {
    const Step3dValues v = normalized_values(values[static_cast<std::size_t>(i)], s,
                                             detail::ellipse_unit(p.system.points[static_cast<std::size_t>(i)].alpha));
    local[static_cast<std::size_t>(i)] =
        detail::local_step_3d_residual(detail::normalized_step_3d(p.point_problem(i), s), v);
    DP.segment<3>(3 * i) << v.DP_T, v.DP_N;
    Dw.segment<3>(3 * i) << v.Dw_T, v.Dw_N;
  }
  const Mat A = p.system.A / s.stiffness;
  const Vec eq = p.DF / s.force - DP - A * Dw;
  equilibrium = eq.cwiseAbs().maxCoeff() /
                (1 + DP.cwiseAbs().maxCoeff() + (A.cwiseAbs() * Dw.cwiseAbs()).maxCoeff());
  if (!std::isfinite(equilibrium)) equilibrium = kInf;
  return true;
}
}  // namespace

double system_step_3d_residual(const SystemStep3dProblem& p,
                               const std::vector<Step3dValues>& values) noexcept {
  try {
    std::vector<double> local;
    double eq = kInf;
    if (!residual_terms(p, values, local, eq)) return kInf;
    double r = eq;
    for (double x : local) r = std::isfinite(x) ? std::max(r, x) : kInf;
    return r;
  } catch (...) {
    return kInf;
  }
}

SystemStep3dSolution make_system_step_3d_solution(const SystemStep3dProblem& p,
                                                  const std::vector<Step3dValues>& values) {
  SystemStep3dSolution out;
  std::vector<double> local;
  double eq = kInf;
  if (!residual_terms(p, values, local, eq))
    throw InputError("step: make_system_step_3d_solution: sizes do not match the system");
  const detail::Units s = scales_of(p);
  out.residual = eq;
  for (int i = 0; i < p.n_points(); ++i) {
    const Step3dValues& uv = values[static_cast<std::size_t>(i)];
    const Step3dValues v =
        normalized_values(uv, s, detail::ellipse_unit(p.system.points[static_cast<std::size_t>(i)].alpha));
    Step3dSolution sol;
    sol.values = uv;
    sol.type = detail::classify_normalized_step_3d(v, p.states[static_cast<std::size_t>(i)].g0);
    sol.residual = local[static_cast<std::size_t>(i)];
    detail::set_slip_direction(sol);
    out.residual = std::isfinite(sol.residual) ? std::max(out.residual, sol.residual) : kInf;
    out.points.push_back(sol);
  }
  return out;
}

SystemStep3dSolveResult solve_system_step_3d_fb_soc(const SystemStep3dProblem& problem,
                                                    const CommonOptions& options,
                                                     const std::vector<Step3dStart>* start) {
  check(problem);
  throw_if_invalid(options.validate(), "options");
  const auto t0 = std::chrono::steady_clock::now();
  const Normalized n = normalize(problem);
  if (start != nullptr && static_cast<int>(start->size()) != n.N)
    throw InputError("start: " + std::to_string(start->size()) + " start points for " +
                     std::to_string(n.N) + " points");
  const Vec z = start == nullptr ? n.z0 : detail::normalized_start_3d(n, start->data());
  SystemStep3dSolveResult out;
  out.solver = "fb-soc";
  detail::newton_3d<Vec, Mat>(SystemKernel{{n}, problem}, z, options, out);
  out.seconds = detail::seconds_since(t0);
  return out;
}

SystemStep3dSolutionSet multistart_system_step_3d(const SystemStep3dProblem& problem,
                                                  int n_starts, std::uint64_t seed) {
  check(problem);
  if (n_starts < 0) throw InputError("n_starts must be >= 0");
  const Normalized n = normalize(problem);
  std::mt19937_64 rng(seed);
  const CommonOptions o = step_3d_solver_options();
  std::vector<SystemStep3dSolution> sols;
  int ok = 0;
  for (int i = 0; i <= n_starts; ++i) {
    const Vec z = i == 0 ? n.z0 : detail::random_start_3d<Vec>(SystemKernel{{n}, problem}, rng);
    SystemStep3dSolveResult r;
    detail::newton_3d<Vec, Mat>(SystemKernel{{n}, problem}, z, o, r);
    if (r.status != Status::kSolved) continue;
    ++ok;
    detail::add_distinct(sols, r.solution,
                         [&n](const SystemStep3dSolution& a, const SystemStep3dSolution& b) {
                           return same_solution(a, b, n.F0);
                         });
  }
  SystemStep3dSolutionSet set;
  set.solutions = std::move(sols);
  set.complete = false;
  set.message = "multistart (" + std::to_string(ok) + "/" + std::to_string(n_starts + 1) +
                " FB-SOC runs verified): distinct verified solutions; local solvers cannot "
                "prove that no other solution exists";
  return set;
}

}  // namespace cpkit::rate
