// validate() of the problem types and of CommonOptions: each message names what is wrong.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"

namespace {
using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_CASE("LcpProblem::validate names the problem", "[validate]") {
  CHECK(LcpProblem(Mat::Identity(2, 2), Vec::Ones(2)).validate().empty());
  CHECK_THAT(LcpProblem().validate(), Contains("q is empty"));
  CHECK_THAT(LcpProblem(Mat::Identity(2, 2), Vec::Ones(3)).validate(),
             Contains("size mismatch") && Contains("2 x 2") && Contains("3 entries"));
  CHECK_THAT(LcpProblem(Mat::Ones(2, 3), Vec::Ones(2)).validate(),
             Contains("not square") && Contains("2 x 3"));
  Mat m = Mat::Identity(3, 3);
  m(2, 1) = NAN;
  CHECK_THAT(LcpProblem(m, Vec::Ones(3)).validate(),
             Contains("M has a non-finite entry at (2, 1)"));
  m(2, 1) = -kInf;
  CHECK_THAT(LcpProblem(m, Vec::Ones(3)).validate(), Contains("(2, 1)"));
  CHECK_THAT(LcpProblem(Mat::Identity(3, 3), Vec{{1, kInf, 0}}).validate(),
             Contains("q has a non-finite entry at [1]"));
}

TEST_CASE("Sparse LcpProblem::validate", "[validate][sparse]") {
  LcpProblem p;
  p.M_sparse = Mat::Identity(3, 3).sparseView();
  p.q = Vec::Ones(3);
  CHECK(p.is_sparse());
  CHECK(p.validate().empty());
  p.q = Vec::Ones(2);
  CHECK_THAT(p.validate(), Contains("size mismatch"));
  p.q = Vec::Ones(3);
  p.M_sparse.coeffRef(0, 2) = NAN;
  CHECK_THAT(p.validate(), Contains("non-finite entry at (0, 2)"));
  LcpProblem r;
  r.M_sparse = Mat::Ones(2, 3).sparseView();
  r.q = Vec::Ones(2);
  CHECK_THAT(r.validate(), Contains("not square"));
  // w() and dense_M() agree with the dense computation.
  p.M_sparse.coeffRef(0, 2) = 4;
  const Mat d = p.dense_M();
  CHECK(d(0, 2) == 4);
  CHECK(p.w(Vec{{1, 2, 3}}) == d * Vec{{1, 2, 3}} + p.q);
}

TEST_CASE("BoxLcpProblem and McpProblem validate", "[validate]") {
  cpkit::BoxLcpProblem b{LcpProblem(Mat::Identity(2, 2), Vec::Ones(2)), Vec{{0, -kInf}},
                         Vec{{1, kInf}}};
  CHECK(b.validate().empty());
  b.lower = Vec{{2, 0}};
  CHECK_THAT(b.validate(), Contains("bound 0 has l > u"));
  b.lower = Vec{{0, NAN}};
  CHECK_THAT(b.validate(), Contains("bound 1 is invalid"));
  b.lower = Vec{{0}};
  CHECK_THAT(b.validate(), Contains("bounds have sizes 1 and 2"));

  auto F = [](const Vec& x, Vec& f) {
    f = x;
    return true;
  };
  auto m = cpkit::make_ncp(2, F);
  CHECK(m.validate().empty());
  CHECK(m.is_ncp());
  m.x0 = Vec::Ones(3);
  CHECK_THAT(m.validate(), Contains("x0 has size 3"));
  m.x0 = Vec{{1, NAN}};
  CHECK_THAT(m.validate(), Contains("x0 has a non-finite entry"));
  m.x0.resize(0);
  m.F = nullptr;
  CHECK_THAT(m.validate(), Contains("F callback is missing"));
  CHECK_THAT(cpkit::McpProblem{}.validate(), Contains("n must be >= 1"));
}

TEST_CASE("lcp_as_mcp evaluates F(z) = M z + q with the exact Jacobian", "[problem]") {
  const LcpProblem p(Mat{{1, 2}, {3, 4}}, Vec{{-1, 1}});
  const auto m = cpkit::lcp_as_mcp(p);
  CHECK(m.is_ncp());
  Vec F;
  REQUIRE(m.F(Vec{{1, 1}}, F));
  CHECK(F == Vec{{2, 8}});
  Mat J;
  REQUIRE(m.jacobian);
  REQUIRE(m.jacobian(Vec{{1, 1}}, J));
  CHECK(J == p.M);
}

TEST_CASE("CommonOptions::validate names the field", "[validate][options]") {
  cpkit::CommonOptions o;
  CHECK(o.validate().empty());
  o.tol = 0;
  CHECK_THAT(o.validate(), Contains("tol must be a positive finite number"));
  o.tol = NAN;
  CHECK_THAT(o.validate(), Contains("tol"));
  o = {};
  o.tol_acceptable = 1e-12;  // below tol
  CHECK_THAT(o.validate(), Contains("tol_acceptable"));
  o = {};
  o.max_iterations = -1;
  CHECK_THAT(o.validate(), Contains("max_iterations must be >= 0"));
  o = {};
  o.time_limit_s = 0;
  CHECK_THAT(o.validate(), Contains("time_limit_s"));
  o = {};
  o.verbosity = 4;
  CHECK_THAT(o.validate(), Contains("verbosity"));
}

TEST_CASE("throw_if_invalid", "[errors]") {
  CHECK_NOTHROW(cpkit::throw_if_invalid(""));
  CHECK_THROWS_AS(cpkit::throw_if_invalid("bad", "ctx"), cpkit::InputError);
  CHECK_THROWS_WITH(cpkit::throw_if_invalid("bad", "ctx"), "ctx: bad");
  CHECK_THROWS_AS(cpkit::throw_if_invalid("bad"), std::invalid_argument);
}
