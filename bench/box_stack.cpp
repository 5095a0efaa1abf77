// A brick-bond wall of boxes on a floor (packing.hpp).
#include <algorithm>
#include <random>
#include <stdexcept>

#include "packing.hpp"

namespace cpkit::bench {

Packing box_stack(const BoxStackOptions& o) {
  if (o.rows < 1 || o.columns < 2 || o.layers < 1 || !(o.a > 0 && o.b > 0 && o.c > 0) ||
      !(o.mu_min >= 0 && o.mu_max >= o.mu_min) || !(o.step > 0))
    throw std::invalid_argument("box_stack: bad options");
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), mu(o.mu_min, o.mu_max);
  Packing p;
  p.name = "boxes_" + std::to_string(o.rows) + "x" + std::to_string(o.columns) + "x" +
           std::to_string(o.layers) + "_seed" + std::to_string(o.seed);
  p.step = o.step;
  // first[row][layer]: index of the layer's first box; odd layers hold columns - 1 boxes,
  // shifted by a / 2, each resting on two boxes.
  auto count = [&](int layer) { return layer % 2 ? o.columns - 1 : o.columns; };
  std::vector<std::vector<int>> first(static_cast<size_t>(o.rows));
  for (int row = 0; row < o.rows; ++row)
    for (int layer = 0; layer < o.layers; ++layer) {
      first[static_cast<size_t>(row)].push_back(static_cast<int>(p.bodies.size()));
      for (int i = 0; i < count(layer); ++i) {
        RigidBody box;
        box.center = Vec3(o.a / 2 + o.a * i + (layer % 2 ? o.a / 2 : 0), o.b / 2 + 1.1 * o.b * row,
                          o.c / 2 + o.c * layer);
        box.mass = o.density * (1 + 0.1 * unit(rng)) * o.a * o.b * o.c;
        box.inertia = box.mass / 12 *
                      Vec3(o.b * o.b + o.c * o.c, o.a * o.a + o.c * o.c, o.a * o.a + o.b * o.b);
        for (int k = 0; k < 3; ++k) box.velocity[k] = o.speed * unit(rng);
        p.bodies.push_back(box);
      }
    }
  const Mat3 up = contact_frame(Vec3(0, 0, 1));
  // Four contacts at the corners of the overlap [x0, x1] x [y0, y1] of B's bottom face.
  auto rest = [&](int a, int b, double x0, double x1) {
    const RigidBody& B = p.bodies[static_cast<size_t>(b)];
    const double y0 = B.center.y() - o.b / 2, y1 = B.center.y() + o.b / 2;
    const double z = B.center.z() - o.c / 2;
    for (const double x : {x0, x1})
      for (const double y : {y0, y1}) {
        Contact ct;
        ct.body_a = a;
        ct.body_b = b;
        ct.point = Vec3(x, y, z);
        ct.frame = up;
        ct.gap = 0;
        ct.mu = mu(rng);
        p.contacts.push_back(ct);
      }
  };
  for (int row = 0; row < o.rows; ++row)
    for (int layer = 0; layer < o.layers; ++layer)
      for (int i = 0; i < count(layer); ++i) {
        const int b = first[static_cast<size_t>(row)][static_cast<size_t>(layer)] + i;
        const double bx = p.bodies[static_cast<size_t>(b)].center.x();
        if (layer == 0) {
          rest(-1, b, bx - o.a / 2, bx + o.a / 2);
          continue;
        }
        // The boxes below that overlap this one: indices i - 1 .. i + 1 of the layer below.
        const int below = first[static_cast<size_t>(row)][static_cast<size_t>(layer - 1)];
        for (int m = std::max(0, i - 1); m <= std::min(count(layer - 1) - 1, i + 1); ++m) {
          const double ax = p.bodies[static_cast<size_t>(below + m)].center.x();
          const double x0 = std::max(ax, bx) - o.a / 2, x1 = std::min(ax, bx) + o.a / 2;
          if (x1 - x0 > 1e-9 * o.a) rest(below + m, b, x0, x1);
        }
      }
  return p;
}

}  // namespace cpkit::bench
