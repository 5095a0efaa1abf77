// Maps of 3-D contact points (sphere_map_3d.hpp; docs/contact_3d.md, "Maps over the sphere of
// load directions"). Independent sources:
// - the 2-D closed forms (summarize_rate_analytic) and the 2-D param-direction map
//   (rate::compute_param_direction_map) for an isotropic point whose Y direction is decoupled:
//   on the great circle g = 0 / g = pi the load has no Y component (docs/contact_3d.md sec. 3);
// - symmetry: an isotropic point with A invariant under rotations of the tangential plane gives
//   a map independent of g; turning the tangential plane by pi/2 (A' = Q A Q^T, the half-axes
//   swapped) shifts the map by a quarter of its columns;
// - the ellipse-to-circle change of variables for C_T = 0 (docs/contact_3d.md sec. 4): the
//   elliptic map's cells against isotropic problems A~ = S A S at S dF, solved one by one;
// - alpha_X = alpha_Y = a is the isotropic law with mu a (the friction set |p_T| <= a mu P_N);
// - a block-diagonal two-point system (the second point sticking) against the one-point map;
// - the faceted route with k = 64 against the exact one at generic cells;
// - 1 and 2 threads give identical arrays;
// - the time limit (issue 24, item 11): a map of eight grazing points used to run for 600 s
//   past --time-limit 1; its cells are now flagged not complete once the budget is spent.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/rate/point_rate_3d.hpp"
#include "cpkit/rate_problem/maps/sphere_map_3d.hpp"

using namespace cpkit;
using namespace cpkit::rate;

namespace {

constexpr double kPi = 3.141592653589793;

ContactSystem3d one_point(const Eigen::Matrix3d& A, double mu, double C_T, Eigen::Vector2d alpha,
                          char state = 'b', double P_N = 0, Eigen::Vector2d P_T = {0, 0},
                          double k_a = 0) {
  ContactSystem3d s;
  s.name = "test";
  s.A = A;
  SystemPoint3d p;
  p.mu = mu;
  p.C_T = C_T;
  p.k_a = k_a;
  p.alpha = alpha;
  p.state.state = state;
  p.state.P_N = P_N;
  p.state.P_T = P_T;
  s.points = {p};
  return s;
}

/// 2-D type mask (bit = SolutionType) to the 3-D one (slip+ and slip- are slip).
unsigned mask_2d_to_3d(unsigned m2) {
  return (m2 & 7u) | ((m2 & 24u) ? 8u : 0u);
}

/// docs/examples/sphere_point_3d.json: strong tangential-normal coupling (with mu = 4 and
/// alpha = (0.6, 1) a region of three solutions on the sphere).
Eigen::Matrix3d coupled_A() {
  Eigen::Matrix3d A;
  A << 1.0, 0.0, 0.9,
       0.0, 1.0, 0.6,
       0.9, 0.6, 1.6;
  return A;
}

Eigen::Matrix3d decoupled_A() {
  Eigen::Matrix3d A;
  A << 1.0, 0.0, 0.8,
       0.0, 2.0, 0.0,
       0.8, 0.0, 1.5;
  return A;
}

}  // namespace

TEST_CASE("3-D map type bits are the documented file format with the one SolutionType",
          "[rate3d][map3d]") {
  // docs/contact_3d.md, "Maps over the sphere": open 1, separation 2, stick 4, slip 8; the 3-D
  // slip (SolutionType::kSlip, added after the 2-D slip+/slip-) keeps bit 8.
  CHECK(type_bit(SolutionType::kOpen) == 1);
  CHECK(type_bit(SolutionType::kSeparation) == 2);
  CHECK(type_bit(SolutionType::kStick) == 4);
  CHECK(type_bit(SolutionType::kSlip) == 8);
  CHECK(type_mask_string(2 | 4 | 8) == "separation|stick|slip");
  CHECK(type_mask_string(0) == "none");
}

TEST_CASE("sphere map: the great circle g = 0, pi of a decoupled isotropic point is the 2-D "
          "closed form", "[rate3d][map3d]") {
  // mu = 2 > a11/a12 = 1.25: a wedge with three solutions in state b.
  struct Case {
    char state;
    double P_N, P_TX, k_a;
  };
  for (const Case c : {Case{'b', 0, 0, 0}, Case{'d', 1.0, 2.0, 0.3}, Case{'d', 1.0, -2.0, 0.0},
                       Case{'c', 1.0, 0.5, 0.0}}) {
    CAPTURE(c.state, c.P_TX);
    const ContactSystem3d sys =
        one_point(decoupled_A(), 2.0, 0.25, {1, 1}, c.state, c.P_N, {c.P_TX, 0}, c.k_a);
    SphereGrid grid;
    grid.n_beta = 181;
    grid.n_gamma = 8;  // g = 0 is column 3, g = pi column 7
    const Map3d m = compute_sphere_map_3d(sys, grid);
    REQUIRE(m.y[3] == 0.0);
    REQUIRE(m.y[7] == kPi);
    rate::ContactParameters p2;
    p2.a11 = 1.0;
    p2.a12 = 0.8;
    p2.a22 = 1.5;
    p2.mu = 2.0;
    p2.C_T = 0.25;
    p2.k_a = c.k_a;
    rate::ContactState s2;
    s2.label = c.state == 'b' ? rate::StateLabel::kB
                              : c.state == 'c' ? rate::StateLabel::kC : rate::StateLabel::kD;
    s2.P_N = c.P_N;
    s2.sgn_PT = c.P_TX < 0 ? -1 : 1;
    int several = 0;
    for (int i = 0; i < m.rows; ++i)
      for (int j : {3, 7}) {
        const double b = m.x[static_cast<std::size_t>(i)];
        const rate::LoadRate load{std::sin(b) * (j == 3 ? 1.0 : -1.0), std::cos(b)};
        const rate::RateSummary two = rate::summarize_rate_analytic(p2, s2, load);
        CAPTURE(i, j, b);
        CHECK(m.complete_at(i, j));
        CHECK(m.count_at(i, j) == two.count);
        CHECK(m.types_at(i, j) == mask_2d_to_3d(two.types));
        several += two.count > 1;
      }
    if (c.state == 'b') CHECK(several >= 4);
  }
}

TEST_CASE("param-direction map at g = 0 of a decoupled isotropic point is the 2-D map",
          "[rate3d][map3d]") {
  const ContactSystem3d sys = one_point(decoupled_A(), 2.0, 0.25, {1, 1});
  Map3dAxis axis;
  axis.param = parse_map_3d_parameter("mu", 1);
  axis.from = 0.5;
  axis.to = 3.0;
  axis.n = 12;  // no row on the critical mu = a11/a12 = 1.25
  const Map3d m = compute_param_direction_map_3d(sys, axis, 90, 0, 2 * kPi, 0.0);
  rate::ContactParameters p2;
  p2.a11 = 1.0;
  p2.a12 = 0.8;
  p2.a22 = 1.5;
  p2.mu = 2.0;
  p2.C_T = 0.25;
  rate::MapAxis a2;
  a2.param = rate::map_parameter("mu");
  a2.from = 0.5;
  a2.to = 3.0;
  a2.n = 12;
  const rate::ParamDirectionMap two = rate::compute_param_direction_map(p2, rate::ContactState{}, a2, 90);
  REQUIRE(two.count.size() == m.count.size());
  int several = 0;
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * m.cols + j;
      CAPTURE(i, j);
      CHECK(m.y[static_cast<std::size_t>(j)] == Approx(two.theta[static_cast<std::size_t>(j)]));
      CHECK(m.complete_at(i, j));
      CHECK(m.count[k] == two.count[k]);
      CHECK(m.types[k] == mask_2d_to_3d(two.types[k]));
      several += two.count[k] > 1;
    }
  CHECK(several >= 10);
}

TEST_CASE("sphere map: rotations of the tangential plane", "[rate3d][map3d]") {
  SECTION("A invariant under rotations: the map does not depend on g") {
    Eigen::Matrix3d A;
    A << 1.3, 0.0, 0.0,
         0.0, 1.3, 0.0,
         0.0, 0.0, 0.9;
    for (double C_T : {0.0, 0.2}) {
      const ContactSystem3d sys = one_point(A, 0.7, C_T, {1, 1});
      SphereGrid grid;
      grid.n_beta = 40;
      grid.n_gamma = 24;
      const Map3d m = compute_sphere_map_3d(sys, grid);
      for (int i = 0; i < m.rows; ++i)
        for (int j = 1; j < m.cols; ++j) {
          CAPTURE(i, j);
          CHECK(m.complete_at(i, j));
          CHECK(m.count_at(i, j) == m.count_at(i, 0));
          CHECK(m.types_at(i, j) == m.types_at(i, 0));
        }
    }
  }
  SECTION("turning the plane by pi/2 (half-axes swapped) shifts the columns by n_g / 4") {
    Eigen::Matrix3d A = coupled_A();
    A(0, 1) = A(1, 0) = 0.2;
    Eigen::Matrix3d Q;
    Q << 0, -1, 0,
         1, 0, 0,
         0, 0, 1;  // e_X -> e_Y, e_Y -> -e_X: exact
    const ContactSystem3d sys = one_point(A, 4.0, 0.1, {0.6, 1.0});
    const ContactSystem3d rot = one_point(Q * A * Q.transpose(), 4.0, 0.1, {1.0, 0.6});
    SphereGrid grid;
    grid.n_beta = 45;
    grid.n_gamma = 48;
    const Map3d m = compute_sphere_map_3d(sys, grid), r = compute_sphere_map_3d(rot, grid);
    int several = 0, both = 0;
    for (int i = 0; i < m.rows; ++i)
      for (int j = 0; j < m.cols; ++j) {
        const int jr = (j + grid.n_gamma / 4) % grid.n_gamma;  // g + pi/2
        if (!m.complete_at(i, j) || !r.complete_at(i, jr)) continue;
        ++both;
        CAPTURE(i, j);
        CHECK(m.count_at(i, j) == r.count_at(i, jr));
        CHECK(m.types_at(i, j) == r.types_at(i, jr));
        several += m.count_at(i, j) > 1;
      }
    CHECK(both >= static_cast<int>(0.99 * m.cells()));
    CHECK(several >= 10);
  }
}

TEST_CASE("sphere map: the ellipse is a circle in other variables (C_T = 0)", "[rate3d][map3d]") {
  const Eigen::Matrix3d A = coupled_A();
  const Eigen::Vector2d alpha(0.6, 1.0);
  const ContactSystem3d sys = one_point(A, 4.0, 0.0, alpha);
  SphereGrid grid;
  grid.n_beta = 30;
  grid.n_gamma = 40;
  const Map3d m = compute_sphere_map_3d(sys, grid);
  const Eigen::Vector3d s(1 / alpha(0), 1 / alpha(1), 1);
  ContactParameters3d iso;
  iso.A = s.asDiagonal() * A * s.asDiagonal();
  iso.mu = 4.0;
  iso.alpha = {1, 1};
  int several = 0, checked = 0;
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      const Eigen::Vector3d dF = sphere_direction(m.x[static_cast<std::size_t>(i)],
                                                  m.y[static_cast<std::size_t>(j)]);
      const RateSolutionSet3d ref = solve_rate_3d(iso, ContactState3d{}, s.asDiagonal() * dF);
      if (!ref.complete || !m.complete_at(i, j)) continue;
      ++checked;
      unsigned mask = 0;
      for (const auto& x : ref.solutions) mask |= type_bit(x.type);
      CAPTURE(i, j);
      CHECK(m.count_at(i, j) == ref.count());
      CHECK(m.types_at(i, j) == mask);
      several += ref.count() > 1;
    }
  CHECK(checked >= static_cast<int>(0.99 * m.cells()));
  CHECK(several >= 10);
}

TEST_CASE("param-param map: alpha_X = alpha_Y = a is the isotropic law with mu a",
          "[rate3d][map3d]") {
  Eigen::Matrix3d A;
  A << 1.0, 0.1, 0.8,
       0.1, 1.2, 0.3,
       0.8, 0.3, 1.5;
  ContactSystem3d sys = one_point(A, 1.6, 0.25, {1, 1});
  Map3dAxis ax, ay;
  ax.param = parse_map_3d_parameter("alpha_X", 1);
  ay.param = parse_map_3d_parameter("alpha_Y", 1);
  ax.from = ay.from = 0.5;
  ax.to = ay.to = 2.0;
  ax.n = ay.n = 7;
  int several = 0;
  for (const Eigen::Vector3d& dF :
       {Eigen::Vector3d(1.0, 0.5, 0.9), Eigen::Vector3d(1.0, 0.2, 0.75), Eigen::Vector3d(-0.3, 1, 0.8),
        Eigen::Vector3d(0.8, 0.1, 0.5)}) {
    sys.dF = Eigen::VectorXd(dF);
    const Map3d m = compute_param_param_map_3d(sys, ax, ay);
    for (int i = 0; i < m.rows; ++i) {
      ContactParameters3d p = sys.point_parameters(0);
      p.alpha = {1, 1};
      p.mu = 1.6 * m.x[static_cast<std::size_t>(i)];
      const RateSolutionSet3d ref = solve_rate_3d(p, ContactState3d{}, dF);
      REQUIRE(ref.complete);
      unsigned mask = 0;
      for (const auto& x : ref.solutions) mask |= type_bit(x.type);
      CAPTURE(dF.transpose(), i);
      REQUIRE(m.y[static_cast<std::size_t>(i)] == m.x[static_cast<std::size_t>(i)]);
      CHECK(m.complete_at(i, i));
      CHECK(m.count_at(i, i) == ref.count());
      CHECK(m.types_at(i, i) == mask);
      several += ref.count() > 1;
    }
    // the cell (1, 1) is the file's isotropic point
    const RateSolutionSet3d file = solve_rate_3d(sys.point_parameters(0), ContactState3d{}, dF);
    const Map3d one = compute_param_param_map_3d(sys, Map3dAxis{ax.param, 1, 1, 1},
                                                 Map3dAxis{ay.param, 1, 1, 1});
    CHECK(one.count_at(0, 0) == file.count());
  }
  CHECK(several >= 2);
}

TEST_CASE("sphere map: threads do not change the map; faceted k = 64 agrees at generic cells",
          "[rate3d][map3d]") {
  const ContactSystem3d sys = one_point(coupled_A(), 4.0, 0.1, {0.6, 1.0});
  SphereGrid grid;  // the band of b with the region of three solutions
  grid.n_beta = 16;
  grid.n_gamma = 32;
  grid.beta_from = 0.6;
  grid.beta_to = 1.4;
  Map3dOptions o1, o2;
  o1.threads = 1;
  o2.threads = 2;
  const Map3d a = compute_sphere_map_3d(sys, grid, o1), b = compute_sphere_map_3d(sys, grid, o2);
  CHECK(a.count == b.count);
  CHECK(a.types == b.types);
  CHECK(a.complete == b.complete);
  CHECK(a.incomplete_cells == b.incomplete_cells);
  CHECK(a.count_cells == b.count_cells);

  Map3dOptions f;
  f.facets = 64;
  f.threads = 2;
  const Map3d fac = compute_sphere_map_3d(sys, grid, f);
  auto same_as_neighbours = [&](int i, int j) {
    if (!a.complete_at(i, j)) return false;
    for (auto [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
      const int ii = i + di, jj = (j + dj + a.cols) % a.cols;
      if (ii < 0 || ii >= a.rows) continue;
      if (!a.complete_at(ii, jj) || a.count_at(ii, jj) != a.count_at(i, j) ||
          a.types_at(ii, jj) != a.types_at(i, j))
        return false;
    }
    return true;
  };
  int generic = 0, several = 0;
  for (int i = 0; i < a.rows; ++i)
    for (int j = 0; j < a.cols; ++j) {
      if (!same_as_neighbours(i, j)) continue;
      ++generic;
      CAPTURE(i, j);
      CHECK(fac.complete_at(i, j));
      CHECK(fac.count_at(i, j) == a.count_at(i, j));
      CHECK(fac.types_at(i, j) == a.types_at(i, j));
      several += a.count_at(i, j) > 1;
    }
  CHECK(generic >= static_cast<int>(0.7 * a.cells()));
  CHECK(several >= 5);
}

TEST_CASE("sphere map of two points: a block-diagonal system with a sticking other point is "
          "the one-point map", "[rate3d][map3d]") {
  const Eigen::Matrix3d A = coupled_A();
  const ContactSystem3d one = one_point(A, 4.0, 0.1, {0.6, 1.0});
  SystemPoint3d stick;  // state c: linear, one solution (stick) for any load
  stick.mu = 0.5;
  stick.state.state = 'c';
  stick.state.P_N = 1;
  SphereGrid grid;
  grid.n_beta = 10;
  grid.n_gamma = 16;
  Map3dOptions o;
  o.facets = 16;
  const Map3d m1 = compute_sphere_map_3d(one, grid, o);
  int several = 0;
  for (int8_t c : m1.count) several += c > 1;
  CHECK(several >= 3);
  for (int loaded : {0, 1}) {
    CAPTURE(loaded);
    ContactSystem3d two;
    two.A = Eigen::MatrixXd::Zero(6, 6);
    two.A.block<3, 3>(3 * loaded, 3 * loaded) = A;
    two.A.block<3, 3>(3 * (1 - loaded), 3 * (1 - loaded)) = Eigen::Matrix3d::Identity() * 2;
    two.points = loaded == 0 ? std::vector<SystemPoint3d>{one.points[0], stick}
                             : std::vector<SystemPoint3d>{stick, one.points[0]};
    o.point = loaded;
    const Map3d m2 = compute_sphere_map_3d(two, grid, o);
    CHECK(m1.count == m2.count);
    CHECK(m1.types == m2.types);
    CHECK(m1.complete == m2.complete);
  }
}

TEST_CASE("3-D maps: bad input is refused", "[rate3d][map3d]") {
  const ContactSystem3d sys = one_point(decoupled_A(), 2.0, 0.25, {1, 1});
  SphereGrid g;
  g.n_beta = 0;
  CHECK_THROWS_AS(compute_sphere_map_3d(sys, g), InputError);
  g.n_beta = 10;
  g.beta_to = 4;
  CHECK_THROWS_AS(compute_sphere_map_3d(sys, g), InputError);
  g.beta_to = kPi;
  g.n_beta = 100000;
  g.n_gamma = 100000;
  CHECK_THROWS_WITH(compute_sphere_map_3d(sys, g), Catch::Contains("at most"));
  ContactSystem3d two = sys;
  two.A = Eigen::MatrixXd::Identity(6, 6);
  two.points.push_back(two.points[0]);
  g.n_gamma = 4;
  g.n_beta = 4;
  CHECK_THROWS_WITH(compute_sphere_map_3d(two, g), Catch::Contains("facets"));
  Map3dOptions o;
  o.facets = 8;
  o.point = 2;
  CHECK_THROWS_WITH(compute_sphere_map_3d(two, g, o), Catch::Contains("point"));
  CHECK_THROWS_WITH(parse_map_3d_parameter("alpha", 1), Catch::Contains("alpha_X"));
  CHECK_THROWS_WITH(parse_map_3d_parameter("mu@3", 2), Catch::Contains("1..2"));
  Map3dAxis ax{parse_map_3d_parameter("alpha_X", 1), -1, 1, 5};
  CHECK_THROWS_WITH(compute_param_direction_map_3d(sys, ax, 10, 0, 2 * kPi, 0),
                    Catch::Contains("alpha_X = -1"));
  Map3dAxis ok{parse_map_3d_parameter("mu", 1), 1, 2, 3};
  CHECK_THROWS_WITH(compute_param_param_map_3d(sys, ok, ok), Catch::Contains("same quantity"));
  Map3dAxis c{parse_map_3d_parameter("C_T", 1), 0, 1, 3};
  CHECK_THROWS_WITH(compute_param_param_map_3d(sys, ok, c), Catch::Contains("dF"));
  ok.from = std::nan("");
  CHECK_THROWS_AS(compute_param_direction_map_3d(sys, ok, 10, 0, 2 * kPi, 0), InputError);
  // a state-d point whose traction leaves the changed ellipse
  const ContactSystem3d d = one_point(decoupled_A(), 2.0, 0.0, {1, 1}, 'd', 1.0, {2.0, 0});
  CHECK_THROWS_WITH(compute_param_direction_map_3d(d, Map3dAxis{parse_map_3d_parameter("mu", 1), 1, 2, 3},
                                                   10, 0, 2 * kPi, 0),
                    Catch::Contains("mu = 1"));
}

TEST_CASE("3-D maps: one time limit for the whole map (issue 24, item 11)", "[rate3d][map]") {
  // Eight grazing points in a chain, 4 facets: one cell's solve (2^8 separation cases) runs
  // far longer than the budget.
  const int n = 8;
  ContactSystem3d s;
  s.A = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    s.A.block<3, 3>(3 * i, 3 * i) << 1.0, 0.0, 0.3, 0.0, 1.0, 0.2, 0.3, 0.2, 1.5;
    if (i + 1 < n) {
      s.A(3 * i, 3 * i + 3) = s.A(3 * i + 3, 3 * i) = 0.1;
      s.A(3 * i + 1, 3 * i + 4) = s.A(3 * i + 4, 3 * i + 1) = 0.1;
      s.A(3 * i + 2, 3 * i + 5) = s.A(3 * i + 5, 3 * i + 2) = 0.2;
      s.A(3 * i, 3 * i + 5) = s.A(3 * i + 5, 3 * i) = 0.05;
      s.A(3 * i + 2, 3 * i + 3) = s.A(3 * i + 3, 3 * i + 2) = 0.05;
    }
    SystemPoint3d p;
    p.mu = 3;
    p.C_T = 0.25;
    p.state.state = 'b';
    s.points.push_back(p);
  }
  SphereGrid g;
  g.n_beta = 1;
  g.n_gamma = 3;
  Map3dOptions o;
  o.facets = 4;
  o.threads = 1;
  o.time_limit_s = 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  const Map3d m = compute_sphere_map_3d(s, g, o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(m.timed_out_cells == 3);  // the first cut short, the others not computed
  CHECK(m.incomplete_cells == 3);
  for (int j = 0; j < 3; ++j) CHECK_FALSE(m.complete_at(0, j));
  CHECK(seconds < 10);  // about 0.5 s; the bound allows a slow (sanitizer) build
  o.time_limit_s = 0;
  CHECK_THROWS_AS(compute_sphere_map_3d(s, g, o), InputError);
}
