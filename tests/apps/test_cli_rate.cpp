// `cpkit rate`: exit codes, JSON output, disagreement handling. Runs the built binary.
#include <sys/wait.h>

#include <catch2/catch.hpp>

#include "cli_runner.hpp"
#include "peer_skip.hpp"
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Run = cpkit::test::CliRun;

Run run_rate(const std::string& args) { return cpkit::test::run_cpkit("rate " + args); }

const std::string kB = "--state b --a11 1 --a12 2 --a22 5 --mu 1 ";  // D_+ = -1: non-unique

}  // namespace

TEST_CASE("cpkit rate: three solutions in JSON (hand case of Fig. 5b)", "[cli][rate]") {
  // A = [[1,2],[2,5]], mu = 1, dF = (1, 1.2): separation, stick, slip+ (hand computation in
  // tests/rate_problem/test_rate_paper.cpp); slip+ has dP = (0.8, 0.8), dw_T^i = 0.2.
  const Run r = run_rate(kB + "--dF 1 1.2 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 3);
  CHECK(j["types"] == nlohmann::json({"separation", "slip+", "stick"}));
  CHECK(j["unique_for_all_directions"] == false);
  REQUIRE(j["solutions"].size() == 3);
  bool found = false;
  for (const auto& s : j["solutions"]) {
    CHECK(s["kind"] == "point");
    if (s["type"] == "slip+") {
      found = true;
      CHECK(s["rates"]["dP_T"].get<double>() == Approx(0.8));
      CHECK(s["rates"]["dP_N"].get<double>() == Approx(0.8));
      CHECK(s["rates"]["dw_Ti"].get<double>() == Approx(0.2));
      CHECK(s["rates"]["dw_N"].get<double>() == Approx(0).margin(1e-12));
      CHECK(s["rates"]["dw_w"].get<double>() == Approx(0).margin(1e-12));
    }
  }
  CHECK(found);
  CHECK(j.contains("Lambda"));
}

TEST_CASE("cpkit rate: a segment with open/closed ends (degenerate a11 = mu|a12|)", "[cli][rate]") {
  // D_+ = 1 - 0.5*2 = 0, dF = (1,2) on N = 0: stick point + slip+ segment from stick (open) to
  // zero-force slip dP = 0, dw_T^i = dF_N/|a12| = 1 (closed).
  for (const char* method : {"enumerate", "analytic"}) {
    const Run r = run_rate("--state b --a11 1 --a12 2 --a22 5 --mu 0.5 --dF 1 2 --json --method " +
                           std::string(method));
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["count"] == "inf");
    CHECK(j["types"] == nlohmann::json({"slip+", "stick"}));
    bool seg = false;
    for (const auto& s : j["solutions"])
      if (s["kind"] == "segment") {
        seg = true;
        CHECK(s["type"] == "slip+");
        CHECK(s["start_closed"] == false);
        CHECK(s["end_closed"] == true);
        CHECK(s["end"]["dw_Ti"].get<double>() == Approx(1));
        CHECK(s["start"]["dP_N"].get<double>() == Approx(2));
      }
    CHECK(seg);
  }
}

TEST_CASE("cpkit rate: a ray (state d, Lambda = 0, L_s = 0)", "[cli][rate]") {
  const Run r = run_rate("--state d --a11 1 --a12 0.5 --a22 1 --mu 2 --P_N 1 --sgnPT 1 --dF 2 1 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == "inf");
  bool ray = false;
  for (const auto& s : j["solutions"])
    if (s["kind"] == "ray") {
      ray = true;
      CHECK(s["start_closed"] == false);
      CHECK(s["direction"]["dw_Ti"].get<double>() > 0);
    }
  CHECK(ray);
}

TEST_CASE("cpkit rate: no solution exits 1", "[cli][rate]") {
  // Lambda = 1 - 3*0.5 = -0.5, L_+ = 4 - 3 = 1 > 0: none.
  const Run r = run_rate("--state d --a11 1 --a12 0.5 --a22 1 --mu 3 --P_N 1 --dF 4 1 --json");
  CHECK(r.code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["count"] == 0);
  CHECK(j["Lambda"].get<double>() == Approx(-0.5));
}

TEST_CASE("cpkit rate: single solvers are checked against the set", "[cli][rate]") {
  // The hand case of Fig. 5b has three solutions (separation, stick, slip+; see above). One
  // solver finds one of them: complete = false, no count, "a solution" in the text
  // (issue 11, sec. 4), and the complete enumeration's count for reference.
  for (const char* m : {"lemke", "fb-newton", "ipopt"}) {
    const Run r = run_rate(kB + "--dF 1 1.2 --json --method " + std::string(m));
    INFO(m << ": " << r.err);
    if (r.code == 2 && r.err.find("not registered") != std::string::npos) {
      CPKIT_SKIP_CHECK(m << " is not registered in this build");
      continue;
    }
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["complete"] == false);
    CHECK_FALSE(j.contains("count"));
    CHECK(j["found"] == 1);
    CHECK(j["enumerated_count"] == 3);
    REQUIRE(j["solutions"].size() == 1);
    const std::string type = j["solutions"][0]["type"].get<std::string>();
    CHECK((type == "separation" || type == "stick" || type == "slip+"));
    const Run t = run_rate(kB + "--dF 1 1.2 --method " + std::string(m));
    REQUIRE(t.code == 0);
    CHECK(t.out.find("count: 1") == std::string::npos);
    CHECK(t.out.find("a solution (found by " + std::string(m)) != std::string::npos);
    CHECK(t.out.find("complete enumeration (--method enumerate): 3 solution(s)") !=
          std::string::npos);
  }
  // The complete routes say so.
  const Run e = run_rate(kB + "--dF 1 1.2 --json");
  REQUIRE(e.code == 0);
  CHECK(nlohmann::json::parse(e.out)["complete"] == true);
}

TEST_CASE("cpkit rate: bad input exits 2 with nothing on stdout", "[cli][rate]") {
  const std::string base = "--a11 1 --a12 0.5 --a22 1 --mu 0.5 --dF 1 1 ";
  const std::vector<std::string> cases = {
        "--state b --a11 1 --a12 2 --a22 1 --mu 0.5 --dF 1 1",  // indefinite A
        "--state b --a11 1 --a12 0 --a22 1 --mu 0 --dF 1 1",    // mu <= 0
        "--state b --a11 1 --a12 0 --a22 1 --mu -1 --dF 1 1",
        std::string("--state c --P_N 0 ") + base,                // P_N <= 0 in c
        std::string("--state d --P_N -1 ") + base,               // P_N <= 0 in d
        "--state b --a11 nan --a12 0 --a22 1 --mu 0.5 --dF 1 1", // NaN
        "--state b --a11 1 --a12 0 --a22 1 --mu 0.5 --dF nan 1",
        std::string("--state e ") + base,                        // unknown state
        std::string("--state b --frobnicate 1 ") + base,         // unknown option
        std::string("--state b --method simplex ") + base,       // unknown method
        std::string("--state b --criterion 36 ") + base,
        "--state b --a11 1 --a12 0 --a22 1 --mu 0.5 --dF 1",     // dF needs 2 values
        std::string("--state d --P_N 1 --sgnPT 0 ") + base};
  for (const std::string& args : cases) {
    const Run r = run_rate(args);
    CAPTURE(args, r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
}

TEST_CASE("cpkit rate: text output", "[cli][rate]") {
  const Run r = run_rate("--state c --a11 2 --a12 1 --a22 3 --mu 0.5 --C_T 0.5 --P_N 1 --dF 1 1");
  REQUIRE(r.code == 0);
  CHECK(r.out.find("count: 1") != std::string::npos);
  CHECK(r.out.find("stick point") != std::string::npos);
}

TEST_CASE("cpkit rate: A in units of 1e10 is solved, not a 'disagreement' (issue 24 item 17)",
          "[cli][rate][units]") {
  // Hand solution (slip+, dw_N = 0, dP_T = mu dP_N): dP_N = 4/17, dw_T^i = 15/17 1e-10; unique
  // since a11 > mu |a12|. It used to exit 3 on an inconclusive enumeration.
  for (const std::string a : {"--a11 1e10 --a12 3e9 --a22 1.2e10", "--a11 1e-10 --a12 3e-11 --a22 1.2e-10"}) {
    const Run r = run_rate("--state b " + a + " --mu 0.5 --dF 1 0.5 --json");
    CAPTURE(a, r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["count"] == 1);
    CHECK(j["types"] == nlohmann::json({"slip+"}));
    CHECK(j["solutions"][0]["rates"]["dP_N"].get<double>() == Approx(4.0 / 17).epsilon(1e-12));
  }
}

TEST_CASE("cpkit rate: an inconclusive enumeration exits 5, never 3 (issue 24 item 17)",
          "[cli][rate]") {
  // dF = (a11 (1 + 1.16e-12), a12): N = a11 dF_N - a12 dF_T is 1e-12 of its terms, far above
  // its rounding. The enumeration's fixed band could not call it (exit 5 here before h19); its
  // signs are now judged against their rounding (certified_b.hpp) and the data decide: in exact
  // rationals (Python fractions on these doubles) N = -9.90e-13 < 0, r = a22 dF_T - a12 dF_N =
  // 0.511 > 0, L_+ = 0.137 > 0, so the one solution is the separation with dw_T = r / det A =
  // 1.0000000000027707.
  const std::string A = "--state b --a11 1.0142831963176735 --a12 0.8450714454408795 "
                        "--a22 1.2075902949448927 --mu 1.038170126179592 ";
  {
    const Run r = run_rate(A + "--dF 1.0142831963188452 0.8450714454408795 --json");
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["complete"] == true);
    CHECK(j["count"] == 1);
    CHECK(j["types"] == nlohmann::json({"separation"}));
    CHECK(j["solutions"][0]["rates"]["dw_T"].get<double>() == Approx(1.0000000000027707).epsilon(1e-12));
    CHECK(j["solutions"][0]["rates"]["dw_N"].get<double>() < 0);
  }
  // dF = (a11, a12): N = 0 exactly in the data. a11 dF_N and a12 dF_T are rounded products, so
  // their difference is within its rounding bound; until issue 34 that made the answer "not
  // conclusive" (exit 5). The signs are now decided exactly (exact_expansion.hpp). By hand
  // (C_T = 0): N = 0, so no separation (it needs N < 0) and dP_N = N / D_s = 0 for a slip;
  // L_+ = dF_T - mu dF_N = a11 - mu a12 = D_+ = 0.137 > 0, so slip+ with lambda = L_+ / D_+ = 1
  // exactly; L_- = -a11 - mu a12 < 0 and D_- > 0: no slip-; stick needs L_+ <= 0: none.
  // One solution: slip+ with dP = 0, dw_T = dw_T^i = 1, dw_N = 0 (Python fractions agree).
  const Run r = run_rate(A + "--dF 1.0142831963176735 0.8450714454408795 --json");
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  CHECK(j["count"] == 1);
  CHECK(j["types"] == nlohmann::json({"slip+"}));
  CHECK(j["solutions"][0]["rates"]["dP_N"].get<double>() == Approx(0).margin(1e-12));
  CHECK(j["solutions"][0]["rates"]["dP_T"].get<double>() == Approx(0).margin(1e-12));
  CHECK(j["solutions"][0]["rates"]["dw_Ti"].get<double>() == Approx(1).epsilon(1e-12));
  // What stays inconclusive: a 2x2 block within the general engine's near-singular band
  // (D_+ = a11 - mu a12 = -1e-7 of its terms, where the certified route defers to it: a
  // continuum is possible there) and a load 1 ulp off N = 0: one sign test too close to call
  // -> exit 5 with complete: false, never 3.
  const Run u = run_rate("--state b --a11 1 --a12 1 --a22 2 --mu 1.0000001 "
                         "--dF 1 1.0000000000000002 --json");
  CHECK(u.code == 5);
  CHECK(u.err.find("not conclusive") != std::string::npos);
  const auto k = nlohmann::json::parse(u.out);
  CHECK(k["complete"] == false);
  CHECK_FALSE(k.contains("count"));
}

TEST_CASE("cpkit rate: the paper's exact critical loads of issue 34 are decided exactly",
          "[cli][rate]") {
  // Binary data (multiples of 2^-10), the load exactly on a critical direction; the answers are
  // from the model's rate equations solved in exact rationals (tests/data/
  // rate_boundary_family.py's oracle on these numbers): each case exited 5 before.
  {  // L_- = 0 exactly: one solution, stick, dP = (dF_T, S) / (1 + a11 C_T)
    const Run r = run_rate("--state b --a11 0.6044921875 --a12 0.5537109375 --a22 1.2255859375 "
                           "--mu 0.5205078125 --C_T 0.6181640625 --dF "
                           "-0.715008749626576900482177734375 0.821838398464024066925048828125 "
                           "--json");
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["complete"] == true);
    CHECK(j["types"] == nlohmann::json({"stick"}));
  }
  {  // L_- = 0 exactly: two solutions, separation and stick (dP = (-1167/1024, 1))
    const Run r = run_rate("--state b --a11 0.6767578125 --a12 -0.693359375 --a22 2.9052734375 "
                           "--mu 1.1396484375 --C_T 0.2275390625 --dF "
                           "-1.315141576342284679412841796875 1.17979816533625125885009765625 "
                           "--json");
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["complete"] == true);
    CHECK(j["types"] == nlohmann::json({"separation", "stick"}));
    for (const auto& s : j["solutions"])
      if (s["type"] == "stick") {
        CHECK(s["rates"]["dP_T"].get<double>() == Approx(-1167.0 / 1024).epsilon(1e-14));
        CHECK(s["rates"]["dP_N"].get<double>() == Approx(1).epsilon(1e-14));
      }
  }
  {  // state d, L_s = 0 exactly (s = -1): stick only (the slip's lambda = L_s / Lambda = 0 is
     // the stick point), dP = (-97/1024, 1); the analytic cross-check agrees: no note, exit 0
    const Run r = run_rate("--state d --a11 4.4921875 --a12 -3.1337890625 --a22 4.6513671875 "
                           "--mu 0.0947265625 --C_T 0.1708984375 --k_a 0 --P_s 0.2978515625 "
                           "--P_N 0.6083984375 --sgnPT -1 --dF -0.167448885738849639892578125 "
                           "1.050731725059449672698974609375 --json");
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.err.find("cannot decide") == std::string::npos);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["complete"] == true);
    CHECK(j["types"] == nlohmann::json({"stick"}));
    CHECK(j["solutions"][0]["rates"]["dP_T"].get<double>() == Approx(-97.0 / 1024).epsilon(1e-14));
    CHECK(j["solutions"][0]["rates"]["dP_N"].get<double>() == Approx(1).epsilon(1e-14));
  }
}

TEST_CASE("cpkit rate: near a critical load at cond 1e12, exact or inconclusive (issue 24)",
          "[cli][rate]") {
  // cond(A) ~ 1e12, state d (sliding, C_T = 0), dF_T = mu dF_N (1 + 8.6e-10). By hand: stick
  // (dw = 0, dP = dF) needs dP_T <= mu dP_N, violated by 2.3e-9 (no A^-1 involved, far above
  // rounding); slip+ has dw = (x, 0), dP = dF - A dw, dP_T = mu dP_N, so
  // x = (dF_T - mu dF_N) / (a11 - mu a12) > 0: one slip+. The analytic route must give exactly
  // that; the enumeration may not call its sign test (then exit 5, never 3 or a wrong answer).
  const long double a11 = 0.2688879234934807L, a12 = -0.7829714099955822L,
                    mu = 2.6918374157340192L, dFT = 2.6918374180398685L, dFN = 1;
  const long double x = (dFT - mu * dFN) / (a11 - mu * a12);
  const std::string args = "--state d --a11 0.2688879234934807 --a12 -0.7829714099955822 "
                           "--a22 2.279924749596601 --mu 2.6918374157340192 "
                           "--dF 2.6918374180398685 1 --P_N 1 --json";
  const Run an = run_rate(args + " --method analytic");
  REQUIRE(an.code == 0);
  const auto j = nlohmann::json::parse(an.out);
  CHECK(j["complete"] == true);
  CHECK(j["types"] == nlohmann::json({"slip+"}));
  CHECK(j["solutions"][0]["rates"]["dw_T"].get<double>() ==
        Approx(static_cast<double>(x)).epsilon(1e-6));
  const Run en = run_rate(args);
  CAPTURE(en.err);
  CHECK((en.code == 0 || en.code == 5));
  const auto k = nlohmann::json::parse(en.out);
  if (en.code == 5) CHECK(k["complete"] == false);
  else CHECK(k["types"] == nlohmann::json({"slip+"}));
}
