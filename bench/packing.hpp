#pragma once
/// \file packing.hpp
/// Seeded granular packings as 3-D frictional contact problems, for benchmarks beyond the sizes
/// of FCLIB's collection (issue 35): spheres in a box and a brick-bond wall of boxes on a floor.
///
/// Mechanics (one time step of Moreau-Jean's scheme, restitution 0, SI units):
/// - bodies are rigid, 6 velocities each: v (translation, m/s), w (rotation, rad/s, world frame);
///   their principal axes are the world axes (spheres, axis-aligned boxes), so the mass matrix of
///   body b is diag(m, m, m, I_x, I_y, I_z); walls and the floor are fixed (no velocities);
/// - contact c joins body A (-1: a wall, the floor) and body B at the point x, with the unit
///   normal n from A to B and tangents t1 = frame.col(1), t2 = frame.col(2) (frame = [n t1 t2],
///   orthonormal, right-handed). Its local velocity is
///     u_c = frame^T (v_B + w_B x (x - x_B) - v_A - w_A x (x - x_A))   (u_N > 0: separating),
///   i.e. u = J v with J of 3 rows per contact and 6 columns per body (contact_jacobian);
/// - the impulse r_c (frame components, N s) acts +r on B and -r on A, so u = W r + q with
///     W = J M^-1 J^T (sparse: contact c couples only with the contacts sharing a body with it),
///     q = J v_free + (max(g_c, 0) / h, 0, 0),  v_free = v + h M^-1 f_gravity,
///   g_c the gap at the start of the step (m; < 0 is an overlap) and h the step (s). An open
///   contact may close within the step; an overlap is not pushed apart (g_c < 0 counts as 0):
///   pushing overlaps apart at -g_c / h can ask a row of spheres between two fixed walls to grow,
///   a problem with no solution.
/// The packing's W is symmetric positive semidefinite by construction (W = G G^T, G = J M^-1/2)
/// and generally singular (more contact rows than body velocities), as real packings are.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::bench {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct RigidBody {
  Vec3 center = Vec3::Zero();   ///< m
  double mass = 1;              ///< kg
  Vec3 inertia = Vec3::Ones();  ///< principal moments about the world axes, kg m^2
  Vec3 velocity = Vec3::Zero(); ///< m/s, at the start of the step
  Vec3 spin = Vec3::Zero();     ///< rad/s, at the start of the step
};

struct Contact {
  int body_a = -1;  ///< index into Packing::bodies, or -1 for a fixed wall / the floor
  int body_b = 0;   ///< index into Packing::bodies (always a body)
  Vec3 point = Vec3::Zero();       ///< contact point, m
  Mat3 frame = Mat3::Identity();   ///< columns n (A to B), t1, t2
  double gap = 0;                  ///< m, < 0: overlap
  double mu = 0.3;                 ///< Coulomb friction coefficient
};

struct Packing {
  std::string name;
  std::vector<RigidBody> bodies;
  std::vector<Contact> contacts;
  double step = 1e-3;                    ///< h, s
  Vec3 gravity = Vec3(0, 0, -9.81);      ///< m/s^2
};

/// Spheres on a simple cubic lattice in a box (floor z = 0, walls x = 0, x = L_x, y = 0, y = L_y;
/// no lid): nx x ny x nz sites of spacing 2 R, each holding a sphere of radius uniform in
/// [R (1 - radius_jitter), R (1 + radius_jitter)] whose center is moved by up to
/// position_jitter R along each axis. Contacts: every sphere pair and sphere-wall pair with gap
/// <= contact_gap R (found on a grid of cells). Initial velocities uniform in
/// [-1, 1] speed per component, spins 0; mu uniform in [mu_min, mu_max] per contact.
struct SpherePackingOptions {
  int nx = 4, ny = 4, nz = 4;
  double radius = 0.01;           ///< R, m
  double radius_jitter = 0.02;
  double position_jitter = 0.01;
  double contact_gap = 0.1;       ///< detection threshold, in units of R
  double density = 2500;          ///< kg/m^3
  double speed = 0.01;            ///< m/s
  double mu_min = 0.3, mu_max = 0.5;
  double step = 1e-3;             ///< s
  std::uint32_t seed = 2026;
};
Packing sphere_packing(const SpherePackingOptions& options);

/// A brick-bond wall of boxes on a floor: rows x columns x layers boxes of size a x b x c
/// (a along x), layer k shifted by a / 2 along x when k is odd, so that a box rests on two
/// boxes below (and the wall is held together); `rows` walls side by side along y with a gap of
/// 0.1 b between them (no contact between walls). Every resting face gives 4 contacts, at the
/// corners of the overlap of the two faces (normal +z); the first layer rests on the floor.
/// Densities uniform in [0.9, 1.1] density per box, velocities uniform in [-1, 1] speed per
/// component, spins 0; mu uniform in [mu_min, mu_max] per contact; gaps 0.
struct BoxStackOptions {
  int rows = 1, columns = 4, layers = 4;
  double a = 0.2, b = 0.1, c = 0.05;  ///< box size, m
  double density = 2000;              ///< kg/m^3
  double speed = 0.01;                ///< m/s
  double mu_min = 0.5, mu_max = 0.7;
  double step = 1e-3;                 ///< s
  std::uint32_t seed = 2026;
};
Packing box_stack(const BoxStackOptions& options);

/// J: 3 n_c x 6 n_b, u = J v (header comment); v ordered body by body (v_x, v_y, v_z, w_x, w_y, w_z).
Eigen::SparseMatrix<double> contact_jacobian(const Packing& packing);

/// The body velocities v_free = v + h M^-1 f_gravity (6 n_b).
Eigen::VectorXd free_velocity(const Packing& packing);

/// The local problem of the packing's step (header comment): W = J M^-1 J^T, q, mu.
FrictionContactProblem packing_problem(const Packing& packing);

/// An orthonormal right-handed frame [n t1 t2] with n = normal (unit): t1 is n x e normalised,
/// e the axis least aligned with n.
Mat3 contact_frame(const Vec3& normal);

}  // namespace cpkit::bench
