// LCPs, box LCPs and NCPs/MCPs solved as MPCCs (Ipopt and NLopt). Expected answers come from
// the problem files' "expected" blocks (literature / closed form) and shared/problems/ncp.md.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/lcp/mpcc_solvers.hpp"
#include "cpkit/lcp/solvers.hpp"

using cpkit::Mat;
using cpkit::Status;
using cpkit::Vec;
using namespace cpkit::lcp;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct FileCase {
  std::string name;
  cpkit::LcpProblem problem;
  nlohmann::json expected;
};

FileCase load(const std::string& name) {
  const std::string path = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/" + name + ".json";
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  return {name, cpkit::read_lcp_file(path), j.at("expected")};
}

const std::vector<std::string> kSolvable = {
    "battle_of_the_sexes", "cps_4_qp",      "cps_example_4_4_16", "cps_example_4_4_7",
    "cps_remark_4_1_14",   "deudeu",        "gould_nonconvex_qp", "lemke_cycling_circulant",
    "murty_exp_6",         "ortiz",         "pang_isolated",      "siconos_exp_murty_qe_6"};
const std::vector<std::string> kInfeasible = {"infeasible_copositive_plus",
                                              "pang_isolated_perturbed"};

bool near_any(const Vec& z, const nlohmann::json& solutions, double tol) {
  for (const auto& s : solutions) {
    Vec v(static_cast<Eigen::Index>(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) v(static_cast<Eigen::Index>(i)) = s[i].get<double>();
    if (v.size() == z.size() && (v - z).lpNorm<Eigen::Infinity>() <= tol * (1 + v.norm()))
      return true;
  }
  return false;
}

/// Captures everything written to file descriptor 1 while `fn` runs.
template <class Fn>
std::string capture_stdout(Fn fn) {
  std::fflush(stdout);
  char name[] = "/tmp/cpkit_mpcc_stdout_XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  const int saved = dup(1);
  dup2(fd, 1);
  fn();
  std::fflush(stdout);
  dup2(saved, 1);
  close(saved);
  std::string text;
  std::ifstream in(name);
  std::getline(in, text, '\0');
  close(fd);
  std::remove(name);
  return text;
}

class CollectSink : public cpkit::LogSink {
 public:
  void write(cpkit::LogLevel, std::string_view message) override {
    std::lock_guard<std::mutex> lock(mutex_);
    lines.emplace_back(message);
  }
  std::vector<std::string> lines;

 private:
  std::mutex mutex_;
};

}  // namespace

TEST_CASE("LCP files with solutions are solved through the MPCC", "[mpcc][lcp]") {
  const auto backend = GENERATE(NlpBackend::kIpopt, NlpBackend::kNlopt);
  const auto name = GENERATE(from_range(kSolvable));
  CAPTURE(name, to_string(backend));
  const FileCase c = load(name);
  ComplementarityMpccOptions o;
  o.mpcc.backend = backend;
  const cpkit::SolveResult r = solve_lcp_mpcc(c.problem, o);
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK(r.solver == std::string(to_string(backend)));
  CHECK(r.residuals.natural <= 1e-10);
  // Finite solution sets are listed completely in the files: the answer must be one of them.
  if (c.expected.value("complete", false) && !c.expected.value("continuum", false))
    CHECK(near_any(r.z, c.expected.at("solutions"), 1e-8));
}

TEST_CASE("infeasible LCPs are never reported solved by the MPCC route", "[mpcc][lcp]") {
  const auto backend = GENERATE(NlpBackend::kIpopt, NlpBackend::kNlopt);
  const auto name = GENERATE(from_range(kInfeasible));
  CAPTURE(name, to_string(backend));
  const FileCase c = load(name);
  ComplementarityMpccOptions o;
  o.mpcc.backend = backend;
  o.restarts = 2;  // keeps the test fast; every restart must fail as well
  const cpkit::SolveResult r = solve_lcp_mpcc(c.problem, o);
  INFO(r.message);
  CHECK_FALSE(cpkit::is_solution(r.status));
  CHECK(r.status != Status::kInfeasible);  // the MPCC route has no certificate
}

TEST_CASE("the selection objective picks the equilibrium nearest a reference",
          "[mpcc][lcp][selection]") {
  // battle_of_the_sexes has exactly three solutions (file: complete list).
  const FileCase c = load("battle_of_the_sexes");
  const auto k = GENERATE(0, 1, 2);
  const auto& sol = c.expected.at("solutions")[static_cast<std::size_t>(k)];
  Vec target(4);
  for (int i = 0; i < 4; ++i) target(i) = sol[static_cast<std::size_t>(i)].get<double>();
  CAPTURE(k);
  ComplementarityMpccOptions o;
  o.reference = target + Vec::Constant(4, 0.01);  // close to solution k, far from the others
  o.mpcc.common.record_trace = true;
  const cpkit::SolveResult r = solve_lcp_mpcc(c.problem, o);
  INFO(r.message);
  REQUIRE(r.status == Status::kSolved);
  CHECK((r.z - target).lpNorm<Eigen::Infinity>() <= 1e-8);
  CHECK(!r.trace.empty());  // one entry per NLP
}

TEST_CASE("a relaxation stopped early is reported with complementarity violated",
          "[mpcc][lcp]") {
  const FileCase c = load("deudeu");
  ComplementarityMpccOptions o;
  o.mpcc.t_initial = 1.0;
  o.mpcc.t_min = 1.0;  // one subproblem: z_i w_i <= 1 only
  o.newton_polish = false;
  o.restarts = 0;
  MpccResult details;
  const cpkit::SolveResult r = solve_lcp_mpcc(c.problem, o, &details);
  INFO(r.message);
  CHECK_FALSE(cpkit::is_solution(r.status));
  CHECK(details.status == Status::kStalled);
  CHECK(details.subproblems.size() == 1);
  CHECK(r.message.find("complementarity violated") != std::string::npos);
}

TEST_CASE("NCPs and MCPs of shared/problems/ncp.md through the MPCC", "[mpcc][mcp]") {
  const auto backend = GENERATE(NlpBackend::kIpopt, NlpBackend::kNlopt);
  CAPTURE(to_string(backend));
  ComplementarityMpccOptions o;
  o.mpcc.backend = backend;
  SECTION("billups: x* = 1 + sqrt(1.01)") {
    auto p = cpkit::make_ncp(
        1, [](const Vec& x, Vec& F) { F.resize(1); F(0) = (x(0) - 1) * (x(0) - 1) - 1.01; return true; },
        [](const Vec& x, Mat& J) { J.resize(1, 1); J(0, 0) = 2 * (x(0) - 1); return true; },
        "billups");
    // From x0 = 0 the NLPs are locally infeasible (F(0) = -0.01 and F decreases towards
    // x = 1): the route may fail there, but must then say so; from x0 = 3 it must succeed.
    p.x0 = Vec::Zero(1);
    const auto r0 = solve_mcp_mpcc(p, o);
    INFO(r0.message);
    if (cpkit::is_solution(r0.status)) CHECK(r0.z(0) == Approx(1 + std::sqrt(1.01)).epsilon(1e-10));
    p.x0 = Vec::Constant(1, 3.0);
    const auto r = solve_mcp_mpcc(p, o);
    INFO(r.message);
    REQUIRE(r.status == Status::kSolved);
    CHECK(r.z(0) == Approx(1 + std::sqrt(1.01)).epsilon(1e-10));
  }
  SECTION("munson1: (1, 0, 0), unique") {
    auto p = cpkit::make_ncp(
        3,
        [](const Vec& x, Vec& F) {
          F.resize(3);
          F << x(0) + 2 * x(1) + 3 * x(2) - 1, x(1) - x(2) + 1, x(0) + x(1) + 1;
          return true;
        },
        {}, "munson1");  // no Jacobian: finite differences
    const auto r = solve_mcp_mpcc(p, o);
    INFO(r.message);
    REQUIRE(cpkit::is_solution(r.status));
    CHECK((r.z - Vec::Unit(3, 0)).lpNorm<Eigen::Infinity>() <= 1e-6);
  }
  SECTION("siconos_mcp_mixed: z1 free, z2 >= 0, (4/3, 7/3)") {
    cpkit::McpProblem p;
    p.n = 2;
    p.F = [](const Vec& z, Vec& F) { F.resize(2); F << 2 * z(0) + z(1) - 5, z(0) + 2 * z(1) - 6; return true; };
    p.jacobian = [](const Vec&, Mat& J) { J.resize(2, 2); J << 2, 1, 1, 2; return true; };
    p.lower = Vec(2);
    p.lower << -kInf, 0;
    p.upper = Vec::Constant(2, kInf);
    const auto r = solve_mcp_mpcc(p, o);
    INFO(r.message);
    REQUIRE(r.status == Status::kSolved);
    CHECK(r.z(0) == Approx(4.0 / 3).epsilon(1e-10));
    CHECK(r.z(1) == Approx(7.0 / 3).epsilon(1e-10));
  }
  SECTION("path_linear_box as a box LCP on [0, 10]^4: (2.8, 0, 0.8, 1.2)") {
    cpkit::BoxLcpProblem b;
    b.lcp.M = Mat(4, 4);
    b.lcp.M << 0, 0, -1, -1, 0, 0, 1, -2, 1, -1, 2, -2, 1, 2, -2, 4;
    b.lcp.q = Vec(4);
    b.lcp.q << 2, 2, -2, -6;
    b.lower = Vec::Zero(4);
    b.upper = Vec::Constant(4, 10);
    const auto r = solve_box_lcp_mpcc(b, o);
    INFO(r.message);
    REQUIRE(r.status == Status::kSolved);
    Vec expect(4);
    expect << 2.8, 0, 0.8, 1.2;
    CHECK((r.z - expect).lpNorm<Eigen::Infinity>() <= 1e-8);
  }
  SECTION("path_nonlinear_box on [0, 10]^4: interior solution to ~6 digits") {
    cpkit::McpProblem p;
    p.n = 4;
    p.F = [](const Vec& x, Vec& F) {
      F.resize(4);
      F << -x(2) * x(2) - x(3) + 2, std::pow(x(2), 3) - 2 * x(3) * x(3) + 2,
          std::pow(x(0), 5) - x(1) + 2 * x(2) - 2 * x(3) - 2,
          x(0) + 2 * std::pow(x(1), 3) - 2 * x(2) + 4 * x(3) - 6;
      return true;
    };
    p.jacobian = [](const Vec& x, Mat& J) {
      J.setZero(4, 4);
      J(0, 2) = -2 * x(2), J(0, 3) = -1;
      J(1, 2) = 3 * x(2) * x(2), J(1, 3) = -4 * x(3);
      J(2, 0) = 5 * std::pow(x(0), 4), J(2, 1) = -1, J(2, 2) = 2, J(2, 3) = -2;
      J(3, 0) = 1, J(3, 1) = 6 * x(1) * x(1), J(3, 2) = -2, J(3, 3) = 4;
      return true;
    };
    p.lower = Vec::Zero(4);
    p.upper = Vec::Constant(4, 10);
    p.x0 = Vec::Ones(4);
    const auto r = solve_mcp_mpcc(p, o);
    INFO(r.message);
    REQUIRE(r.status == Status::kSolved);
    Vec expect(4);
    expect << 1.28475, 0.972916, 0.909376, 1.17304;
    CHECK((r.z - expect).lpNorm<Eigen::Infinity>() <= 1e-5);
  }
}

TEST_CASE("Ipopt never writes to stdout; its journal goes to the log sink", "[mpcc][io]") {
  const FileCase c = load("ortiz");
  SECTION("silent at verbosity 0") {
    const std::string out = capture_stdout([&] {
      const auto r = solve_lcp_ipopt(c.problem);
      CHECK(r.status == Status::kSolved);
    });
    CHECK(out.empty());
  }
  SECTION("verbosity 3 forwards Ipopt's output to the sink, not to stdout") {
    CollectSink sink;
    cpkit::CommonOptions common;
    common.log = &sink;
    common.verbosity = 3;
    const std::string out = capture_stdout([&] {
      const auto r = solve_lcp_ipopt(c.problem, common);
      CHECK(r.status == Status::kSolved);
    });
    CHECK(out.empty());
    bool saw_ipopt = false;
    for (const auto& l : sink.lines) saw_ipopt |= l.rfind("ipopt: ", 0) == 0;
    CHECK(saw_ipopt);
  }
}

TEST_CASE("concurrent Ipopt solves are serialized and all succeed", "[mpcc][threads]") {
  const FileCase c = load("gould_nonconvex_qp");
  std::vector<Status> status(4, Status::kNotRun);
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < status.size(); ++k)
    threads.emplace_back([&, k] { status[k] = solve_lcp_ipopt(c.problem).status; });
  for (auto& t : threads) t.join();
  for (Status s : status) CHECK(s == Status::kSolved);
}

TEST_CASE("registry entries ipopt and nlopt exist and bad input throws", "[mpcc][input]") {
  const auto* ipopt = solvers().find("ipopt");
  REQUIRE(ipopt != nullptr);
  CHECK(ipopt->info.serialized);
  REQUIRE(solvers().find("nlopt") != nullptr);
  cpkit::LcpProblem bad(Mat::Identity(2, 2), Vec::Constant(3, 1.0));
  CHECK_THROWS_AS(ipopt->solve_lcp(bad, {}), cpkit::InputError);
  const FileCase c = load("deudeu");
  ComplementarityMpccOptions o;
  o.reference = Vec::Ones(5);
  CHECK_THROWS_AS(solve_lcp_mpcc(c.problem, o), cpkit::InputError);
  o = ComplementarityMpccOptions{};
  o.mpcc.rho_factor = 0.5;
  CHECK_THROWS_AS(solve_lcp_mpcc(c.problem, o), cpkit::InputError);
}
