#include "cpkit/rate_problem/step/step_enumeration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/LU>

#include "cpkit/core/errors.hpp"
#include "polynomial_roots.hpp"
#include "../model/unit_scaling.hpp"

namespace cpkit::rate {
namespace {

constexpr double kDegTol = 1e-12;  // relative size under which a coefficient is zero

/// Everything the pieces need, computed once per problem (the parameters themselves are read
/// from StepProblem::params).
struct Setup {
  double detA, D0, e, S, T, cw, kc;
  double P0, PT0, g0;
  double fscale, dscale;
};

Setup make_setup(const StepProblem& p) noexcept {
  const ContactParameters& a = p.params;
  Setup s;
  s.detA = a.detA();
  s.D0 = a.D0();
  s.e = 1 + a.a11 * a.C_T;
  s.S = s.e * p.load.dF_N - a.a12 * a.C_T * p.load.dF_T;
  s.T = a.a22 * p.load.dF_T - a.a12 * p.load.dF_N;
  s.cw = p.wear_coefficient();
  s.kc = p.softening();
  s.P0 = std::max(p.state.P_N0, 0.0);
  s.PT0 = p.state.P_T0;
  s.g0 = p.state.g0;
  s.fscale = std::max({std::abs(s.PT0), s.P0, std::abs(p.load.dF_T), std::abs(p.load.dF_N),
                       std::numeric_limits<double>::min()});
  s.dscale = std::abs(s.g0) + s.fscale * ((a.a11 + a.a22) / s.detA + a.C_T);
  return s;
}

struct Continuum {
  SolutionType type;
  int s;
  double x_lo, x_hi;  // x_hi may be +inf (ray)
  double b0, b1;      // xi(x) = s (b0 + b1 x) / detA
};

// ---- Units: exact power-of-two normalisation (forces 2^force_exp, stiffness 2^stiffness_exp,
// lengths 2^length_exp(); detail::Units) ----

using detail::Units;

int exponent_of(double v) noexcept {  // 2^e <= v < 2^(e+1) for finite v > 0
  int e = 0;
  std::frexp(v, &e);
  return e - 1;
}

Units units_of(const StepProblem& p) noexcept {
  Units u;
  u.stiffness_exp = exponent_of(std::max(p.params.a11, p.params.a22));
  const double f = std::max({std::abs(p.state.P_T0), std::abs(p.state.P_N0),
                             std::abs(p.load.dF_T), std::abs(p.load.dF_N)});
  if (f > 0) {
    u.force_exp = exponent_of(f);
  } else if (p.state.g0 != 0) {
    u.force_exp = u.stiffness_exp + exponent_of(std::abs(p.state.g0));  // no force at all: lengths of order 1
  }
  return u;
}

/// x 2^e: a multiplication by the exact factor when 2^e is a normal double (fast, and exact
/// like ldexp unless the result leaves the normal range, where both round), else ldexp.
struct Pow2 {
  int e;
  double f;
  explicit Pow2(int e_) noexcept : e(e_), f(e_ >= -1000 && e_ <= 1000 ? std::ldexp(1.0, e_) : 0) {}
  double operator()(double x) const noexcept { return f != 0 ? x * f : std::ldexp(x, e); }
};

/// The problem in the units `u` (every scaling a power of two: exact unless a value leaves
/// double's range; a wear coefficient that underflows there is 0 to working precision).
StepProblem normalise(const StepProblem& p, const Units& u) noexcept {
  StepProblem n = p;
  if (u.force_exp == 0 && u.stiffness_exp == 0) return n;
  const Pow2 dA(-u.stiffness_exp), uA(u.stiffness_exp), dF(-u.force_exp), uF(u.force_exp),
      dL(-u.length_exp());
  n.params.a11 = dA(p.params.a11);
  n.params.a12 = dA(p.params.a12);
  n.params.a22 = dA(p.params.a22);
  n.params.C_T = uA(p.params.C_T);  // length/force
  n.params.P_s = dF(p.params.P_s);  // k = k_a / (3 P_s): 1/force
  n.wear.k_M = uF(p.wear.k_M);      // 1/force
  if (!std::isfinite(n.params.P_s)) {
    n.params.k_a = 0;
    n.params.P_s = 1;
  }
  n.state.P_T0 = dF(p.state.P_T0);
  n.state.P_N0 = dF(p.state.P_N0);
  n.state.g0 = dL(p.state.g0);
  n.load.dF_T = dF(p.load.dF_T);
  n.load.dF_N = dF(p.load.dF_N);
  return n;
}

/// Values of the normalised problem in the caller's units.
StepValues to_user(const StepValues& v, const Units& u) noexcept {
  if (u.force_exp == 0 && u.stiffness_exp == 0) return v;
  const Pow2 F(u.force_exp), L(u.length_exp());
  StepValues w;
  w.DP_T = F(v.DP_T);
  w.DP_N = F(v.DP_N);
  w.P_T1 = F(v.P_T1);
  w.P_N1 = F(v.P_N1);
  w.Dw_T = L(v.Dw_T);
  w.Dw_N = L(v.Dw_N);
  w.Dw_Ti = L(v.Dw_Ti);
  w.Dw_w = L(v.Dw_w);
  w.g1 = L(v.g1);
  return w;
}

bool all_finite(const StepValues& v) noexcept {
  for (double x : {v.DP_T, v.DP_N, v.Dw_T, v.Dw_N, v.Dw_Ti, v.Dw_w, v.P_T1, v.P_N1, v.g1})
    if (!std::isfinite(x)) return false;
  return true;
}

// ---- Verification of a candidate against the model's own equations (unit-free) ----

constexpr double kAccept = 1e-12;  // backward error at or below which a candidate is accepted
constexpr double kEps = std::numeric_limits<double>::epsilon();

enum Piece { kPieceSep = 0, kPieceStick = 1, kPieceSlipPlus = 2, kPieceSlipMinus = 3 };

/// A candidate: u = (DP_T, DP_N, Dw_T, Dw_N, Dw_Ti) in normalised units.
/// (No default member initialisers: Work holds eight of them per call on the hot path; every
/// field is set before use.)
struct Candidate {
  int piece;
  double u[5];
  double backward;  ///< unit-free backward error (equations and sign conditions)
  double ftol;      ///< relative forward tolerance (from the conditioning)
  double fs, ds;    ///< force and displacement scales (scales_of) after polishing
};

double ratio(double num, double den) noexcept {
  if (!(num > 0)) return 0;
  return den > 0 ? num / den : INFINITY;
}

/// Residuals r and term magnitudes t of the five equations of the piece (equilibrium T, N,
/// compatibility, the two active conditions); the Jacobian when J is set.
void piece_equations(const StepProblem& n, int piece, const double u[5], double r[5], double t[5],
                     Eigen::Matrix<double, 5, 5>* J) noexcept {
  const ContactParameters& a = n.params;
  const double DPT = u[0], DPN = u[1], DwT = u[2], DwN = u[3], xi = u[4];
  const double fT = n.load.dF_T, fN = n.load.dF_N, P0 = n.state.P_N0, PT0 = n.state.P_T0;
  const double g0 = n.state.g0, mu = a.mu, kc = n.softening(), cw = n.wear_coefficient();
  const double P1 = P0 + DPN, PT1 = PT0 + DPT, Pt = P0 + std::abs(DPN);
  r[0] = a.a11 * DwT + a.a12 * DwN + DPT - fT;
  t[0] = std::abs(a.a11 * DwT) + std::abs(a.a12 * DwN) + std::abs(DPT) + std::abs(fT);
  r[1] = a.a12 * DwT + a.a22 * DwN + DPN - fN;
  t[1] = std::abs(a.a12 * DwT) + std::abs(a.a22 * DwN) + std::abs(DPN) + std::abs(fN);
  r[2] = DwT - a.C_T * DPT - xi;
  t[2] = std::abs(DwT) + std::abs(a.C_T * DPT) + std::abs(xi);
  if (J != nullptr) {
    J->setZero();
    (*J)(0, 0) = 1;
    (*J)(0, 2) = a.a11;
    (*J)(0, 3) = a.a12;
    (*J)(1, 1) = 1;
    (*J)(1, 2) = a.a12;
    (*J)(1, 3) = a.a22;
    (*J)(2, 2) = 1;
    (*J)(2, 0) = -a.C_T;
    (*J)(2, 4) = -1;
  }
  switch (piece) {
    case kPieceSep:  // P_N1 = 0, P_T1 = 0
      r[3] = P1;
      t[3] = Pt;
      r[4] = PT1;
      t[4] = std::abs(PT0) + std::abs(DPT);
      if (J != nullptr) {
        (*J)(3, 1) = 1;
        (*J)(4, 0) = 1;
      }
      break;
    case kPieceStick:  // Dw_T^i = 0, g1 = 0
      r[3] = xi;
      t[3] = std::abs(xi) + std::abs(DwT) + std::abs(a.C_T * DPT);
      r[4] = g0 + DwN;
      t[4] = std::abs(g0) + std::abs(DwN);
      if (J != nullptr) {
        (*J)(3, 4) = 1;
        (*J)(4, 3) = 1;
      }
      break;
    default: {  // slip s: s P_T1 = Y(P_N1), g1 = g0 + Dw_N - c_w P_N1 s Dw_T^i = 0
      const double s = piece == kPieceSlipPlus ? 1.0 : -1.0;
      r[3] = s * PT1 - (mu * P1 - kc * P1 * P1);
      t[3] = std::abs(PT0) + std::abs(DPT) + mu * Pt + kc * Pt * Pt;
      r[4] = g0 + DwN - cw * P1 * s * xi;
      t[4] = std::abs(g0) + std::abs(DwN) + std::abs(cw * P1 * xi);
      if (J != nullptr) {
        (*J)(3, 0) = s;
        (*J)(3, 1) = -(mu - 2 * kc * P1);
        (*J)(4, 3) = 1;
        (*J)(4, 1) = -cw * s * xi;
        (*J)(4, 4) = -cw * P1 * s;
      }
    }
  }
}

/// The candidate's force and displacement scales: the largest force of the step (state, load,
/// increments) and the largest displacement (its own, g0, or what those forces move the
/// stiffest direction by). Conditions on computed unknowns are judged against these (a
/// normwise backward error: a quantity that should be 0 comes out as rounding of this size).
void scales_of(const StepProblem& n, const double u[5], double& fs, double& ds) noexcept {
  fs = std::max({std::abs(n.state.P_T0), n.state.P_N0, std::abs(n.load.dF_T),
                 std::abs(n.load.dF_N), std::abs(u[0]), std::abs(u[1])});
  ds = std::max({std::abs(u[2]), std::abs(u[3]), std::abs(u[4]), std::abs(n.state.g0),
                 std::abs(n.params.C_T * u[0]), fs / (n.params.a11 + n.params.a22)});
}

/// Backward error of the piece's equations (rows 0, 1, 4... in force units, 2 and the
/// displacement rows in length units), each relative to its terms or the scale of its kind.
double equation_error(const StepProblem& n, int piece, const double u[5], double fs,
                      double ds) noexcept {
  double r[5], t[5];
  piece_equations(n, piece, u, r, t, nullptr);
  // Which rows are in length units: compatibility (2), and for stick xi = 0 (3) and the gap
  // rows g1 = 0 (4) of stick and slip.
  const bool len[5] = {false, false, true, piece == kPieceStick, piece != kPieceSep};
  double e = 0;
  for (int i = 0; i < 5; ++i) e = std::max(e, ratio(std::abs(r[i]), std::max(t[i], len[i] ? ds : fs)));
  return e;
}

double equation_error(const StepProblem& n, int piece, const double u[5]) noexcept {
  double fs, ds;
  scales_of(n, u, fs, ds);
  return equation_error(n, piece, u, fs, ds);
}

/// Violations of the piece's sign conditions, relative to the candidate's scales.
double sign_error(const StepProblem& n, int piece, const double u[5], double fs,
                  double ds) noexcept {
  const double DPT = u[0], DPN = u[1], DwN = u[3], xi = u[4];
  const double P0 = n.state.P_N0, PT0 = n.state.P_T0, g0 = n.state.g0;
  const double mu = n.params.mu, kc = n.softening();
  const double P1 = P0 + DPN, PT1 = PT0 + DPT, Pt = P0 + std::abs(DPN);
  const double Y = mu * P1 - kc * P1 * P1, Yt = mu * Pt + kc * Pt * Pt;
  (void)fs;
  // Force conditions per direction: a normal force is judged against the normal forces of the
  // step, a friction margin against the tangential ones (a load of 1e6 along T must not excuse
  // a P_N1 of -1e-6 when the normal forces are of order 1e3).
  const double fN = std::max({P0, std::abs(DPN), std::abs(n.load.dF_N)});
  const double fT = std::max({std::abs(PT0), std::abs(DPT), std::abs(n.load.dF_T), Yt});
  double e = 0;
  switch (piece) {
    case kPieceSep:  // g1 <= 0 (no wear at P_N1 = 0)
      e = ratio(g0 + DwN, ds);
      break;
    case kPieceStick:  // P_N1 >= 0, |P_T1| <= Y
      e = std::max(ratio(-P1, fN), ratio(std::abs(PT1) - Y, fT));
      break;
    default: {  // P_N1 >= 0, s Dw_T^i >= 0, Y >= 0
      const double s = piece == kPieceSlipPlus ? 1.0 : -1.0;
      e = std::max({ratio(-P1, fN), ratio(-s * xi, ds), ratio(-Y, std::max(fN, Yt))});
    }
  }
  return e;
}

double sign_error(const StepProblem& n, int piece, const double u[5]) noexcept {
  double fs, ds;
  scales_of(n, u, fs, ds);
  return sign_error(n, piece, u, fs, ds);
}

/// Polishes u by Newton steps on the piece's equations (rows scaled by their terms, LU with
/// partial pivoting), then sets the backward error and the forward tolerance.
void refine(const StepProblem& n, Candidate& c) noexcept {
  // The piece's own two conditions are imposed exactly (to rounding of their formulas).
  auto snap = [&](double* u) {
    // (0.0 - x: no negative zeros in the output)
    const double P1 = n.state.P_N0 + u[1];
    if (c.piece == kPieceSep) {
      u[0] = 0.0 - n.state.P_T0;
      u[1] = 0.0 - n.state.P_N0;
    } else if (c.piece == kPieceStick) {
      u[4] = 0;
      u[3] = 0.0 - n.state.g0;
    } else {
      const double s = c.piece == kPieceSlipPlus ? 1.0 : -1.0;
      u[0] = s * (n.params.mu * P1 - n.softening() * P1 * P1) - n.state.P_T0;
      u[3] = n.wear_coefficient() * P1 * s * u[4] - n.state.g0;
    }
  };
  snap(c.u);
  double err = equation_error(n, c.piece, c.u);
  Eigen::Matrix<double, 5, 5> J;
  double rcond = 1;
  // Already at the rounding level (the usual case for well-conditioned data, and the
  // simulation's hot path): no factorisation, forward tolerance 1e-9.
  const bool polished = err <= 64 * kEps;
  for (int it = 0; it < 4 && !polished; ++it) {
    double r[5], t[5];
    piece_equations(n, c.piece, c.u, r, t, &J);
    Eigen::Matrix<double, 5, 1> rhs;
    for (int i = 0; i < 5; ++i) {
      const double w = t[i] > 0 ? 1.0 / t[i] : 1.0;
      J.row(i) *= w;
      rhs(i) = -r[i] * w;
    }
    // Columns in the candidate's own magnitudes: forces and displacements.
    double fs = std::max({std::abs(n.state.P_T0), n.state.P_N0, std::abs(n.load.dF_T),
                          std::abs(n.load.dF_N), std::abs(c.u[0]), std::abs(c.u[1])});
    double ds = std::max({std::abs(c.u[2]), std::abs(c.u[3]), std::abs(c.u[4]),
                          std::abs(n.state.g0)});
    if (!(fs > 0)) fs = 1;
    if (!(ds > 0)) ds = fs;
    const double cs[5] = {fs, fs, ds, ds, ds};
    for (int j = 0; j < 5; ++j) J.col(j) *= cs[j];
    const Eigen::PartialPivLU<Eigen::Matrix<double, 5, 5>> lu(J);
    rcond = lu.rcond();
    if (err <= 4 * kEps || !(rcond > 0) || !std::isfinite(rcond)) break;
    const Eigen::Matrix<double, 5, 1> du = lu.solve(rhs);
    double trial[5];
    for (int j = 0; j < 5; ++j) trial[j] = c.u[j] + du(j) * cs[j];
    snap(trial);
    const double e2 = equation_error(n, c.piece, trial);
    if (!(e2 < err)) break;
    std::copy(trial, trial + 5, c.u);
    err = e2;
  }
  scales_of(n, c.u, c.fs, c.ds);
  c.backward = std::max(err, sign_error(n, c.piece, c.u, c.fs, c.ds));
  // Forward error of the unknowns relative to their magnitudes: backward error / rcond.
  c.ftol = polished ? 1e-9 : std::max(1e-9, 16 * std::max(c.backward, kEps) / std::max(rcond, 1e-300));
}

StepValues values_of(const StepProblem& n, const double u[5]) noexcept {
  StepValues v;
  v.DP_T = u[0];
  v.DP_N = u[1];
  v.Dw_T = u[2];
  v.Dw_N = u[3];
  v.Dw_Ti = u[4];
  v.P_T1 = n.state.P_T0 + u[0];
  v.P_N1 = n.state.P_N0 + u[1];
  v.Dw_w = n.wear_coefficient() * std::max(v.P_N1, 0.0) * std::abs(u[4]);
  v.g1 = n.state.g0 + u[3] - v.Dw_w;
  return v;
}

/// Type of an accepted candidate: its piece, except at the ends of the pieces, where a
/// quantity at the rounding level of the candidate's own scales (scales_of) counts as 0.
SolutionType type_of(const StepProblem& n, const Candidate& c) noexcept {
  constexpr double kTypeTol = 1e-9;
  const double* u = c.u;
  const double fs = c.fs, ds = c.ds;
  const double P1 = n.state.P_N0 + u[1];
  const bool open = step_started_open(n);
  auto by_slip = [&]() {
    if (std::abs(u[4]) <= kTypeTol * ds) return SolutionType::kStick;
    return u[4] > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
  };
  if (c.piece == kPieceSep) {
    if (open) return SolutionType::kOpen;
    if (n.state.g0 + u[3] < -kTypeTol * ds) return SolutionType::kSeparation;
    return by_slip();  // grazing end: the rate problem's zero-force stick/slip
  }
  if (open && P1 <= kTypeTol * fs) return SolutionType::kOpen;
  if (c.piece == kPieceStick) return SolutionType::kStick;
  return by_slip();
}

/// Same physical point (within both candidates' forward tolerances)?
bool same_point(const StepProblem& n, const Candidate& a, const Candidate& b) noexcept {
  const double tol = std::min(1e-6, std::max(a.ftol, b.ftol));
  const double fs = std::max({std::abs(n.state.P_T0), n.state.P_N0, std::abs(n.load.dF_T),
                              std::abs(n.load.dF_N), std::abs(a.u[0]), std::abs(a.u[1]),
                              std::abs(b.u[0]), std::abs(b.u[1])});
  const double ds = std::max(a.ds, b.ds);
  for (int j = 0; j < 5; ++j)
    if (std::abs(a.u[j] - b.u[j]) > tol * (j < 2 ? fs : ds)) return false;
  return true;
}

struct Work {
  StepPoints pts;                           // normalised units
  std::array<Candidate, kMaxStepPoints> cand;  // the accepted candidates behind pts
  Continuum cont[2];
  int ncont = 0;
};

/// Adds a candidate (x = DP_N, xi) of `piece` after polishing, judging and de-duplication.
void try_point(const StepProblem& n, int piece, double x, double xi, double tol,
               Work& w) noexcept {
  if (!std::isfinite(x) || !std::isfinite(xi)) return;
  Candidate c;
  c.piece = piece;
  c.backward = INFINITY;
  c.ftol = 1e-9;
  const StepValues v0 = step_values(n, x, xi);
  c.u[0] = v0.DP_T;
  c.u[1] = v0.DP_N;
  c.u[2] = v0.Dw_T;
  c.u[3] = v0.Dw_N;
  c.u[4] = v0.Dw_Ti;
  // A sign condition violated by 25 % of its scale is not a rounding matter: polishing moves
  // the point by its forward error only, so such a candidate is rejected as it is.
  if (sign_error(n, piece, c.u) > std::max(0.25, tol)) return;
  refine(n, c);
  if (!(c.backward <= kAccept)) {
    if (!(c.backward > tol)) ++w.pts.undecided;  // neither accepted nor rejected
    return;
  }
  StepPoints& out = w.pts;
  for (int i = 0; i < out.n; ++i)
    if (same_point(n, w.cand[i], c)) return;
  if (out.n >= kMaxStepPoints) return;
  StepPoint pt;
  pt.type = type_of(n, c);
  pt.DP_N = c.u[1];
  pt.xi = c.u[4];
  w.cand[out.n] = c;
  out.points[out.n++] = pt;
}

/// Every candidate of the normalised problem `p` (normalise()).
void enumerate_core(const StepProblem& p, double tol, Work& w) noexcept {
  const Setup st = make_setup(p);
  const ContactParameters& a = p.params;
  w.pts.n = 0;
  w.pts.infinite = false;
  w.pts.undecided = 0;
  w.pts.unrepresentable = 0;
  w.ncont = 0;
  // 1. P_N1 = 0: P_T1 = 0 fixes xi.
  {
    const double x = -st.P0;
    const double xi = (st.D0 * st.PT0 + st.T - a.a12 * st.P0) / st.detA;
    try_point(p, kPieceSep, x, xi, tol, w);
  }
  // 2. stick: g1 = 0 with xi = 0.
  {
    const double x = (st.D0 * st.g0 + st.S) / st.e;
    try_point(p, kPieceStick, x, 0.0, tol, w);
  }
  // 3. slip s = +1, -1.
  for (int s = 1; s >= -1; s -= 2) {
    const double Y0 = a.mu * st.P0 - st.kc * st.P0 * st.P0;
    const double margin = Y0 - s * st.PT0;
    const double b0 = -st.D0 * margin + s * st.T;
    const double b1 = s * a.a12 - st.D0 * a.mu + 2 * st.D0 * st.kc * st.P0;
    const double b2 = st.D0 * st.kc;
    const double sb0 = st.D0 * (a.mu * st.P0 + st.kc * st.P0 * st.P0 + std::abs(st.PT0)) +
                       std::abs(a.a22 * p.load.dF_T) + std::abs(a.a12 * p.load.dF_N);
    const double sb1 = std::abs(a.a12) + st.D0 * a.mu + 2 * st.D0 * st.kc * st.P0;
    const double sb2 = b2;
    const double a0 = st.D0 * st.g0 + st.S;
    const double a1 = -st.e;
    const double a2 = -s * a.a12 - st.D0 * st.cw * st.P0;
    const double a3 = -st.D0 * st.cw;
    const double sa0 = st.D0 * std::abs(st.g0) + st.e * std::abs(p.load.dF_N) +
                       std::abs(a.a12 * a.C_T * p.load.dF_T);
    const double sa1 = st.e;
    const double sa2 = std::abs(a.a12) + st.D0 * st.cw * st.P0;
    const double sa3 = -a3;
    const double c[4] = {st.detA * a0 + a2 * b0, st.detA * a1 + a2 * b1 + a3 * b0,
                         a3 * b1 + a2 * b2, a3 * b2};
    const double sc[4] = {st.detA * sa0 + sa2 * sb0, st.detA * sa1 + sa2 * sb1 + sa3 * sb0,
                          sa3 * sb1 + sa2 * sb2, sa3 * sb2};
    const SolutionType type = s > 0 ? SolutionType::kSlipPlus : SolutionType::kSlipMinus;
    double roots[4];
    int nr;
    const double x_lo = -st.P0;
    if (c[3] != 0) {
      const double x_hi = a.mu / st.kc - st.P0;  // Y(P_N1) >= 0, condition (46)
      nr = detail::cubic_roots_in(c, sc, x_lo, x_hi, roots);
    } else {
      nr = stable_quadratic_roots(c[2], c[1], c[0], sc[2], sc[1], sc[0], kDegTol, roots);
    }
    if (nr < 0) {
      // The gap row holds identically along the friction row: a continuum in x >= -P0 with
      // l(x) = (b0 + b1 x)/detA >= 0 (b2 = 0 here: the cubic case never degenerates).
      const bool b1_zero = std::abs(b1) <= kDegTol * sb1;
      double lo = x_lo, hi = std::numeric_limits<double>::infinity();
      bool empty = false;
      if (b1_zero) {
        if (b0 < -kDegTol * sb0) empty = true;
      } else if (b1 > 0) {
        lo = std::max(lo, -b0 / b1);
      } else {
        hi = -b0 / b1;
        if (hi < lo - 1e-12 * st.fscale) empty = true;
      }
      if (!empty) {
        if (std::isfinite(hi) && hi - lo <= 1e-12 * st.fscale) {
          const double xm = std::max(lo, hi);
          try_point(p, s > 0 ? kPieceSlipPlus : kPieceSlipMinus, xm, s * (b0 + b1 * xm) / st.detA, tol, w);
        } else if (w.ncont < 2) {
          w.cont[w.ncont++] = Continuum{type, s, lo, hi, b0, b1_zero ? 0.0 : b1};
          w.pts.infinite = true;
        }
      }
      continue;
    }
    for (int i = 0; i < nr; ++i) {
      const double x = roots[i];
      if (st.P0 + x < -1e-6 * st.fscale) continue;  // clearly outside: refine() judges the rest
      const double l = ((b2 * x + b1) * x + b0) / st.detA;
      try_point(p, s > 0 ? kPieceSlipPlus : kPieceSlipMinus, x, s * l, tol, w);
    }
  }
}

double distance(const StepValues& v) noexcept { return std::abs(v.DP_N) + std::abs(v.DP_T); }

/// The continua of `w` as segments or rays of the set (conts), and their ends that are open
/// (of another type: stick where xi = 0, open where P_N1 = 0 after an open start), which are
/// listed as points of their own type (the partition of piece_geometry.hpp).
void continuum_solutions(const StepProblem& n, const Setup& st, Work& w,
                         std::vector<StepSolution>& conts, std::vector<StepValues>& open_ends) {
  for (int i = 0; i < w.ncont; ++i) {
    const Continuum& c = w.cont[i];
    const int piece = c.s > 0 ? kPieceSlipPlus : kPieceSlipMinus;
    // An end judged without polishing (the piece's Jacobian is singular along a continuum).
    auto judge = [&](double x, StepValues& v) {
      v = step_values(n, x, c.s * (c.b0 + c.b1 * x) / st.detA);
      Candidate k;
      k.piece = piece;
      k.ftol = 1e-9;
      const double u[5] = {v.DP_T, v.DP_N, v.Dw_T, v.Dw_N, v.Dw_Ti};
      std::copy(u, u + 5, k.u);
      scales_of(n, k.u, k.fs, k.ds);
      k.backward = std::max(equation_error(n, piece, k.u), sign_error(n, piece, k.u));
      if (!(k.backward <= kAccept)) ++w.pts.undecided;  // an end not verified
      return k;
    };
    StepSolution sol;
    sol.type = c.type;
    const Candidate k0 = judge(c.x_lo, sol.start);
    sol.residual = k0.backward;
    sol.start_closed = type_of(n, k0) == c.type;
    if (!sol.start_closed) open_ends.push_back(sol.start);
    if (std::isfinite(c.x_hi)) {
      sol.kind = RateSolution::Kind::kSegment;
      const Candidate k1 = judge(c.x_hi, sol.end);
      sol.residual = std::max(sol.residual, k1.backward);
      sol.end_closed = type_of(n, k1) == c.type;
      if (!sol.end_closed) open_ends.push_back(sol.end);
    } else {
      sol.kind = RateSolution::Kind::kRay;
      const StepValues v1 = step_values(n, c.x_lo + 1.0, c.s * (c.b0 + c.b1 * (c.x_lo + 1.0)) / st.detA);
      sol.direction.DP_T = v1.DP_T - sol.start.DP_T;
      sol.direction.DP_N = v1.DP_N - sol.start.DP_N;
      sol.direction.Dw_T = v1.Dw_T - sol.start.Dw_T;
      sol.direction.Dw_N = v1.Dw_N - sol.start.Dw_N;
      sol.direction.Dw_Ti = v1.Dw_Ti - sol.start.Dw_Ti;
      sol.direction.Dw_w = v1.Dw_w - sol.start.Dw_w;
      sol.direction.P_T1 = sol.direction.DP_T;
      sol.direction.P_N1 = sol.direction.DP_N;
      sol.direction.g1 = v1.g1 - sol.start.g1;
    }
    conts.push_back(sol);
  }
}

/// Marks the solutions of the set reached continuously from the start state (detect_jumps).
void mark_jumps(const StepProblem& n, const Setup& st, double tol, StepSolutionSet& set) {
  // Homotopy in t: follow the solutions of the step with increment t (DF_T, DF_N) from t = 0
  // (where the start state itself is a solution) to t = 1, linking each solution to its
  // nearest neighbour at the previous t. A solution is continuous (rate-consistent) when its
  // chain leads back to the start state; jumps stay O(1) away from every such chain.
  constexpr int kSteps = 128;
  const double link = 0.1 * st.fscale;
  auto dist = [&](const StepValues& a, const StepValues& b) {
    return std::abs(a.DP_N - b.DP_N) + std::abs(a.DP_T - b.DP_T) +
           st.detA / st.D0 * std::abs(a.Dw_Ti - b.Dw_Ti);
  };
  std::vector<StepValues> prev_v, cur_v;
  std::vector<char> prev_r, cur_r;
  // The index of the solution of the previous t nearest to v (-1: none), its distance in best.
  auto nearest = [&](const StepValues& v, double& best) {
    int bi = -1;
    for (std::size_t j = 0; j < prev_v.size(); ++j) {
      const double d = dist(v, prev_v[j]);
      if (d < best) {
        best = d;
        bi = static_cast<int>(j);
      }
    }
    return bi;
  };
  bool ok = true;
  for (int k = 0; k <= kSteps && ok; ++k) {
    const double t = static_cast<double>(k) / kSteps;
    StepProblem pt = n;
    pt.load.dF_T *= t;
    pt.load.dF_N *= t;
    Work wt;
    enumerate_core(pt, tol, wt);
    if (wt.pts.infinite) {
      ok = false;
      break;
    }
    cur_v.clear();
    cur_r.clear();
    for (int i = 0; i < wt.pts.n; ++i) {
      const StepValues v = values_of(pt, wt.cand[i].u);
      bool r = false;
      if (k == 0) {
        r = distance(v) + st.detA / st.D0 * std::abs(v.Dw_Ti) <= 1e-9 * st.fscale;
      } else {
        double best = INFINITY;
        const int bi = nearest(v, best);
        r = bi >= 0 && prev_r[bi] && best <= link;
      }
      cur_v.push_back(v);
      cur_r.push_back(r ? 1 : 0);
    }
    std::swap(prev_v, cur_v);
    std::swap(prev_r, cur_r);
  }
  if (ok) {
    // prev_v now holds the t = 1 solutions: match them to the reported points.
    set.continuous_count = 0;
    for (auto& sol : set.solutions) {
      double best = INFINITY;
      const int bi = nearest(sol.start, best);
      sol.jump = !(bi >= 0 && prev_r[bi]);
      if (!sol.jump) ++set.continuous_count;
    }
  }
}

}  // namespace

void enumerate_step_points(const StepProblem& problem, const StepNcp& /*ncp*/, StepPoints& out,
                           double tol) noexcept {
  const Units u = units_of(problem);
  const StepProblem n = normalise(problem, u);
  // One work area per thread: constructing it (eight StepPoints with their values) per call
  // cost a fifth of this hot path (the simulation's per-step call).
  thread_local Work w;
  enumerate_core(n, tol, w);
  out.n = 0;
  out.unrepresentable = 0;
  out.infinite = w.pts.infinite;
  out.undecided = w.pts.undecided;
  for (int i = 0; i < w.pts.n; ++i) {
    StepPoint pt = w.pts.points[i];
    pt.values = to_user(values_of(n, w.cand[i].u), u);
    pt.DP_N = pt.values.DP_N;
    pt.xi = pt.values.Dw_Ti;
    if (!all_finite(pt.values)) {
      ++out.unrepresentable;
      continue;
    }
    out.points[out.n++] = pt;
  }
}

int StepSolutionSet::count() const noexcept {
  return infinite ? -1 : static_cast<int>(solutions.size());
}

unsigned StepSolutionSet::type_mask() const noexcept {
  unsigned m = 0;
  for (const auto& s : solutions) m |= 1u << static_cast<int>(s.type);
  return m;
}

StepSolutionSet enumerate_step(const StepProblem& problem, const StepEnumerationOptions& opt) {
  throw_if_invalid(problem.validate(), "step");
  if (!(opt.tol > 0) || !std::isfinite(opt.tol))
    throw InputError("step enumeration: tol must be finite and > 0");
  // Everything below is in the normalised units of `n`; values go back through to_user().
  const Units units = units_of(problem);
  const StepProblem n = normalise(problem, units);
  Work w;
  enumerate_core(n, opt.tol, w);
  StepSolutionSet set;
  set.infinite = w.pts.infinite;
  int unrepresentable = 0;
  // Continua first. A continuum's interior has its slip type; an end of another type
  // (stick where xi = 0, open where P_N1 = 0 after an open start) is open and listed as a point
  // of its own type (the partition of piece_geometry.hpp).
  std::vector<StepSolution> conts;
  std::vector<StepValues> open_ends;
  const Setup st = make_setup(n);
  continuum_solutions(n, st, w, conts, open_ends);
  auto same_point = [&](double DP_N, double xi, const StepValues& v) {
    return std::abs(v.DP_N - DP_N) <= 1e-9 * st.fscale && std::abs(v.Dw_Ti - xi) <= 1e-9 * st.dscale;
  };
  auto at_open_end = [&](double DP_N, double xi) {
    for (const auto& v : open_ends)
      if (same_point(DP_N, xi, v)) return true;
    return false;
  };
  auto on_continuum = [&](const StepPoint& pt) {
    for (int i = 0; i < w.ncont; ++i) {
      const Continuum& c = w.cont[i];
      if (pt.DP_N < c.x_lo - 1e-9 * st.fscale || pt.DP_N > c.x_hi + 1e-9 * st.fscale) continue;
      const double xi = c.s * (c.b0 + c.b1 * pt.DP_N) / st.detA;
      if (std::abs(xi - pt.xi) <= 1e-9 * st.dscale) return true;
    }
    return false;
  };
  auto add_point = [&](const StepValues& v, SolutionType type, double backward) {
    StepSolution sol;
    sol.start = v;
    sol.type = type;
    sol.residual = backward;
    set.solutions.push_back(sol);
  };
  for (int i = 0; i < w.pts.n; ++i) {
    const StepPoint& pt = w.pts.points[i];
    // Points on the closed part of a continuum belong to it; an open end is a point of its own.
    if (on_continuum(pt) && !at_open_end(pt.DP_N, pt.xi)) continue;
    add_point(values_of(n, w.cand[i].u), pt.type, w.cand[i].backward);
  }
  for (const auto& v : open_ends) {
    bool listed = false;
    for (const auto& sol : set.solutions)
      listed = listed || same_point(v.DP_N, v.Dw_Ti, sol.start);
    if (listed) continue;
    Candidate k;
    k.piece = kPieceStick;
    k.backward = 0;
    k.ftol = 1e-9;
    const double u[5] = {v.DP_T, v.DP_N, v.Dw_T, v.Dw_N, v.Dw_Ti};
    std::copy(u, u + 5, k.u);
    scales_of(n, k.u, k.fs, k.ds);
    add_point(v, type_of(n, k), 0);
  }
  for (auto& c : conts) set.solutions.push_back(c);
  std::stable_sort(set.solutions.begin(), set.solutions.end(),
                   [](const StepSolution& a, const StepSolution& b) {
                     return static_cast<int>(a.type) < static_cast<int>(b.type);
                   });
  set.continuous_count = -1;
  if (opt.detect_jumps && !set.infinite) mark_jumps(n, st, opt.tol, set);
  // Back to the caller's units; a solution that does not fit in double is not listed.
  std::vector<StepSolution> listed;
  for (auto sol : set.solutions) {
    sol.start = to_user(sol.start, units);
    sol.end = to_user(sol.end, units);
    sol.direction = to_user(sol.direction, units);
    const bool fits = all_finite(sol.start) &&
                      (sol.kind != RateSolution::Kind::kSegment || all_finite(sol.end)) &&
                      (sol.kind != RateSolution::Kind::kRay || all_finite(sol.direction));
    if (fits) listed.push_back(sol); else ++unrepresentable;
  }
  if (unrepresentable > 0)
    throw InputError("step: " + std::to_string(unrepresentable) +
                     " solution(s) not representable in double precision (their values "
                     "overflow in these units)");
  set.solutions = std::move(listed);
  if (w.pts.undecided > 0) {
    set.complete = false;
    std::ostringstream m;
    m << w.pts.undecided << " candidate(s) could be neither verified nor rejected (unit-free "
      << "backward error between 1e-12 and " << opt.tol
      << "): ill-conditioned data; the set may miss solutions";
    set.message = m.str();
  }
  return set;
}

}  // namespace cpkit::rate
