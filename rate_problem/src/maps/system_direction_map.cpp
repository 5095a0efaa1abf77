// N-point direction map: exact critical directions from the linear forms of every basis
// (docs/maps.md, "N points").
#include "cpkit/rate_problem/maps/system_direction_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/LU>

#include "cpkit/core/errors.hpp"
#include "direction_sectors.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.14159265358979323846264338327950;
// A form whose coefficients are below this fraction of the largest coefficient of its family is
// identically zero (round-off of an exact zero); relative, so the units of A do not matter.
constexpr double kZeroForm = 1e-12;
// Two zeros closer than this (rad) are the same direction.
constexpr double kSameAngle = 1e-10;

using Mat2 = Eigen::Matrix<double, Eigen::Dynamic, 2>;

/// Adds theta0 and theta0 + pi for every row (a, b) of F that is not identically zero.
void add_zeros(const Mat2& F, double scale, std::vector<double>& out) {
  for (int r = 0; r < F.rows(); ++r) {
    const double a = F(r, 0), b = F(r, 1);
    if (std::hypot(a, b) <= kZeroForm * scale) continue;
    double t = std::atan2(-a, b);  // a cos t + b sin t = 0
    if (t < 0) t += kPi;
    if (t >= kPi) t -= kPi;
    out.push_back(t);
    out.push_back(t + kPi);
  }
}

double max_abs(const Mat2& F) { return F.size() == 0 ? 0.0 : F.cwiseAbs().maxCoeff(); }

/// Zeros of the forms of the complementary bases S in [S_begin, S_end) (S = 0, the empty basis,
/// is added by the caller).
void basis_zeros(const SystemRatePrecomputed& pre, const Mat2& Q, const Mat2& base, double ps,
                 std::uint32_t S_begin, std::uint32_t S_end, std::vector<double>& zeros) {
  const int m = pre.m;
  for (std::uint32_t S = S_begin; S < S_end; ++S) {
    std::vector<int> in, out;
    for (int i = 0; i < m; ++i) ((S >> i) & 1u ? in : out).push_back(i);
    const int k = static_cast<int>(in.size());
    Eigen::MatrixXd Mss(k, k), Mns(m - k, k), Pz(pre.Pz.rows(), k);
    Mat2 qs_(k, 2), qn(m - k, 2);
    for (int a = 0; a < k; ++a) {
      qs_.row(a) = Q.row(in[a]);
      Pz.col(a) = pre.Pz.col(in[a]);
      for (int b = 0; b < k; ++b) Mss(a, b) = pre.M(in[a], in[b]);
      for (int b = 0; b < m - k; ++b) Mns(b, a) = pre.M(out[b], in[a]);
    }
    for (int b = 0; b < m - k; ++b) qn.row(b) = Q.row(out[b]);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(Mss);
    if (lu.isInvertible()) {
      const Mat2 Z = lu.solve(-Eigen::MatrixXd(qs_));
      add_zeros(Z, std::max(max_abs(Z), 1e-300), zeros);
      const Mat2 W = Mns * Z + qn;
      add_zeros(W, std::max({max_abs(Mns * Z), max_abs(qn), 1e-300}), zeros);
      const Mat2 P = base + Pz * Z;
      add_zeros(P, std::max({max_abs(Pz * Z), ps}), zeros);
    } else {
      // Solutions exist only where q_S is in the range of M_SS: u^T q_S = 0 for u in the left
      // null space.
      const Eigen::FullPivLU<Eigen::MatrixXd> lut(Mss.transpose());
      const Eigen::MatrixXd U = lut.kernel();
      const Mat2 C = U.transpose() * qs_;
      add_zeros(C, std::max(max_abs(qs_), 1e-300), zeros);
    }
  }
}

/// All zeros of all forms, sorted and deduplicated, in [0, 2 pi). The 2^m bases are split into
/// chunks run on `threads` workers; the sorted result does not depend on the split.
std::vector<double> candidate_angles(const SystemRatePrecomputed& pre, const Mat2& E,
                                     int threads) {
  const int m = pre.m;
  std::vector<double> zeros;
  const Mat2 Q = pre.Q * E;     // q = Q (cos, sin)^T
  const Mat2 base = pre.Pf * E; // physical rates at z = 0
  const double qs = std::max(max_abs(Q), 1e-300);
  const double ps = std::max(max_abs(base), 1e-300);
  add_zeros(base, ps, zeros);
  add_zeros(Q, qs, zeros);  // the empty basis: w = q
  const std::uint32_t bases = 1u << m;
  const int chunks = std::min<int>(64, static_cast<int>(bases));
  std::vector<std::vector<double>> part(static_cast<std::size_t>(chunks));
  run_items(0, chunks, resolve_threads(threads, chunks), [&](int c) {
    const std::uint32_t b0 = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(
                                                            uint64_t{bases} * c / chunks));
    const std::uint32_t b1 = static_cast<std::uint32_t>(uint64_t{bases} * (c + 1) / chunks);
    basis_zeros(pre, Q, base, ps, b0, b1, part[static_cast<std::size_t>(c)]);
  }, [](int) {});
  for (const auto& p : part) zeros.insert(zeros.end(), p.begin(), p.end());
  std::sort(zeros.begin(), zeros.end());
  std::vector<double> out;
  for (double t : zeros) {
    if (t >= kTwoPi) t -= kTwoPi;
    if (out.empty() || t - out.back() > kSameAngle) out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  if (out.size() > 1 && out.front() + kTwoPi - out.back() <= kSameAngle) out.pop_back();
  return out;
}

struct Arc {
  double from = 0, to = 0;
  SystemRateSummary summary;      ///< at the midpoint
  SystemRateSummary quarter[2];   ///< at the quarter points (a check)
  bool consistent = true;
};
}  // namespace

bool same_solution_set(const SystemRateSummary& a, const SystemRateSummary& b) noexcept {
  if (a.count != b.count || a.n_tuples != b.n_tuples) return false;
  const int n = std::min(a.n_tuples, SystemRateSummary::kCap);
  for (int i = 0; i < n; ++i)
    if (a.tuples[static_cast<std::size_t>(i)] != b.tuples[static_cast<std::size_t>(i)]) return false;
  return true;
}

void system_map_patterns(const ContactSystem& system, Eigen::VectorXd& e1, Eigen::VectorXd& e2) {
  const int N = system.n_points();
  if (system.pattern1) {
    e1 = *system.pattern1;
    e2 = *system.pattern2;
  } else {
    e1 = Eigen::VectorXd::Zero(2 * N);
    e2 = Eigen::VectorXd::Zero(2 * N);
    for (int i = 0; i < N; ++i) {
      e1(2 * i) = 1;
      e2(2 * i + 1) = 1;
    }
  }
  Mat2 E(2 * N, 2);
  E.col(0) = e1;
  E.col(1) = e2;
  if (Eigen::FullPivLU<Eigen::MatrixXd>(E).rank() < 2)
    throw InputError("patterns: e1 and e2 are parallel (or zero); dF(theta) = cos(theta) e1 + "
                     "sin(theta) e2 needs two independent load patterns");
}

int system_map_lcp_size(const ContactSystem& system) noexcept {
  int m = 0;
  for (const SystemPoint& p : system.points)
    m += p.state.label == StateLabel::kB ? 3 : p.state.label == StateLabel::kD ? 1 : 0;
  return m;
}

void check_system_map_lcp_size(const ContactSystem& system, const std::string& what) {
  const int m = system_map_lcp_size(system);
  if (m > kMaxSystemMapLcp)
    throw InputError("system: the rate LCP has size " + std::to_string(m) +
                     " (3 per point in state b, 1 per point in state d); " + what +
                     " scans all its 2^m bases and accepts at most " +
                     std::to_string(kMaxSystemMapLcp));
}

SystemDirectionMap compute_system_direction_map(const ContactSystem& system,
                                                const MapOptions& options) {
  check_system_map_lcp_size(system, "the direction map");
  throw_if_invalid(system.validate(), "system");
  throw_if_invalid(options.validate(), "map options");
  if (options.method != RateMethod::kEnumerate)
    throw InputError("map options: the N-point direction map uses the enumeration route only");
  SystemDirectionMap map;
  system_map_patterns(system, map.e1, map.e2);
  Mat2 E(map.e1.size(), 2);
  E.col(0) = map.e1;
  E.col(1) = map.e2;
  const SystemRatePrecomputed pre = precompute_system_rate(system);

  auto load = [&](double t) -> Eigen::VectorXd { return std::cos(t) * map.e1 + std::sin(t) * map.e2; };

  const std::vector<double> cand = candidate_angles(pre, E, options.threads);
  const std::size_t m = cand.size();
  map.candidates = static_cast<int>(m);
  std::vector<Arc> arcs(m == 0 ? 1 : m);
  std::vector<SystemCriticalDirection> at(m);
  // Every arc (midpoint and quarter points) and every candidate, on the workers: item k < arcs
  // is arc k, item arcs + i is candidate i. Results are stored by index.
  const int items = static_cast<int>(arcs.size() + m);
  run_items(0, items, resolve_threads(options.threads, items), [&](int k) {
    if (k < static_cast<int>(arcs.size())) {
      Arc& a = arcs[static_cast<std::size_t>(k)];
      const std::size_t i = static_cast<std::size_t>(k);
      a.from = m == 0 ? 0 : cand[i];
      a.to = m == 0 ? kTwoPi : (i + 1 < m ? cand[i + 1] : cand[0] + kTwoPi);
      const double w = a.to - a.from;
      a.summary = summarize_rate_problem(pre, load(a.from + 0.5 * w));
      a.quarter[0] = summarize_rate_problem(pre, load(a.from + 0.25 * w));
      a.quarter[1] = summarize_rate_problem(pre, load(a.from + 0.75 * w));
      a.consistent = same_solution_set(a.quarter[0], a.summary) &&
                     same_solution_set(a.quarter[1], a.summary);
    } else {
      const std::size_t i = static_cast<std::size_t>(k) - arcs.size();
      at[i].theta = cand[i];
      at[i].load = load(cand[i]);
      at[i].summary = summarize_rate_problem(pre, at[i].load, /*on_critical=*/true);
    }
  }, [](int) {});
  for (const Arc& a : arcs) {
    map.evaluations += 3;
    map.unreliable += !a.summary.reliable + !a.quarter[0].reliable + !a.quarter[1].reliable;
    map.inconsistent_sectors += !a.consistent;
  }
  for (const auto& c : at) {
    ++map.evaluations;
    map.unreliable += !c.summary.reliable;
  }
  std::vector<std::size_t> crit;
  for (std::size_t i = 0; i < m; ++i) {
    const Arc& before = arcs[(i + m - 1) % m];
    const Arc& after = arcs[i];
    if (!same_solution_set(at[i].summary, before.summary) ||
        !same_solution_set(at[i].summary, after.summary) ||
        !same_solution_set(before.summary, after.summary))
      crit.push_back(i);
  }
  sectors_from_arcs(arcs, at, crit, map.sectors, map.critical,
                    [](SystemDirectionSector& s, const Arc& a) { s.summary = a.summary; });
  return map;
}

}  // namespace cpkit::rate
