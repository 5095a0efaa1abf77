// Checks of the packing generator (packing.hpp) against independent computations, on small
// instances (well under a second). Exit 0 when every check passes, 1 otherwise.
// - contacts: the sphere packing's contacts are exactly the pairs (sphere-sphere over all
//   pairs, sphere-wall over all walls) with gap <= threshold, found by brute force; the brick
//   wall's count is the hand count 4 c + (L - 1) 8 (c - 1);
// - W and q: column 3c + k of W is the change of every contact's local velocity caused by a unit
//   impulse frame_c e_k at contact c, computed with Newton-Euler by hand (dv = +-P / m,
//   dw = I^-1 (arm x P)) and rigid-body kinematics, without J; q likewise from v_free and
//   max(gap, 0) / h;
// - W symmetric and positive semidefinite: eigenvalues of the dense W (Eigen's self-adjoint
//   solver) >= -1e-12 lambda_max; frames orthonormal and right-handed;
// - real problems: cpkit's nsgs (in relative_q) and, when built with it, Siconos' NSGS solve each
//   small packing to |F_nat|/|q| <= 1e-8 as cpkit's verdict and Siconos' fc3d_compute_error
//   both judge it.
// Usage: bench_packing_check
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/measure_solve.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "packing.hpp"
#include "siconos_friction.hpp"

namespace {

using cpkit::bench::Contact;
using cpkit::bench::Packing;
using cpkit::bench::Vec3;

int failures = 0;

void expect(bool ok, const char* what, double value = NAN) {
  if (!ok) {
    ++failures;
    std::printf("FAIL %s (%g)\n", what, value);
  }
}

// Velocity of body b's material point at x (b = -1: a fixed wall).
Vec3 point_velocity(const Packing& p, int b, const Eigen::VectorXd& v, const Vec3& x) {
  if (b < 0) return Vec3::Zero();
  const Vec3 lin = v.segment<3>(6 * b), ang = v.segment<3>(6 * b + 3);
  return lin + ang.cross(x - p.bodies[static_cast<size_t>(b)].center);
}

// Local velocities of every contact for body velocities v (3 n_c).
Eigen::VectorXd local_velocities(const Packing& p, const Eigen::VectorXd& v) {
  Eigen::VectorXd u(3 * static_cast<Eigen::Index>(p.contacts.size()));
  for (size_t c = 0; c < p.contacts.size(); ++c) {
    const Contact& k = p.contacts[c];
    const Vec3 rel = point_velocity(p, k.body_b, v, k.point) - point_velocity(p, k.body_a, v, k.point);
    u.segment<3>(3 * static_cast<Eigen::Index>(c)) = k.frame.transpose() * rel;
  }
  return u;
}

// W and q of the packing by Newton-Euler impulses (header comment), dense.
void check_against_impulses(const Packing& p, const cpkit::FrictionContactProblem& fc) {
  const Eigen::Index nc = static_cast<Eigen::Index>(p.contacts.size());
  const Eigen::Index nb = static_cast<Eigen::Index>(p.bodies.size());
  const Eigen::MatrixXd W = Eigen::MatrixXd(fc.W);
  const double scale = W.cwiseAbs().maxCoeff();
  double worst = 0;
  for (Eigen::Index c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k) {
      const Contact& ct = p.contacts[static_cast<size_t>(c)];
      const Vec3 P = ct.frame.col(k);  // unit impulse in the world frame
      Eigen::VectorXd dv = Eigen::VectorXd::Zero(6 * nb);
      for (const auto& [b, sign] : {std::pair<int, double>{ct.body_b, 1.0}, {ct.body_a, -1.0}}) {
        if (b < 0) continue;
        const cpkit::bench::RigidBody& body = p.bodies[static_cast<size_t>(b)];
        dv.segment<3>(6 * b) += sign * P / body.mass;
        dv.segment<3>(6 * b + 3) +=
            (sign * (ct.point - body.center).cross(P)).cwiseQuotient(body.inertia);
      }
      const Eigen::VectorXd du = local_velocities(p, dv);
      worst = std::max(worst, (du - W.col(3 * c + k)).cwiseAbs().maxCoeff());
    }
  expect(worst <= 1e-12 * scale, "W equals the Newton-Euler impulse responses", worst / scale);

  Eigen::VectorXd v(6 * nb);
  for (Eigen::Index b = 0; b < nb; ++b) {
    v.segment<3>(6 * b) = p.bodies[static_cast<size_t>(b)].velocity + p.step * p.gravity;
    v.segment<3>(6 * b + 3) = p.bodies[static_cast<size_t>(b)].spin;
  }
  Eigen::VectorXd q = local_velocities(p, v);
  for (Eigen::Index c = 0; c < nc; ++c) q[3 * c] += std::max(0.0, p.contacts[static_cast<size_t>(c)].gap) / p.step;
  const double q_err = (q - fc.q).cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff();
  expect(q_err <= 1e-13, "q equals the kinematic free velocities plus max(gap, 0) / h", q_err);

  expect((W - W.transpose()).cwiseAbs().maxCoeff() == 0, "W exactly symmetric");
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(W).eigenvalues();
  expect(ev.minCoeff() >= -1e-12 * ev.maxCoeff(), "W positive semidefinite", ev.minCoeff() / ev.maxCoeff());
  for (const Contact& ct : p.contacts) {
    const double orth = (ct.frame.transpose() * ct.frame - cpkit::bench::Mat3::Identity()).cwiseAbs().maxCoeff();
    expect(orth <= 1e-14 && ct.frame.determinant() > 0, "frame orthonormal, right-handed", orth);
  }
  std::printf("%s: %zu bodies, %ld contacts, eigenvalues of W in [%.3g, %.3g], "
              "impulse check %.1e, q check %.1e\n",
              p.name.c_str(), p.bodies.size(), static_cast<long>(nc), ev.minCoeff(), ev.maxCoeff(),
              worst / scale, q_err);
}

// Both solvers solve the packing's problem to 1e-8 in |F_nat|/|q|, by both checks.
void check_solvable(const cpkit::FrictionContactProblem& fc) {
  constexpr double tol = 1e-8;
  cpkit::CommonOptions o;
  o.tol = tol;
  o.max_iterations = 100000;
  const cpkit::SolveResult r = cpkit::lcp::friction::solve_in_measure(
      fc, *cpkit::lcp::solvers().find("nsgs"), o, cpkit::FrictionMeasure::kRelativeQ);
  const double ours = cpkit::friction_errors(fc, r.z).relative_q;
  expect(r.status == cpkit::Status::kSolved && ours <= tol, "cpkit nsgs solves it", ours);
  std::printf("  cpkit nsgs: %d sweeps, |F|/|q| %.1e (cpkit's check)", r.iterations, ours);
#ifdef CPKIT_HAVE_SICONOS
  cpkit::bench::SiconosFriction sp(fc);
  expect(sp.error(r.z) <= tol, "Siconos' check accepts cpkit's answer", sp.error(r.z));
  Eigen::VectorXd z = Eigen::VectorXd::Zero(fc.q.size()), u = z;
  SolverOptions* so = solver_options_create(SICONOS_FRICTION_3D_NSGS);
  so->dparam[SICONOS_DPARAM_TOL] = tol / 10;  // its own stop is relative to max(|q|, |r|, |u|)
  so->iparam[SICONOS_IPARAM_MAX_ITER] = 100000;
  const int info = fc3d_driver(sp.get(), z.data(), u.data(), so);
  const int sweeps = so->iparam[SICONOS_IPARAM_ITER_DONE];
  solver_options_delete(so);
  const double theirs = sp.error(z), theirs_by_cpkit = cpkit::friction_errors(fc, z).relative_q;
  expect(info == 0 && theirs <= tol && theirs_by_cpkit <= tol, "Siconos NSGS solves it", theirs);
  std::printf("; Siconos NSGS: %d sweeps, |F|/|q| %.1e (Siconos' check), %.1e (cpkit's)", sweeps,
              theirs, theirs_by_cpkit);
#endif
  std::printf("\n");
}

// The sphere packing's contacts against a brute-force search over all pairs and walls.
void check_sphere_contacts(const cpkit::bench::SpherePackingOptions& o, const Packing& p) {
  // Radii from the masses (m = density 4/3 pi r^3).
  std::vector<double> radius;
  for (const auto& b : p.bodies) radius.push_back(std::cbrt(b.mass / (o.density * 4.0 / 3.0 * M_PI)));
  const double Lx = 2 * o.radius * o.nx, Ly = 2 * o.radius * o.ny, threshold = o.contact_gap * o.radius;
  std::set<std::tuple<int, int, int>> expected;  // (a, b, wall id or -1)
  for (int b = 0; b < static_cast<int>(p.bodies.size()); ++b) {
    const Vec3 c = p.bodies[static_cast<size_t>(b)].center;
    const double r = radius[static_cast<size_t>(b)];
    const double wall_distance[5] = {c.z(), c.x(), Lx - c.x(), c.y(), Ly - c.y()};
    for (int w = 0; w < 5; ++w)
      if (wall_distance[w] - r <= threshold) expected.insert({-1, b, w});
    for (int a = 0; a < b; ++a) {
      const double gap = (c - p.bodies[static_cast<size_t>(a)].center).norm() - r -
                         radius[static_cast<size_t>(a)];
      if (gap <= threshold) expected.insert({a, b, -1});
    }
  }
  const Vec3 wall_normal[5] = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)};
  std::set<std::tuple<int, int, int>> found;
  for (const Contact& ct : p.contacts) {
    int w = -1;
    if (ct.body_a < 0)
      for (int k = 0; k < 5; ++k)
        if ((ct.frame.col(0) - wall_normal[k]).norm() < 1e-15) w = k;
    found.insert({ct.body_a, ct.body_b, w});
  }
  expect(found.size() == p.contacts.size(), "no contact twice");
  expect(found == expected, "contacts equal the brute-force search",
         static_cast<double>(expected.size()) - static_cast<double>(found.size()));
  expect(expected.size() >= 2 * p.bodies.size(), "a packing: at least two contacts a sphere",
         static_cast<double>(expected.size()));
}

}  // namespace

int main() {
  // 20 spheres (5 x 2 x 2), then a looser one where lattice jitter matters (gaps up to 0.25 R).
  for (const double jitter : {0.0005, 0.05}) {
    cpkit::bench::SpherePackingOptions o;
    o.nx = 5, o.ny = 2, o.nz = 2;
    o.radius_jitter = jitter;
    o.position_jitter = jitter;
    o.contact_gap = jitter < 0.01 ? 0.01 : 0.25;
    const Packing p = cpkit::bench::sphere_packing(o);
    check_sphere_contacts(o, p);
    check_against_impulses(p, cpkit::bench::packing_problem(p));
    check_solvable(cpkit::bench::packing_problem(p));
  }
  cpkit::bench::BoxStackOptions o;
  o.rows = 2, o.columns = 3, o.layers = 3;
  const Packing boxes = cpkit::bench::box_stack(o);
  const size_t hand = static_cast<size_t>(o.rows * (4 * o.columns + (o.layers - 1) * 8 * (o.columns - 1)));
  expect(boxes.contacts.size() == hand, "brick wall: 4 c + (L - 1) 8 (c - 1) contacts a row",
         static_cast<double>(boxes.contacts.size()));
  check_against_impulses(boxes, cpkit::bench::packing_problem(boxes));
  check_solvable(cpkit::bench::packing_problem(boxes));
  std::printf(failures ? "%d check(s) FAILED\n" : "all checks passed\n", failures);
  return failures ? 1 : 0;
}
