#pragma once
// Test helper: a SmallSolutionSet (enumerate_small, SmallPreparedLcp) in the form the brute-force
// checker (enumerate_brute_force.hpp) judges.
#include "cpkit/lcp/enumerate_small.hpp"
#include "lcp/enumerate_brute_force.hpp"

template <int N>
brute::Found to_found(const cpkit::lcp::SmallSolutionSet<N>& out) {
  brute::Found f;
  for (int p = 0; p < out.num_points; ++p) {
    f.z.emplace_back(out.z[p].data(), out.z[p].data() + N);
    f.w.emplace_back(out.w[p].data(), out.w[p].data() + N);
  }
  for (int k = 0; k < out.num_pieces; ++k) {
    brute::Found::Piece pc;
    pc.support = out.pieces[k].support;
    for (int p = 0; p < out.num_points; ++p)
      if ((out.pieces[k].vertex_mask >> p) & 1u) pc.vertices.push_back(p);
    for (int r = 0; r < out.pieces[k].num_rays; ++r)
      pc.rays.emplace_back(out.pieces[k].rays[r].data(), out.pieces[k].rays[r].data() + N);
    f.pieces.push_back(pc);
  }
  f.infinite = out.infinite;
  return f;
}
