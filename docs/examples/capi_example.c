/* cpkit from C (docs/library.md): build with a C compiler alone,
 *   gcc -std=c99 capi_example.c $(pkg-config --cflags --libs cpkit) -o capi_example
 * Hand answers: M = [[2, 1], [1, 2]], q = (-5, -6) has z = (4/3, 7/3), w = 0 (M z = -q, z > 0);
 * one contact with W = I, q = (-1, 0.2, 0), mu = 0.5 sticks: u = 0, r = -q = (1, -0.2, 0),
 * inside the cone (|r_T| = 0.2 <= 0.5 r_N). */
#include <cpkit/cpkit.h>
#include <math.h>
#include <stdio.h>

int main(void) {
  const double M[4] = {2, 1, 1, 2}; /* column-major */
  const double q[2] = {-5, -6};
  double z[2], w[2];
  cpkit_info info;
  int s = cpkit_lcp_solve(2, M, q, "lemke", NULL, z, w, &info);
  printf("lcp: status %d, z = (%.15g, %.15g)\n", s, z[0], z[1]);
  if (s != 0 || fabs(z[0] - 4.0 / 3) > 1e-12 || fabs(z[1] - 7.0 / 3) > 1e-12) return 1;

  /* One contact: W = I in compressed sparse columns (0-based), normal first. */
  const int col_ptr[4] = {0, 1, 2, 3}, row_index[3] = {0, 1, 2};
  const double values[3] = {1, 1, 1}, qc[3] = {-1, 0.2, 0}, mu[1] = {0.5};
  double r[3], u[3];
  cpkit_options options;
  cpkit_default_options(&options);
  options.tol = 1e-12;
  s = cpkit_fc3d_solve(1, 3, col_ptr, row_index, values, qc, mu, "auto", &options, r, u, &info);
  printf("contact: status %d, r = (%.15g, %.15g, %.15g)\n", s, r[0], r[1], r[2]);
  if (s != 0 || fabs(r[0] - 1) > 1e-12 || fabs(r[1] + 0.2) > 1e-12 || fabs(r[2]) > 1e-12) return 1;

  /* Bad input is a status with a message, never a crash or an exit. */
  s = cpkit_lcp_solve(-1, M, q, "lemke", NULL, z, w, &info);
  printf("n = -1: status %d: %s\n", s, info.message);
  if (s != 2 || info.status != 2) return 1;
  const double q_nan[2] = {NAN, -6};
  s = cpkit_lcp_solve(2, M, q_nan, "lemke", NULL, z, w, &info);
  printf("NaN in q: status %d: %s\n", s, info.message);
  return s == 2 ? 0 : 1;
}
