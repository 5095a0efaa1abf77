#pragma once
// Test helper (not a test): a minimal reader of Siconos 4.4 FrictionContact .dat files (dense
// storage 0 and sparse-block storage 1), written here from the files' layout so that h16's
// tests can load real problems by a route independent of cpkit's own reader:
//   dim, n_c, storage, then
//   storage 0: rows, cols, "rows cols", the entries, read in column-major order as Siconos
//              4.4's reader does (its writer prints a row per line: the Rover files' W, not
//              symmetric to ~1e-6, are transposed by the round trip; cpkit follows the reader);
//   storage 1: rows, cols, number of blocks, block rows, block cols, the cumulative row and
//              column block sizes, filled1, filled2, index1 (filled1), index2 (filled2), then
//              per block its number and 9 values (column-major);
//   then q (3 n_c) and mu (n_c).
#include <Eigen/SparseCore>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::test {

inline FrictionContactProblem read_dat(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  int dim = 0, nc = 0, storage = 0;
  in >> dim >> nc >> storage;
  if (dim != 3) throw std::runtime_error(path + ": dimension " + std::to_string(dim));
  const int n = 3 * nc;
  std::vector<Eigen::Triplet<double>> t;
  if (storage == 0) {
    int rows = 0, cols = 0, r2 = 0, c2 = 0;
    in >> rows >> cols >> r2 >> c2;
    for (int j = 0; j < n; ++j)  // column-major, as Siconos 4.4's reader fills it
      for (int i = 0; i < n; ++i) {
        double v = 0;
        in >> v;
        if (v != 0) t.emplace_back(i, j, v);
      }
  } else if (storage == 1) {
    int rows = 0, cols = 0, blocks = 0, b0 = 0, b1 = 0, f1 = 0, f2 = 0;
    in >> rows >> cols >> blocks >> b0 >> b1;
    std::vector<int> skip(static_cast<std::size_t>(b0 + b1));
    for (int& s : skip) in >> s;
    in >> f1 >> f2;
    std::vector<int> i1(static_cast<std::size_t>(f1)), i2(static_cast<std::size_t>(f2));
    for (int& v : i1) in >> v;
    for (int& v : i2) in >> v;
    for (int br = 0; br + 1 < f1; ++br)
      for (int k = i1[br]; k < i1[br + 1]; ++k) {
        int number = 0;
        in >> number;
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) {
            double v = 0;
            in >> v;
            if (v != 0) t.emplace_back(3 * br + r, 3 * i2[k] + c, v);
          }
      }
  } else {
    throw std::runtime_error(path + ": storage " + std::to_string(storage));
  }
  FrictionContactProblem p;
  p.W.resize(n, n);
  p.W.setFromTriplets(t.begin(), t.end());
  p.q.resize(n);
  for (int i = 0; i < n; ++i) in >> p.q[i];
  p.mu.resize(nc);
  for (int i = 0; i < nc; ++i) in >> p.mu[i];
  if (!in) throw std::runtime_error(path + ": truncated");
  p.name = path;
  return p;
}

}  // namespace cpkit::test
