// Spheres on a jittered simple cubic lattice in a box (packing.hpp).
#include <cmath>
#include <random>
#include <stdexcept>

#include "packing.hpp"

namespace cpkit::bench {

Packing sphere_packing(const SpherePackingOptions& o) {
  if (o.nx < 1 || o.ny < 1 || o.nz < 1 || !(o.radius > 0) || !(o.contact_gap >= 0) ||
      !(o.radius_jitter >= 0 && o.radius_jitter < 0.5) || !(o.position_jitter >= 0) ||
      !(o.mu_min >= 0 && o.mu_max >= o.mu_min) || !(o.step > 0))
    throw std::invalid_argument("sphere_packing: bad options");
  const double R = o.radius, spacing = 2 * R;
  const Vec3 box(o.nx * spacing, o.ny * spacing, 0);
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), mu(o.mu_min, o.mu_max);

  Packing p;
  p.name = "spheres_" + std::to_string(o.nx) + "x" + std::to_string(o.ny) + "x" +
           std::to_string(o.nz) + "_seed" + std::to_string(o.seed);
  p.step = o.step;
  std::vector<double> radius;
  for (int k = 0; k < o.nz; ++k)
    for (int j = 0; j < o.ny; ++j)
      for (int i = 0; i < o.nx; ++i) {
        RigidBody s;
        const double r = R * (1 + o.radius_jitter * unit(rng));
        s.center = Vec3(R + spacing * i, R + spacing * j, R + spacing * k);
        for (int a = 0; a < 3; ++a) s.center[a] += o.position_jitter * R * unit(rng);
        s.mass = o.density * 4.0 / 3.0 * M_PI * r * r * r;
        s.inertia = Vec3::Constant(0.4 * s.mass * r * r);
        for (int a = 0; a < 3; ++a) s.velocity[a] = o.speed * unit(rng);
        p.bodies.push_back(s);
        radius.push_back(r);
      }
  const double threshold = o.contact_gap * R;
  auto index = [&](int i, int j, int k) { return (k * o.ny + j) * o.nx + i; };
  for (int k = 0; k < o.nz; ++k)
    for (int j = 0; j < o.ny; ++j)
      for (int i = 0; i < o.nx; ++i) {
        const int b = index(i, j, k);
        const Vec3 c = p.bodies[static_cast<size_t>(b)].center;
        const double r = radius[static_cast<size_t>(b)];
        // The floor and the four walls: normal from the wall into the sphere.
        const struct { Vec3 normal; double distance; } walls[] = {
            {Vec3(0, 0, 1), c.z()},           {Vec3(1, 0, 0), c.x()},
            {Vec3(-1, 0, 0), box.x() - c.x()}, {Vec3(0, 1, 0), c.y()},
            {Vec3(0, -1, 0), box.y() - c.y()}};
        for (const auto& w : walls) {
          const double gap = w.distance - r;
          if (gap > threshold) continue;
          Contact ct;
          ct.body_a = -1;
          ct.body_b = b;
          ct.frame = contact_frame(w.normal);
          ct.point = c - r * w.normal;
          ct.gap = gap;
          ct.mu = mu(rng);
          p.contacts.push_back(ct);
        }
        // Spheres of the 26 neighbouring sites with a larger index (each pair once); farther
        // sites are at least 4 R - 2 sqrt(3) position_jitter R apart, beyond any contact.
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if (ii < 0 || jj < 0 || kk < 0 || ii >= o.nx || jj >= o.ny || kk >= o.nz) continue;
              const int other = index(ii, jj, kk);
              if (other <= b) continue;
              const Vec3 d = p.bodies[static_cast<size_t>(other)].center - c;
              const double dist = d.norm();
              const double gap = dist - r - radius[static_cast<size_t>(other)];
              if (gap > threshold) continue;
              Contact ct;
              ct.body_a = b;
              ct.body_b = other;
              const Vec3 n = d / dist;
              ct.frame = contact_frame(n);
              ct.point = c + (r + gap / 2) * n;
              ct.gap = gap;
              ct.mu = mu(rng);
              p.contacts.push_back(ct);
            }
      }
  return p;
}

}  // namespace cpkit::bench
