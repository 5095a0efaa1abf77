// Issue 34: the paper's one-point rate problem at EXACT critical loads of binary data (parameters
// multiples of 2^-10, the load exactly on N = 0 or L_s = 0; a sixth of the state-d points on the
// parameter boundary Lambda = 0 exactly) is decided exactly: complete, the exact count, types and
// rates, exit 0 (1 when there is none). It used to answer "not complete" (exit 5): the rounding
// bound of the certified signs can never decide a zero formed from rounded products.
//
// Independent source: tests/data/rate_boundary_family.py solves every solution type from the
// model's rate equations in exact rationals (Python fractions) on these doubles and wrote the
// rows (rate_boundary_rows.inc, seeded; the closed forms N, L_s only place the loads).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cpkit/rate_problem/rate/point_rate.hpp"
#include "cpkit/rate_problem/requests/rate_request.hpp"

using namespace cpkit::rate;

namespace {

struct Expected {
  double dP_T, dP_N, dw_Ti;
};

struct Row {
  char state;
  double a11, a12, a22, mu, C_T, k_a, P_s, P_N;
  int sgn_PT;
  double dF_T, dF_N;
  const char* line;   ///< the critical line the load lies on
  int count;          ///< the exact count
  const char* types;  ///< the exact types, sorted as Python's sorted(), space-separated
  Expected sol[3];    ///< each solution's rates in the order of `types`
};

const Row kRows[] = {
#include "rate_boundary_rows.inc"
};

/// The types of a set sorted by name (Python's sorted(): separation, slip+, slip-, stick).
std::vector<const RateSolution*> sorted_by_type(const RateSolutionSet& s) {
  std::vector<const RateSolution*> v;
  for (const auto& p : s.solutions) v.push_back(&p);
  std::sort(v.begin(), v.end(), [](const RateSolution* a, const RateSolution* b) {
    return to_string(a->type) < to_string(b->type);
  });
  return v;
}

std::string type_names(const RateSolutionSet& s) {
  std::string out;
  for (const RateSolution* p : sorted_by_type(s))
    out += (out.empty() ? "" : " ") + std::string(to_string(p->type));
  return out;
}

ContactParameters params_of(const Row& r) {
  ContactParameters p;
  p.a11 = r.a11, p.a12 = r.a12, p.a22 = r.a22, p.mu = r.mu, p.C_T = r.C_T;
  p.k_a = r.k_a, p.P_s = r.P_s;
  return p;
}

ContactState state_of(const Row& r) {
  ContactState st;
  st.label = r.state == 'b' ? StateLabel::kB : StateLabel::kD;
  st.P_N = r.P_N;
  st.sgn_PT = r.sgn_PT;
  return st;
}

}  // namespace

TEST_CASE("rate problem at exact critical loads of binary data: decided exactly (issue 34)",
          "[rate][critical][exact]") {
  int rows = 0, multiple = 0, none = 0, lambda_zero = 0;
  for (const Row& r : kRows) {
    const ContactParameters p = params_of(r);
    const ContactState st = state_of(r);
    const LoadRate f{r.dF_T, r.dF_N};
    CAPTURE(r.state, r.a11, r.a12, r.a22, r.mu, r.C_T, r.k_a, r.P_s, r.P_N, r.sgn_PT, r.dF_T,
            r.dF_N, r.line, r.types);
    const CheckedRateSolution c = solve_rate_problem_checked(p, st, f, RateMethod::kEnumerate);
    const RateSolutionSet& s = c.set;
    CAPTURE(s.message, c.problem, type_names(s));
    CHECK(c.problem.empty());
    CHECK(s.complete);
    REQUIRE(s.count() == r.count);
    CHECK(type_names(s) == r.types);
    // the rates to the rounding of the computation (the oracle's are the exact rationals rounded)
    const std::vector<const RateSolution*> sol = sorted_by_type(s);
    const double scale = (std::abs(r.dF_T) + std::abs(r.dF_N)) * (1 + r.C_T + 1 / r.a11 + 1 / r.a22);
    for (int k = 0; k < r.count; ++k) {
      CHECK(sol[k]->kind == RateSolution::Kind::kPoint);
      CHECK(sol[k]->start.dP_T == Approx(r.sol[k].dP_T).margin(1e-12 * scale));
      CHECK(sol[k]->start.dP_N == Approx(r.sol[k].dP_N).margin(1e-12 * scale));
      CHECK(sol[k]->start.dw_Ti == Approx(r.sol[k].dw_Ti).margin(1e-12 * scale));
    }
    // the analytic route decides the same set (its signs, where the bound cannot, exactly)
    const RateSolutionSet a = solve_rate_problem(p, st, f, RateMethod::kAnalytic);
    CHECK(a.complete);
    CHECK(a.count() == r.count);
    CHECK(type_names(a) == r.types);
    // (the maps' summaries are not asked: at a computed critical direction, a rounded point of
    // the line, they want the set on the line and flag it unreliable; test_map_direction)
    ++rows;
    multiple += r.count > 1 ? 1 : 0;
    none += r.count == 0 ? 1 : 0;
    lambda_zero += std::string(r.line) == "Lambda=0" ? 1 : 0;
  }
  // the family as generated: 480 loads, of them several with 2 solutions and some with none
  CHECK(rows == 480);
  CHECK(multiple >= 40);
  CHECK(none >= 4);
  CHECK(lambda_zero >= 10);
}

TEST_CASE("cpkit rate's request at exact critical loads: exit 0 (1 with no solution), no note "
          "of an undecided sign", "[rate][critical][exact]") {
  for (const Row& r : kRows) {
    RateRequest q;
    q.state = std::string(1, r.state);
    q.model = {r.a11, r.a12, r.a22, r.mu, r.C_T, r.k_a, r.P_s, std::nullopt};
    q.P_N = r.P_N;
    if (r.state == 'd') q.sgn_PT = r.sgn_PT;  // --sgnPT applies to state d only
    q.dF = {r.dF_T, r.dF_N};
    const RateOutcome out = run_rate_request(q);
    CAPTURE(r.state, r.a11, r.a12, r.a22, r.mu, r.C_T, r.dF_T, r.dF_N, r.line, r.types);
    CHECK(out.exit_code == (r.count == 0 ? cpkit::kExitNoSolution : cpkit::kExitOk));
    CHECK(out.notes.empty());
  }
}
