#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>

#include "run_items.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/rate/faceted_rate_3d.hpp"
#include "cpkit/rate_problem/rate/system_rate_3d.hpp"

namespace cpkit::rate {

namespace {

constexpr double kPi = 3.141592653589793;

struct Cell3d {
  int8_t count = 0;     ///< -1: infinitely many (a ray of the one-point state d)
  uint8_t types = 0;    ///< mask of type_bit() of the loaded point's solution types
  bool complete = true;
  bool timed_out = false;  ///< the time limit ended the cell's solve (complete = false)
};

/// One cell: every solution for the load rate dF (3N) by the route of `options`; the faceted
/// solve gets at most `time_limit_s` seconds (what is left of the map's budget).
Cell3d evaluate_cell_3d(const ContactSystem3d& sys, const Eigen::VectorXd& dF,
                        const Map3dOptions& o, double time_limit_s) {
  Cell3d c;
  if (!(time_limit_s > 0)) {  // the map's budget is spent: not computed
    c.complete = false;
    c.timed_out = true;
    return c;
  }
  if (o.facets == 0) {
    const RateSolutionSet3d s = solve_rate_3d(sys.point_parameters(0), sys.points[0].state,
                                              Eigen::Vector3d(dF.head<3>()));
    c.count = static_cast<int8_t>(s.infinite() ? -1 : std::min(s.count(), 127));
    for (const auto& x : s.solutions) c.types |= type_bit(x.type);
    c.complete = s.complete;
    return c;
  }
  const SystemRateSet3d s = solve_system_rate_3d_faceted(sys, dF, o.facets, time_limit_s);
  c.count = static_cast<int8_t>(std::min(s.count(), 127));
  for (const auto& x : s.solutions) c.types |= type_bit(x.types[static_cast<std::size_t>(o.point)]);
  c.complete = s.complete;
  c.timed_out = s.timed_out;
  return c;
}

/// Validates every point of a system (parameters and state): throws naming the point.
void validate_points(const ContactSystem3d& sys, const std::string& where) {
  for (int i = 0; i < sys.n_points(); ++i) {
    const ContactParameters3d p = sys.point_parameters(i);
    std::string e = p.validate();
    if (e.empty()) e = sys.points[static_cast<std::size_t>(i)].state.validate(p);
    if (!e.empty())
      throw InputError(where + "point " + std::to_string(i + 1) + ": " + e);
  }
}

/// Runs cell(i, j) -> Cell3d over rows x cols on threads (rows handed out one at a time) and
/// fills the map's arrays and counters.
template <class RowSetup>
void fill_map(Map3d& m, const Map3dOptions& options, const Map3dProgress& progress,
              RowSetup&& row_cells) {
  const Stopwatch clock;
  const std::size_t n = static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols);
  m.count.assign(n, 0);
  m.types.assign(n, 0);
  m.complete.assign(n, 1);
  std::vector<uint8_t> timed_out(n, 0);
  m.threads = rate::resolve_threads(options.threads, m.rows);
  // One budget for the whole map: a cell gets what is left; none is left: not computed.
  const double limit = options.time_limit_s;
  rate::run_items(
      0, m.rows, m.threads,
      [&](int i) {
        row_cells(i, [&](int) { return limit - clock.seconds(); },
                  [&](int j, const Cell3d& c) {
          const std::size_t k = static_cast<std::size_t>(i) * m.cols + static_cast<std::size_t>(j);
          m.count[k] = c.count;
          m.types[k] = c.types;
          m.complete[k] = c.complete ? 1 : 0;
          timed_out[k] = c.timed_out ? 1 : 0;
        });
      },
      [&](int done) {
        if (progress) progress(static_cast<double>(done) / std::max(1, m.rows));
      });
  std::map<int, int64_t> counts;
  m.incomplete_cells = 0;
  m.timed_out_cells = 0;
  m.type_cells.fill(0);
  for (std::size_t k = 0; k < n; ++k) {
    ++counts[m.count[k]];
    ++m.type_cells[m.types[k] & 15u];
    m.incomplete_cells += m.complete[k] == 0;
    m.timed_out_cells += timed_out[k];
  }
  m.count_cells.assign(counts.begin(), counts.end());
  m.seconds = clock.seconds();
  if (progress) progress(1.0);
}

void check_options(const ContactSystem3d& sys, const Map3dOptions& options) {
  validate_points(sys, "");
  if (const std::string e = options.validate(sys); !e.empty()) throw InputError(e);
}

/// The load rate with `dir` at the loaded point and the others' from the options.
Eigen::VectorXd load_with(const ContactSystem3d& sys, const Map3dOptions& o,
                          const Eigen::Vector3d& dir) {
  Eigen::VectorXd dF = Eigen::VectorXd::Zero(3 * sys.n_points());
  if (o.others_from_file && sys.dF) dF = *sys.dF;
  dF.segment<3>(3 * o.point) = dir;
  return dF;
}

}  // namespace

std::string type_mask_string(unsigned mask) {
  std::string s;
  for (SolutionType t : {SolutionType::kOpen, SolutionType::kSeparation, SolutionType::kStick, SolutionType::kSlip})
    if (mask & type_bit(t)) s += (s.empty() ? "" : "|") + std::string(to_string(t));
  return s.empty() ? "none" : s;
}

Eigen::Vector2d cos_sin_exact(double a) noexcept {
  if (a == 0) return {1, 0};
  if (a == kPi || a == -kPi) return {-1, 0};
  if (a == kPi / 2) return {0, 1};
  if (a == -kPi / 2) return {0, -1};
  return {std::cos(a), std::sin(a)};
}

Eigen::Vector3d sphere_direction(double beta, double gamma) noexcept {
  const Eigen::Vector2d b = cos_sin_exact(beta), g = cos_sin_exact(gamma);
  return {b(1) * g(0), b(1) * g(1), b(0)};
}

double SphereGrid::beta(int i) const noexcept {
  // cell centres; the ratio first: b = pi/2 comes out exactly for the default range, odd n_beta
  return beta_from + (beta_to - beta_from) * ((i + 0.5) / n_beta);
}

double SphereGrid::gamma(int j) const noexcept {
  return kPi * (static_cast<double>(2 * (j + 1) - n_gamma) / n_gamma);
}

std::string SphereGrid::validate() const {
  if (n_beta < 1 || n_beta > 1000000) return "n_beta must be in [1, 1000000]";
  if (n_gamma < 1 || n_gamma > 1000000) return "n_gamma must be in [1, 1000000]";
  if (!std::isfinite(beta_from) || beta_from < 0 || beta_from > kPi)
    return "beta_from must be in [0, pi]";
  if (!std::isfinite(beta_to) || beta_to < 0 || beta_to > kPi) return "beta_to must be in [0, pi]";
  if (n_beta > 1 && !(beta_from < beta_to)) return "beta_from must be < beta_to";
  if (static_cast<int64_t>(n_beta) * n_gamma > kMaxMap3dCells)
    return "n_beta x n_gamma must be at most " + std::to_string(kMaxMap3dCells) + " cells";
  return {};
}

Map3dParameter parse_map_3d_parameter(std::string_view text, int n_points) {
  return check_map_parameter(text, kMap3d, n_points);  // the names and NAME@i of 3-D maps
}

void apply_map_3d_parameter(const Map3dParameter& p, double v, ContactSystem3d& sys) {
  for (int i = 0; i < sys.n_points(); ++i)
    if (p.point == 0 || i == p.point - 1)
      p.row->set_point_3d(sys.points[static_cast<std::size_t>(i)], v);
}

std::string Map3dOptions::validate(const ContactSystem3d& sys) const {
  const int N = sys.n_points();
  if (facets != 0 && (facets < 3 || facets > kMaxFacets))
    return "facets must be in [3, " + std::to_string(kMaxFacets) + "] (0: exact), got " +
           std::to_string(facets);
  if (N > 1 && facets == 0)
    return "a system of " + std::to_string(N) +
           " points needs the faceted route (facets K): the exact route is for one point";
  if (point < 0 || point >= N)
    return "point must be 1.." + std::to_string(N) + ", got " + std::to_string(point + 1);
  if (others_from_file && !sys.dF)
    return "the other points' load rates from the file need \"dF\" in the system file";
  if (threads < 0 || threads > 1024) return "threads must be in [0, 1024]";
  if (!(time_limit_s > 0)) return "time_limit_s must be > 0 (infinite: no limit)";
  return {};
}

Map3d compute_sphere_map_3d(const ContactSystem3d& sys, const SphereGrid& grid,
                            const Map3dOptions& options, const Map3dProgress& progress) {
  check_options(sys, options);
  throw_if_invalid(grid.validate(), "sphere grid");
  Map3d m;
  m.rows = grid.n_beta;
  m.cols = grid.n_gamma;
  for (int i = 0; i < m.rows; ++i) m.x.push_back(grid.beta(i));
  for (int j = 0; j < m.cols; ++j) m.y.push_back(grid.gamma(j));
  fill_map(m, options, progress, [&](int i, auto&& left, auto&& put) {
    for (int j = 0; j < m.cols; ++j)
      put(j, evaluate_cell_3d(sys, load_with(sys, options, sphere_direction(m.x[i], m.y[j])),
                              options, left(j)));
  });
  return m;
}

Map3d compute_param_direction_map_3d(const ContactSystem3d& sys, const Map3dAxis& axis,
                                     int theta_n, double theta_from, double theta_to,
                                     double gamma, const Map3dOptions& options,
                                     const Map3dProgress& progress) {
  check_options(sys, options);
  throw_if_invalid(axis.validate(), "axis");
  if (theta_n < 1 || theta_n > 1000000) throw InputError("theta_n must be in [1, 1000000]");
  if (!std::isfinite(theta_from) || !std::isfinite(theta_to) || !(theta_to > theta_from) ||
      theta_to - theta_from > 2 * kPi + 1e-12)
    throw InputError("theta range: need 0 < theta_to - theta_from <= 2 pi, got [" +
                     num_text(theta_from, 10) + ", " + num_text(theta_to, 10) + "]");
  if (!std::isfinite(gamma)) throw InputError("gamma must be finite");
  if (static_cast<int64_t>(axis.n) * theta_n > kMaxMap3dCells)
    throw InputError("n x theta_n must be at most " + std::to_string(kMaxMap3dCells) + " cells");
  Map3d m;
  m.rows = axis.n;
  m.cols = theta_n;
  std::vector<ContactSystem3d> rows(static_cast<std::size_t>(axis.n), sys);
  for (int i = 0; i < axis.n; ++i) {
    m.x.push_back(axis.value(i));
    apply_map_3d_parameter(axis.param, m.x.back(), rows[static_cast<std::size_t>(i)]);
    validate_points(rows[static_cast<std::size_t>(i)],
                    axis.param.name() + " = " + num_text(m.x.back(), 10) + ": ");
  }
  m.y = rate::map_theta_values(theta_n, theta_from, theta_to);
  const Eigen::Vector2d g = cos_sin_exact(gamma);
  fill_map(m, options, progress, [&](int i, auto&& left, auto&& put) {
    const ContactSystem3d& s = rows[static_cast<std::size_t>(i)];
    for (int j = 0; j < m.cols; ++j) {
      const Eigen::Vector2d t = cos_sin_exact(m.y[static_cast<std::size_t>(j)]);
      put(j, evaluate_cell_3d(s, load_with(s, options, Eigen::Vector3d(t(0) * g(0), t(0) * g(1), t(1))),
                              options, left(j)));
    }
  });
  return m;
}

Map3d compute_param_param_map_3d(const ContactSystem3d& sys, const Map3dAxis& axis1,
                                 const Map3dAxis& axis2, const Map3dOptions& options,
                                 const Map3dProgress& progress) {
  check_options(sys, options);
  throw_if_invalid(axis1.validate(), "first axis");
  throw_if_invalid(axis2.validate(), "second axis");
  const Map3dParameter &p1 = axis1.param, &p2 = axis2.param;
  if (p1.row == p2.row && (p1.point == 0 || p2.point == 0 || p1.point == p2.point))
    throw InputError("the two axes " + p1.name() + " and " + p2.name() +
                     " vary the same quantity of the same point");
  if (!sys.dF) throw InputError("a param-param map is computed at the system's \"dF\": the file has none");
  if (static_cast<int64_t>(axis1.n) * axis2.n > kMaxMap3dCells)
    throw InputError("n x n2 must be at most " + std::to_string(kMaxMap3dCells) + " cells");
  Map3d m;
  m.rows = axis1.n;
  m.cols = axis2.n;
  for (int i = 0; i < axis1.n; ++i) m.x.push_back(axis1.value(i));
  for (int j = 0; j < axis2.n; ++j) m.y.push_back(axis2.value(j));
  // Every grid value first: the first invalid one is named before any cell is computed.
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      ContactSystem3d s = sys;
      apply_map_3d_parameter(axis1.param, m.x[static_cast<std::size_t>(i)], s);
      apply_map_3d_parameter(axis2.param, m.y[static_cast<std::size_t>(j)], s);
      validate_points(s, axis1.param.name() + " = " +
                             num_text(m.x[static_cast<std::size_t>(i)], 10) + ", " +
                             axis2.param.name() + " = " +
                             num_text(m.y[static_cast<std::size_t>(j)], 10) + ": ");
    }
  const Eigen::VectorXd dF = *sys.dF;
  fill_map(m, options, progress, [&](int i, auto&& left, auto&& put) {
    ContactSystem3d s = sys;
    apply_map_3d_parameter(axis1.param, m.x[static_cast<std::size_t>(i)], s);
    for (int j = 0; j < m.cols; ++j) {
      apply_map_3d_parameter(axis2.param, m.y[static_cast<std::size_t>(j)], s);
      put(j, evaluate_cell_3d(s, dF, options, left(j)));
    }
  });
  return m;
}

}  // namespace cpkit::rate
