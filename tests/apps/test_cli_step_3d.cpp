// `cpkit step --system FILE` with a "dim": 3 file (apps/step_3d.cpp) end to end. Independent
// source: the 2-D command line (`cpkit step --a11 ... --all`, the active-set enumeration) on an
// isotropic point whose Y direction is decoupled and unloaded, where the 3-D step must give the
// 2-D solutions (every mode: --all, --chain, --facets with even K, --multistart); and bad input
// (exit 2 with the problem named, nothing on stdout). N > 1 coupled points (FB-SOC Newton,
// --multistart) against the 2-D N-point command line (`cpkit step --system 2-D FILE --all`) for
// isotropic points whose Y directions are decoupled and unloaded.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

namespace {

using Run = cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;

std::string num(double x) {
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

/// A one-point 3-D file: A = [[a11, 0, a12], [0, aYY, 0], [a12, 0, a22]], isotropic.
std::string write_point(const std::string& name, double a11, double a12, double a22, double aYY,
                        double mu, double C_T, const std::string& extra_point_fields) {
  const auto path = scratch_dir() / (name + ".json");
  std::ofstream f(path);
  f << "{\"name\": \"" << name << "\", \"dim\": 3, \"A\": [[" << num(a11) << ", 0, " << num(a12)
    << "], [0, " << num(aYY) << ", 0], [" << num(a12) << ", 0, " << num(a22)
    << "]], \"points\": [{\"mu\": " << num(mu) << ", \"C_T\": " << num(C_T) << extra_point_fields
    << "}]}";
  return "'" + path.string() + "'";
}

struct Case {
  double a11, a12, a22, aYY, mu, C_T;
  char state;
  double P_T0, P_N0;
  double DFX, DFN;
};

std::string file_of(const Case& c, int i) {
  std::string extra = std::string(", \"state\": \"") + c.state + "\"";
  if (c.state == 'c' || c.state == 'd')
    extra += ", \"P_N\": " + num(c.P_N0) + ", \"P_T\": [" + num(c.P_T0) + ", 0]";
  return write_point("p" + std::to_string(i), c.a11, c.a12, c.a22, c.aYY, c.mu, c.C_T, extra);
}

std::string two_d_args(const Case& c) {
  return "step --a11 " + num(c.a11) + " --a12 " + num(c.a12) + " --a22 " + num(c.a22) +
         " --mu " + num(c.mu) + " --C_T " + num(c.C_T) + " --P_T0 " + num(c.P_T0) + " --P_N0 " +
         num(c.P_N0) + " --g0 0 --DF " + num(c.DFX) + " " + num(c.DFN);
}

bool in_2d(const nlohmann::json& s3, const nlohmann::json& two_d, double F) {
  if (std::abs(s3["P_T1"][1].get<double>()) > 1e-7 * F) return false;
  for (const auto& s : two_d["solutions"])
    if (s["kind"] == "point" &&
        std::abs(s["values"]["P_T1"].get<double>() - s3["P_T1"][0].get<double>()) <= 1e-6 * F &&
        std::abs(s["values"]["P_N1"].get<double>() - s3["P_N1"].get<double>()) <= 1e-6 * F)
      return true;
  return false;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  // State d with Lambda = a11 - mu a12 < 0: three 2-D solutions (separation, stick, slip+).
  out.push_back({1, 0.9, 1, 0.7, 2, 0, 'd', 2, 1, -0.01, 0});
  out.push_back({1, 0.9, 1, 0.7, 2, 0, 'd', 2, 1, 0.01, 0});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
  for (int i = 0; i < 10; ++i) {
    Case c;
    c.a11 = 0.2 + 2 * pos(rng);
    c.a22 = 0.2 + 2 * pos(rng);
    c.a12 = 0.9 * u(rng) * std::sqrt(c.a11 * c.a22);
    c.aYY = 0.3 + pos(rng);
    c.mu = 0.2 + 2 * pos(rng);
    c.C_T = i % 2 ? 0 : pos(rng);
    c.state = "bcd"[i % 3];
    c.P_N0 = c.state == 'b' ? 0 : 1 + pos(rng);
    c.P_T0 = c.state == 'b' ? 0 : c.state == 'c' ? 0.5 * u(rng) * c.mu * c.P_N0 : c.mu * c.P_N0;
    const double th = 3.14159265358979 * u(rng);
    c.DFX = std::cos(th);
    c.DFN = std::sin(th);
    out.push_back(c);
  }
  return out;
}

}  // namespace

TEST_CASE("cpkit step, 3-D point with a decoupled Y direction: the 2-D solutions in every mode",
          "[cli][step3d]") {
  int i = 0, several = 0, local_failed = 0;
  for (const Case& c : cases()) {
    const std::string file = file_of(c, i++);
    const Run r2 = run_cpkit(two_d_args(c) + " --all --json");
    REQUIRE(r2.code == 0);
    const auto two_d = nlohmann::json::parse(r2.out);
    if (two_d["count"] == "inf") continue;
    const int n2 = two_d["count"].get<int>();
    if (n2 > 1) ++several;
    const double F = std::max({std::abs(c.DFX), std::abs(c.DFN), std::abs(c.P_T0), c.P_N0});
    const std::string base = "step --system " + file + " --DF " + num(c.DFX) + " 0 " + num(c.DFN);
    CAPTURE(i, base, n2);
    // --all: every solution, exactly
    const Run all = run_cpkit(base + " --all --json");
    CAPTURE(all.err);
    REQUIRE(all.code == 0);
    const auto ja = nlohmann::json::parse(all.out);
    CHECK(ja["complete"] == true);
    CHECK(ja["count"] == n2);
    for (const auto& s : ja["solutions"]) CHECK(in_2d(s, two_d, F));
    CHECK(ja["cpkit_version"].is_string());
    CHECK(ja.contains("run"));
    CHECK(ja["input"]["DF"].size() == 3);
    CHECK(ja["input"]["mode"] == "all");
    // the default chain: the exact link answers, with the solution nearest the start state
    const Run def = run_cpkit(base + " --json");
    REQUIRE(def.code == 0);
    const auto jd = nlohmann::json::parse(def.out);
    CHECK(jd["solver"] == "exact");
    REQUIRE(jd["solutions"].size() == 1);
    CHECK(in_2d(jd["solutions"][0], two_d, F));
    // --chain of the local solvers: one verified solution, one of the 2-D ones, or exit 1 (a
    // local method may stall: e.g. the jump to separation from state d, far from the start)
    const Run ch = run_cpkit(base + " --chain fb-soc,ipopt --json");
    REQUIRE((ch.code == 0 || ch.code == 1));
    const auto jc = nlohmann::json::parse(ch.out);
    CHECK(jc["attempts"].size() >= 1);
    if (ch.code == 1) {
      ++local_failed;
      CHECK(jc["status"] == "no_solution");
      CHECK(jc["solutions"].empty());
    } else {
      CHECK(jc["status"] == "solved");
      REQUIRE(jc["solutions"].size() == 1);
      const auto& s = jc["solutions"][0];
      for (const char* k : {"type", "P_T1", "P_N1", "DP", "Dw", "Dw_Ti", "Dw_w", "lambda",
                            "slip_direction", "slip_angle", "residual"})
        CHECK(s.contains(k));
      CHECK(s["residual"].get<double>() <= 1e-9);
      CHECK(in_2d(s, two_d, F));
    }
    // --facets with even K: the vertices +-X hold the 2-D law exactly
    const Run fa = run_cpkit(base + " --facets 8 --json");
    REQUIRE(fa.code == 0);
    const auto jf = nlohmann::json::parse(fa.out);
    CHECK(jf["count"] == n2);
    for (const auto& x : jf["solutions"]) CHECK(in_2d(x, two_d, F));
    // --multistart: verified 2-D solutions, never claimed complete
    const Run ms = run_cpkit(base + " --multistart 6 --json");
    REQUIRE(ms.code == 0);
    const auto jm = nlohmann::json::parse(ms.out);
    CHECK(jm["complete"] == false);
    CHECK(jm["found"].get<int>() <= n2);
    for (const auto& x : jm["solutions"]) CHECK(in_2d(x, two_d, F));
  }
  CHECK(several >= 1);
  CHECK(local_failed <= 2);
}

TEST_CASE("cpkit step, 3-D: state a (open) with --g0, text output, Mroz wear", "[cli][step3d]") {
  const std::string open = write_point("open", 1, 0.3, 1, 1, 0.5, 0, ", \"state\": \"a\"");
  const Run r = run_cpkit("step --system " + open + " --g0 -0.5 --DF 0.1 0.2 0.1 --all");
  CHECK(r.code == 0);
  CHECK(r.out.find("count: 1") != std::string::npos);
  CHECK(r.out.find("open: ") != std::string::npos);
  // closing the gap: a normal load of 1 on a gap of 0.01 -> contact
  const Run c = run_cpkit("step --system " + open + " --g0 -0.01 --DF 0 0 1 --json");
  REQUIRE(c.code == 0);
  const auto j = nlohmann::json::parse(c.out);
  CHECK(j["solutions"][0]["P_N1"].get<double>() > 0);
  const std::string d = write_point("dm", 1, 0.2, 1, 1, 0.5, 0,
                                    ", \"state\": \"d\", \"P_N\": 1, \"P_T\": [0.5, 0]");
  const Run m = run_cpkit("step --system " + d + " --wear-law mroz --k_M 0.1 --DF 0.2 0.1 0 --all --json");
  REQUIRE(m.code == 0);
  const auto jm = nlohmann::json::parse(m.out);
  CHECK(jm["input"]["wear_law"] == "mroz-stupkiewicz");
  bool wear = false;
  for (const auto& s : jm["solutions"]) wear = wear || s["Dw_w"].get<double>() > 0;
  CHECK(wear);
}

TEST_CASE("cpkit step, 3-D: bad input exits 2 naming the problem", "[cli][step3d]") {
  const std::string b = write_point("b", 1, 0.3, 1, 1, 0.5, 0, ", \"state\": \"b\"");
  const std::string worn = write_point("w", 1, 0.3, 1, 1, 0.5, 0, ", \"state\": \"b\", \"k_a\": 0.3");
  const std::string open = write_point("a", 1, 0.3, 1, 1, 0.5, 0, ", \"state\": \"a\"");
  const std::string two = std::string("'") + CPKIT_SOURCE_DIR + "/docs/examples/two_point_system_3d.json'";
  const std::pair<std::string, std::string> bad[] = {
      {"step --system " + two + " --DF 1 0 1 0 0 1 --all", "one point"},
      {"step --system " + worn + " --DF 1 0 1 --facets 8", "--facets"},
      {"step --system " + b + " --DF 1 0 1 --all --chain exact", "--chain"},
      {"step --system " + b + " --DF 1 0 1 --all --facets 8", "alternative modes"},
      {"step --system " + b + " --DF 1 0 1 --facets 8 --multistart 3", "alternative modes"},
      {"step --system " + b + " --DF 1 0", "3 numbers"},
      {"step --system " + b + " --DF 1 0 1 --g0 -1", "--g0"},
      {"step --system " + open + " --DF 1 0 1", "--g0"},
      {"step --system " + b + " --DF 1 0 1 --chain exact,lemke", "lemke"},
      {"step --system " + b + " --DF 1 0 1 --multistart 0", "--multistart"},
      {"step --system " + b + " --DF 1 0 1 --facets 2", "facets"},
      {"step --system " + b + " --DF 1 0 1 --mu 0.3", "--mu"},
      {"step --system " + worn + " --DF 1 0 1 --wear-law mroz --k_M 0.1", "k_a"},
      {"step --a11 1 --a12 0 --a22 1 --mu 0.5 --P_T0 0 --P_N0 1 --g0 0 --DF 0.1 0 --facets 8",
       "dim"},
  };
  for (const auto& [args, what] : bad) {
    const Run r = run_cpkit(args);
    CAPTURE(args, r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(what) != std::string::npos);
  }
}

namespace {
/// The 2-D counterpart (X-N DOFs) of docs/examples/two_point_system_3d.json.
std::string two_d_of_example() {
  const auto path = scratch_dir() / "two_point_2d_of_3d.json";
  std::ofstream f(path);
  f << R"({"name": "2-D of two_point_system_3d",
 "A": [[1.0, 0.3, 0.2, 0.1], [0.3, 1.0, 0.1, 0.2], [0.2, 0.1, 1.0, 0.3], [0.1, 0.2, 0.3, 1.0]],
 "points": [{"P_T": 0, "P_N": 0, "g": 0, "mu": 3, "C_T": 0.25, "k_a": 0.1, "P_s": 1},
            {"P_T": 6, "P_N": 2, "g": 0, "mu": 3, "C_T": 0.25, "k_a": 0.1, "P_s": 1}]})";
  return "'" + path.string() + "'";
}

bool in_2d_system(const nlohmann::json& s3, const nlohmann::json& two_d, double F) {
  for (const auto& t : two_d["solutions"]) {
    bool all = true;
    for (std::size_t i = 0; i < s3["points"].size(); ++i) {
      const auto& p = s3["points"][i];
      all = all && std::abs(p["P_T1"][1].get<double>()) <= 1e-7 * F &&
            std::abs(p["P_T1"][0].get<double>() - t["values"]["P_T1"][i].get<double>()) <= 1e-6 * F &&
            std::abs(p["P_N1"].get<double>() - t["values"]["P_N1"][i].get<double>()) <= 1e-6 * F;
    }
    if (all) return true;
  }
  return false;
}
}  // namespace

TEST_CASE("cpkit step, 3-D with N > 1 coupled points: FB-SOC and multistart give 2-D N-point "
          "solutions", "[cli][step3d]") {
  const std::string three = std::string("'") + CPKIT_SOURCE_DIR + "/docs/examples/two_point_system_3d.json'";
  const std::string two = two_d_of_example();
  int compared = 0;
  for (const auto& [dfx1, dfn1, dfx2, dfn2] :
       std::vector<std::array<double, 4>>{{1.0, -1.0, 0.5, 1.0}, {0.2, 0.5, -0.3, 0.4},
                                          {-0.5, 1.0, 1.0, -0.2}, {0.1, 0.1, 0.1, 0.1}}) {
    const std::string df2 = num(dfx1) + " " + num(dfn1) + " " + num(dfx2) + " " + num(dfn2);
    const std::string df3 = num(dfx1) + " 0 " + num(dfn1) + " " + num(dfx2) + " 0 " + num(dfn2);
    const Run r2 = run_cpkit("step --system " + two + " --DF " + df2 + " --all --json");
    CAPTURE(df3, r2.err);
    REQUIRE(r2.code == 0);
    const auto j2 = nlohmann::json::parse(r2.out);
    if (j2["complete"] != true) continue;
    const double F = 6;
    // the default for N > 1: FB-SOC Newton on the 8 unknowns
    const Run d = run_cpkit("step --system " + three + " --DF " + df3 + " --json");
    CAPTURE(d.err);
    REQUIRE((d.code == 0 || d.code == 1));
    const auto jd = nlohmann::json::parse(d.out);
    CHECK(jd["n_points"] == 2);
    CHECK(jd["input"]["DF"].size() == 6);
    CHECK(jd["input"]["state"].size() == 2);
    CHECK(jd["attempts"].size() == 1);
    if (d.code == 0) {
      CHECK(jd["solver"] == "fb-soc");
      REQUIRE(jd["solutions"].size() == 1);
      const auto& s = jd["solutions"][0];
      REQUIRE(s["points"].size() == 2);
      for (const auto& p : s["points"])
        for (const char* k : {"type", "P_T1", "P_N1", "DP", "Dw", "Dw_Ti", "Dw_w", "g1", "lambda",
                              "slip_direction", "slip_angle", "residual"})
          CHECK(p.contains(k));
      CHECK(s["residual"].get<double>() <= 1e-9);
      CHECK(in_2d_system(s, j2, F));
      ++compared;
    }
    // --chain fb-soc is the same
    const Run c = run_cpkit("step --system " + three + " --DF " + df3 + " --chain fb-soc --json");
    CHECK(c.code == d.code);
    // --multistart: verified 2-D solutions, never claimed complete
    const Run m = run_cpkit("step --system " + three + " --DF " + df3 + " --multistart 10 --json");
    CAPTURE(m.err);
    REQUIRE((m.code == 0 || m.code == 5));
    const auto jm = nlohmann::json::parse(m.out);
    CHECK(jm["complete"] == false);
    CHECK(jm["found"].get<int>() <= static_cast<int>(j2["solutions"].size()));
    for (const auto& s : jm["solutions"]) {
      CHECK(s["residual"].get<double>() <= 1e-9);
      CHECK(in_2d_system(s, j2, F));
      ++compared;
    }
    // text output: one line per point
    const Run t = run_cpkit("step --system " + three + " --DF " + df3 + " --multistart 4");
    CHECK(t.out.find("NOT proved complete") != std::string::npos);
    if (t.code == 0) CHECK(t.out.find("point 2 ") != std::string::npos);
  }
  CHECK(compared >= 4);
}

TEST_CASE("cpkit step, 3-D with N > 1: refused modes and bad input exit 2", "[cli][step3d]") {
  const std::string three = std::string("'") + CPKIT_SOURCE_DIR + "/docs/examples/two_point_system_3d.json'";
  const std::string base = "step --system " + three;
  const std::pair<std::string, std::string> bad[] = {
      {base + " --DF 1 0 1 0 0 1 --all", "no complete enumeration"},
      {base + " --DF 1 0 1 0 0 1 --facets 8", "no complete enumeration"},
      {base + " --DF 1 0 1 0 0 1 --chain exact", "fb-soc"},
      {base + " --DF 1 0 1 0 0 1 --chain fb-soc,ipopt", "fb-soc"},
      {base + " --DF 1 0 1", "3N = 6"},
      {base + " --DF 1 0 1 0 0 1 --g0 -1", "--g0"},
      {base + " --DF 1 0 1 0 0 1 --multistart 0", "--multistart"},
      {base + " --DF 1 0 1 0 0 1 --chain fb-soc --multistart 3", "alternative modes"},
      {base + " --DF 1 0 1 0 0 1 --wear-law mroz --k_M 0.1", "k_a"},
  };
  for (const auto& [args, what] : bad) {
    const Run r = run_cpkit(args);
    CAPTURE(args, r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(what) != std::string::npos);
  }
}

namespace {
/// A one-point 3-D file with a full A (row-major, 9 numbers) and point fields.
std::string write_full(const std::string& name, const std::array<double, 9>& A,
                       const std::string& point_fields) {
  const auto path = scratch_dir() / (name + ".json");
  std::ofstream f(path);
  f << "{\"dim\": 3, \"A\": [";
  for (int i = 0; i < 3; ++i)
    f << (i ? ", " : "") << "[" << num(A[3 * i]) << ", " << num(A[3 * i + 1]) << ", "
      << num(A[3 * i + 2]) << "]";
  f << "], \"points\": [{" << point_fields << "}]}";
  return "'" + path.string() + "'";
}
}  // namespace

TEST_CASE("cpkit step, 3-D: ill-conditioned A (cond ~1e8), the issue's answers", "[cli][step3d]") {
  // Issue 24, item 1: the answers stated there (hand calculation; the slip has Dw_N = 0, so it
  // does not depend on the ill-conditioned A_NN at all).
  const std::array<double, 9> A = {2, 0, 1, 0, 1, 0.5, 1, 0.5, 0.7500000074505806};
  const std::string slip = write_full("cond_slip", A, "\"state\": \"b\", \"mu\": 2, \"C_T\": 0");
  const Run r = run_cpkit("step --system " + slip + " --DF -1 0.375 0.125 --all --json");
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  REQUIRE(j["count"] == 1);
  const auto& s = j["solutions"][0];
  CHECK(s["type"] == "slip");
  CHECK(s["P_T1"][0].get<double>() == Approx(-7.0 / 13).epsilon(1e-7));
  CHECK(s["P_T1"][1].get<double>() == Approx(0.2625).epsilon(1e-7));
  CHECK(s["P_N1"].get<double>() == Approx(0.29951923076923077).epsilon(1e-7));
  CHECK(s["Dw"][0].get<double>() == Approx(-3.0 / 13).epsilon(1e-7));
  CHECK(s["Dw"][1].get<double>() == Approx(0.1125).epsilon(1e-7));
  CHECK(std::abs(s["Dw"][2].get<double>()) <= 1e-12);
  // the chain's exact link answers the same
  const Run c = run_cpkit("step --system " + slip + " --DF -1 0.375 0.125 --json");
  REQUIRE(c.code == 0);
  CHECK(nlohmann::json::parse(c.out)["solutions"][0]["type"] == "slip");

  const std::string stick = write_full("cond_stick", A, "\"state\": \"b\", \"mu\": 1, \"C_T\": 1");
  const Run t = run_cpkit("step --system " + stick + " --DF 0.125 0.125 1 --all --json");
  CAPTURE(t.err);
  REQUIRE(t.code == 0);
  const auto k = nlohmann::json::parse(t.out);
  CHECK(k["complete"] == true);
  REQUIRE(k["count"] == 1);
  CHECK(k["solutions"][0]["type"] == "stick");
  CHECK(k["solutions"][0]["P_T1"][0].get<double>() == Approx(1.0 / 24).epsilon(1e-7));
  CHECK(k["solutions"][0]["P_T1"][1].get<double>() == Approx(1.0 / 16).epsilon(1e-7));
  CHECK(k["solutions"][0]["P_N1"].get<double>() == Approx(89.0 / 96).epsilon(1e-7));
}

TEST_CASE("cpkit step, 3-D: subnormal loads are refused alike by every route", "[cli][step3d]") {
  // Issue 24, item 5: a load of 1e-320 has a solution that cannot be written to the solver's
  // accuracy (subnormal doubles carry a few bits): exit 2, naming it, in every mode.
  const std::string f = std::string("'") + CPKIT_SOURCE_DIR + "/docs/examples/elliptic_point_3d.json'";
  for (const std::string mode : {" --all", "", " --chain fb-soc", " --chain ipopt", " --facets 8",
                                 " --multistart 2"}) {
    const Run r = run_cpkit("step --system " + f + " --DF 1e-320 0 1e-320" + mode);
    CAPTURE(mode, r.out, r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("subnormal") != std::string::npos);
    CHECK(r.out.empty());
  }
  // The same problem in units of moderate size is solved (the model is homogeneous here).
  const Run ok = run_cpkit("step --system " + f + " --DF 1 0 1 --all");
  CHECK(ok.code == 0);
}
