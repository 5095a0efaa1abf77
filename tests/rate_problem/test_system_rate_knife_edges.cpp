// Issue 24: no N-point answer printed as complete when it is wrong. A 2-point system (both points
// grazing, coupled A) is solved at each of its critical directions of the load dF = (cos t,
// sin t, 0.3, -0.2) with dF_T1 moved by -3..3 ulps: the answer must be the exact set of that
// double load or say complete: false. 1e-6 rad on either side it must be the exact set, complete.
// Independent source: tests/data/system_rate_knife_edges.py solves every type tuple of the model
// in exact rational arithmetic (fractions) on the doubles' exact values and wrote the table.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "cpkit/rate_problem/system/contact_system.hpp"
#include "cpkit/rate_problem/rate/system_rate.hpp"

using namespace cpkit::rate;

namespace {

struct Row {
  double fT1, fN1;
  int count;
  bool ambiguous;      ///< a point of several tuples: only the count is compared
  bool must_complete;  ///< away from the critical direction: the data decide
  const char* types;   ///< the exact set's type tuples, sorted, space-separated
};

const Row kRows[] = {
#include "knife_edge_rows.inc"
};

const char* kSystem = R"({"name": "two grazing points", "A": [[1, 2, 0.25, 0.1], [2, 5, 0.1, 0.5],
  [0.25, 0.1, 1, 0.3], [0.1, 0.5, 0.3, 2]],
  "points": [{"state": "b", "mu": 1, "C_T": 0}, {"state": "b", "mu": 0.5, "C_T": 0.25}]})";

std::string tuples(const SystemRateSolutionSet& s) {
  std::vector<std::string> v;
  for (const auto& p : s.solutions) {
    std::string t;
    for (const SolutionType x : p.types) t += (t.empty() ? "" : "/") + std::string(to_string(x));
    v.push_back(t);
  }
  std::sort(v.begin(), v.end());
  std::string out;
  for (const auto& t : v) out += (out.empty() ? "" : " ") + t;
  return out;
}

}  // namespace

TEST_CASE("N-point rate problem at critical directions +- ulps: the exact set or not complete",
          "[rate][system][critical]") {
  const ContactSystem S = parse_contact_system(kSystem);
  int complete = 0, knife = 0;
  for (const Row& r : kRows) {
    Eigen::VectorXd dF(4);
    dF << r.fT1, r.fN1, 0.3, -0.2;
    const SystemRateSolutionSet s = solve_rate_problem(S, dF);
    CAPTURE(r.fT1, r.fN1, r.types, s.message, tuples(s));
    if (r.must_complete) CHECK(s.complete);
    if (!s.complete) continue;
    CHECK(!s.infinite);
    CHECK(s.count() == r.count);
    if (!r.ambiguous) CHECK(tuples(s) == r.types);
    ++complete;
    knife += r.must_complete ? 0 : 1;
  }
  // not vacuous: the 16 rows 1e-6 rad away are all decided. Of the 56 ulp-perturbed loads the
  // N-point route decides 1 today (it has no exact evaluation of its signs, issue 34): at least
  // that one must stay decided, so that "complete: false" for every row cannot pass the loop.
  CHECK(complete >= 16);
  INFO(knife << " of the ulp-perturbed loads were decided (the others say complete: false)");
  CHECK(knife >= 1);
}
