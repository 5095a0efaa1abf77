#pragma once
/// \file sphere_map_3d.hpp
/// Maps of 3-D contact points (docs/contact_3d.md, "Maps over the sphere of load directions"):
///  - the sphere map: the load rate of one point runs over the unit sphere,
///    dF = (sin b cos g, sin b sin g, cos b) on (T_X, T_Y, N), b in [0, pi] measured from +N,
///    g in (-pi, pi] the azimuth in the tangential plane from +T_X towards +T_Y; rows b, columns g;
///  - parameter x direction: rows a parameter (alpha_X, alpha_Y, mu, C_T, k_a, P_s), columns the
///    direction theta in the meridian plane at azimuth G, dF = (cos theta cos G, cos theta sin G,
///    sin theta) (for G = 0 this is the 2-D maps' (dF_T, dF_N) = (cos theta, sin theta));
///  - parameter x parameter: two parameters at the system's load rate dF.
/// Every cell holds the number of solutions (-1: infinitely many, a ray), the mask of solution
/// types (of the loaded point; bits type_bit()) and whether the set is proved complete: a cell
/// whose solve says complete = false is recorded as such (and counted in incomplete_cells), its
/// count is what was found.
///
/// Route: one point without facets: the exact one-point problem (solve_rate_3d); with facets K
/// (required for N > 1): the faceted N-point problem (solve_system_rate_3d_faceted), the other
/// points' load rates 0 or the file's (Map3dOptions::others_from_file). Rows are computed on
/// threads, stored by index: the result is the same for any thread count.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "cpkit/rate_problem/maps/map_axis.hpp"
#include "cpkit/rate_problem/maps/map_parameter_table.hpp"
#include "cpkit/rate_problem/model/rates.hpp"
#include "cpkit/rate_problem/system/contact_system.hpp"

namespace cpkit::rate {

/// Bit of a solution type in a cell's mask: open 1, separation 2, stick 4, slip 8 (the file
/// format's bits: slip takes the bit of the 2-D slip+, since a 3-D cell has no slip-).
inline constexpr uint8_t type_bit(SolutionType t) noexcept {
  return t == SolutionType::kSlip ? uint8_t{8}
                                  : static_cast<uint8_t>(1u << static_cast<unsigned>(t));
}
/// "none", or the types of a mask joined by '|' ("separation|stick|slip").
std::string type_mask_string(unsigned mask);

/// Largest number of cells of a 3-D map (3 bytes each are kept in memory).
inline constexpr int64_t kMaxMap3dCells = 16'000'000;

/// cos and sin of an angle, exact (0, +-1) at the angles 0, +-pi/2, +-pi as doubles
/// (so that a load on a coordinate plane has exact zeros).
Eigen::Vector2d cos_sin_exact(double angle) noexcept;

/// The load direction (sin b cos g, sin b sin g, cos b).
Eigen::Vector3d sphere_direction(double beta, double gamma) noexcept;

/// The grid of a sphere map: n_beta rows at the cell centres
/// b_i = beta_from + (beta_to - beta_from) (i + 1/2) / n_beta (the poles, where every g is the
/// same direction, are not rows; b = pi/2 is one when n_beta is odd), n_gamma columns
/// g_j = pi (2 (j + 1) - n_gamma) / n_gamma in (-pi, pi] (g = 0 and g = pi are columns, exactly,
/// when n_gamma is even).
struct SphereGrid {
  int n_beta = 91, n_gamma = 180;
  double beta_from = 0, beta_to = 3.141592653589793;
  double beta(int i) const noexcept;
  double gamma(int j) const noexcept;
  std::string validate() const;  ///< empty when usable; names n_beta, n_gamma, beta_from, ...
};

/// A quantity a 3-D map axis varies, of every point (point = 0) or of point i (1..N): a row of
/// the map parameter table.
using Map3dParameter = MapParameterRef;
/// Parses alpha_X, alpha_Y, mu, C_T, k_a, P_s, or "<name>@i" (1 <= i <= n_points). Throws
/// InputError naming the accepted names.
Map3dParameter parse_map_3d_parameter(std::string_view s, int n_points);
/// Sets the parameter in the system (no validation).
void apply_map_3d_parameter(const Map3dParameter& p, double value, ContactSystem3d& system);

struct Map3dOptions {
  int facets = 0;  ///< 0: exact (one point only); K in [3, 64]: the faceted route
  int point = 0;   ///< the loaded point (0-based) of sphere and param-direction maps; its types
  /// The other points' load rates: false 0, true the system's dF (required then).
  bool others_from_file = false;
  int threads = 0;  ///< 0: std::thread::hardware_concurrency()
  /// Wall-clock budget of the whole map in seconds (from the start of the compute call; default
  /// 600, as `cpkit map --time-limit`; may be infinite, then a faceted N-point cell may run
  /// without bound). Each cell's solve gets what is left of it; a cell it cuts short keeps what was
  /// found, not complete; once it is spent, the cells not computed are stored as count 0,
  /// types 0, not complete; both are counted in Map3d::timed_out_cells. A faceted N-point cell can otherwise take without bound
  /// (2^n_b separation cases).
  double time_limit_s = 600;
  /// Validates against the system: facets (required for N > 1), point, others_from_file,
  /// time_limit_s > 0.
  std::string validate(const ContactSystem3d& system) const;
};

/// Progress: fraction of rows done, from the calling thread (about every 0.1 s).
using Map3dProgress = std::function<void(double fraction)>;

/// A computed 3-D map: rows x cols cells, row-major.
struct Map3d {
  int rows = 0, cols = 0;
  std::vector<double> x, y;         ///< row and column values (b and g, param and theta, ...)
  std::vector<int8_t> count;        ///< [i * cols + j]
  std::vector<uint8_t> types;       ///< type masks
  std::vector<uint8_t> complete;    ///< 1: proved complete, 0: not
  int64_t incomplete_cells = 0;
  /// Cells the time limit (Map3dOptions::time_limit_s) cut short or left uncomputed; they are
  /// among the incomplete cells. Nonzero: the map is not the answer for those cells.
  int64_t timed_out_cells = 0;
  std::vector<std::pair<int, int64_t>> count_cells;  ///< (count, cells), by count (-1 first)
  std::array<int64_t, 16> type_cells{};             ///< cells per type mask
  double seconds = 0;
  int threads = 1;
  int64_t cells() const noexcept { return static_cast<int64_t>(rows) * cols; }
  int8_t count_at(int i, int j) const { return count[static_cast<std::size_t>(i) * cols + j]; }
  uint8_t types_at(int i, int j) const { return types[static_cast<std::size_t>(i) * cols + j]; }
  bool complete_at(int i, int j) const { return complete[static_cast<std::size_t>(i) * cols + j] != 0; }
};

/// The sphere map of options.point. Throws InputError for invalid system, grid or options.
Map3d compute_sphere_map_3d(const ContactSystem3d& system, const SphereGrid& grid,
                            const Map3dOptions& options = {}, const Map3dProgress& progress = {});

/// Parameter x direction: rows axis values, columns theta_n directions theta_j =
/// theta_from + (j + 1/2) (theta_to - theta_from) / theta_n in the meridian plane at azimuth
/// `gamma` (0 < theta_to - theta_from <= 2 pi). Throws InputError for an invalid axis value
/// (the first one met, e.g. a state-d point whose traction leaves its changed ellipse).
Map3d compute_param_direction_map_3d(const ContactSystem3d& system, const Map3dAxis& axis,
                                     int theta_n, double theta_from, double theta_to,
                                     double gamma, const Map3dOptions& options = {},
                                     const Map3dProgress& progress = {});

/// Parameter x parameter at the system's dF (required). Throws InputError as above.
Map3d compute_param_param_map_3d(const ContactSystem3d& system, const Map3dAxis& axis1,
                                 const Map3dAxis& axis2, const Map3dOptions& options = {},
                                 const Map3dProgress& progress = {});

}  // namespace cpkit::rate
