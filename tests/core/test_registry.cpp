// SolverRegistry: names, duplicates, capabilities.
#include <catch2/catch.hpp>

#include "cpkit/core/registry.hpp"

namespace {

cpkit::SolverEntry entry(const std::string& name, bool lcp, bool box, bool sparse = false) {
  cpkit::SolverEntry e;
  e.info.name = name;
  e.info.sparse = sparse;
  if (lcp)
    e.solve_lcp = [name](const cpkit::LcpProblem&, const cpkit::CommonOptions&) {
      cpkit::SolveResult r;
      r.solver = name;
      return r;
    };
  if (box)
    e.solve_box_lcp = [](const cpkit::BoxLcpProblem&, const cpkit::CommonOptions&) {
      return cpkit::SolveResult{};
    };
  return e;
}

}  // namespace

TEST_CASE("Registry: add, find, names in order", "[registry]") {
  cpkit::SolverRegistry r;
  r.add(entry("b", true, false));
  r.add(entry("a", false, true));
  r.add(entry("c", true, true, true));
  CHECK(r.names() == std::vector<std::string>{"b", "a", "c"});
  CHECK(r.names(cpkit::ProblemKind::kLcp) == std::vector<std::string>{"b", "c"});
  CHECK(r.names(cpkit::ProblemKind::kBoxLcp) == std::vector<std::string>{"a", "c"});
  CHECK(r.names(cpkit::ProblemKind::kMcp).empty());
  REQUIRE(r.find("c") != nullptr);
  CHECK(r.find("c")->solve_lcp(cpkit::LcpProblem{}, {}).solver == "c");
  CHECK(r.find("nope") == nullptr);
  CHECK(r.entries().size() == 3);
}

TEST_CASE("Registry: duplicate and empty names throw", "[registry]") {
  cpkit::SolverRegistry r;
  r.add(entry("lemke", true, false));
  CHECK_THROWS_AS(r.add(entry("lemke", true, false)), std::invalid_argument);
  CHECK_THROWS_WITH(r.add(entry("lemke", false, true)), Catch::Contains("duplicate solver name 'lemke'"));
  CHECK_THROWS_WITH(r.add(entry("", true, false)), Catch::Contains("empty solver name"));
  CHECK(r.names().size() == 1);
}

TEST_CASE("SolverEntry::accepts checks the kind and the storage", "[registry]") {
  cpkit::LcpProblem dense(cpkit::Mat::Identity(2, 2), cpkit::Vec::Ones(2));
  cpkit::LcpProblem sparse;
  sparse.M_sparse = dense.M.sparseView();
  sparse.q = dense.q;
  const auto d = entry("d", true, false, false);
  const auto s = entry("s", true, false, true);
  const auto b = entry("b", false, true);
  CHECK(d.accepts(dense));
  CHECK_FALSE(d.accepts(sparse));
  CHECK(s.accepts(sparse));
  CHECK_FALSE(b.accepts(dense));
  CHECK(b.accepts(cpkit::ProblemKind::kBoxLcp));
  CHECK_FALSE(b.accepts(cpkit::ProblemKind::kLcp));
}
