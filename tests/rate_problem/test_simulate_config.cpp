// The `cpkit simulate` config schema, called directly (simulation/simulate_config.hpp): the
// values read are the ones written in the config here; every refusal is an InputError that names
// the field. Independent sources: the config texts written here, docs/simulation.md's stated
// messages ("load.cycles = 4294967297 is out of range [1, 2147483647]"), and the memory and step
// caps computed by hand (2 doubles per cycle; 1 GiB = 2^30 bytes; 10^8 steps).
#include <catch2/catch.hpp>

#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/simulation/simulate_config.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"

using namespace cpkit::rate;
using Catch::Contains;

namespace {

const char* kParams = R"("parameters": {"a11": 2.0, "a12": 0.3, "a22": 1.5, "mu": 0.5})";

SimulateSettings parsed(const std::string& body) {
  SimulateSettings s;
  parse_simulate_config("{" + std::string(kParams) + (body.empty() ? "" : ", ") + body + "}",
                        "t.json", "/cfg", s);
  return s;
}

/// The message of the InputError that parse + validate throw ("" when none).
std::string refusal(const std::string& text) {
  try {
    SimulateSettings s;
    parse_simulate_config(text, "t.json", "/cfg", s);
    validate_simulate_settings(s);
  } catch (const cpkit::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("simulate config: the values written are the values read", "[simulate_config]") {
  const SimulateSettings s = parsed(
      R"("load": {"type": "fretting", "F_N": 1.0, "amplitude": 1.2, "period": 2.0,
                  "cycles": 1e2, "steps_per_cycle": 40, "ramp_steps": 10},
         "wear": {"law": "mroz", "k_M": 0.25},
         "heat": {"enabled": true, "T_body": [300, 310]},
         "output": {"csv": "out/a.csv", "summary": "/abs/s.json", "every": 2})");
  CHECK(s.opt.params.a11 == 2.0);
  CHECK(s.opt.params.a12 == 0.3);
  CHECK(s.opt.params.a22 == 1.5);
  CHECK(s.opt.params.mu == 0.5);
  CHECK(s.fretting.amplitude == 1.2);
  CHECK(s.fretting.cycles == 100);  // 1e2 is an integral number: accepted as 100
  CHECK(s.fretting.steps_per_cycle == 40);
  CHECK(s.csv_period == 2.0);
  CHECK(s.opt.wear.law == WearLaw::kMrozStupkiewicz);
  CHECK(s.opt.wear.k_M == 0.25);
  CHECK(s.opt.heat.enabled);
  CHECK(s.opt.heat.T_body[1] == 310);
  CHECK(s.csv == "/cfg/out/a.csv");       // relative to the config's folder
  CHECK(s.summary == "/abs/s.json");      // absolute paths kept
  CHECK(s.every == 2);
  for (bool h : s.have) CHECK(h);
  CHECK_NOTHROW(validate_simulate_settings(s));
}

TEST_CASE("simulate config: bad input names the field", "[simulate_config]") {
  const std::string p = kParams;
  CHECK_THAT(refusal("{" + p + R"(, "load": {"cycles": 4294967297}})"),
             Contains("load.cycles = 4294967297 is out of range [1, 2147483647]"));
  CHECK_THAT(refusal("{" + p + R"(, "load": {"cycles": 2.5}})"),
             Contains("load.cycles must be an integer"));
  CHECK_THAT(refusal(R"({"parameters": {"a11": 2, "a12": 0.3, "a22": 1.5, "mu": 0.5, "criterion": 38.7}})"),
             Contains("parameters.criterion must be an integer"));
  CHECK_THAT(refusal(R"({"parameters": {"a11": 2, "a12": 0.3, "a22": 1.5, "mu": "x"}})"),
             Contains("parameters.mu must be a number"));
  CHECK_THAT(refusal("{" + p + R"(, "wear": {"law": "usual"}})"),
             Contains("wear.law must be archard or mroz"));
  CHECK_THAT(refusal("{" + p + R"(, "heat": {"T_body": [1]}})"),
             Contains("heat.T_body must be an array of two numbers"));
  CHECK_THAT(refusal("{" + p + R"(, "output": {"colour": 1}})"), Contains("unknown key output.colour"));
  CHECK_THAT(refusal("{" + p + R"(, "extra": 1})"), Contains("unknown key 'extra'"));
  CHECK_THAT(refusal("{" + p + R"(, "branch_rule": "nearest"})"),
             Contains("branch_rule must be closest or stop"));
  CHECK_THAT(refusal("[1]"), Contains("the top level must be an object"));
  CHECK_THAT(refusal("{\"parameters\": {\"a11\": 2, \"a12\": 0.3, \"a22\": 1.5}}"),
             Contains("mu is required"));
  CHECK_THAT(refusal("{" + p + R"(, "output": {"every": 3}})"),
             Contains("every = 3 (--every, output.every) has no effect"));
  CHECK_THAT(refusal("{" + p + R"(, "load": {"type": "sine"}})"),
             Contains("load type must be fretting, ramp or csv, got 'sine'"));
  // Every message says which config it is about.
  CHECK_THAT(refusal("{" + p + R"(, "extra": 1})"), Contains("config 't.json'"));
  CHECK(refusal("{" + p + "}").empty());  // the defaults are a valid run
}

TEST_CASE("simulate config: the memory and step caps, computed by hand", "[simulate_config]") {
  const std::string p = kParams;
  // 10^8 cycles keep 2 doubles each: 1.6e9 B = 1.49 GiB, more than the 1 GiB (2^30 B) limit.
  CHECK_THAT(refusal("{" + p + R"(, "load": {"cycles": 100000000, "steps_per_cycle": 4}})"),
             Contains("would need about 1.49 GiB of memory"));
  // 3e7 cycles x 4 + 10 ramp steps = 120000010 steps (4.8e8 B: under the memory limit) exceed
  // the 10^8-step cap.
  CHECK_THAT(refusal("{" + p + R"(, "load": {"cycles": 30000000, "steps_per_cycle": 4,
                                              "ramp_steps": 10}})"),
             Contains("the run would take 120000010 steps"));
  CHECK_THAT(refusal("{" + p + R"(, "load": {"cycles": 30000000, "steps_per_cycle": 4,
                                              "ramp_steps": 10}})"),
             Contains("the cap is 100000000 steps"));
  // The same steps are under the cap by one.
  CHECK(refusal("{" + p + R"(, "load": {"cycles": 24999997, "steps_per_cycle": 4,
                                        "ramp_steps": 12}})").empty());
  CHECK_THROWS_WITH(check_simulation_steps(1000001, true, "x"),
                    Contains("the cap is 1000000 steps"));
  CHECK_NOTHROW(check_simulation_steps(1000000, true, "x"));
}

TEST_CASE("simulate config: byte sizes for messages and options", "[simulate_config]") {
  CHECK(cpkit::byte_text(1.6e9) == "1.49 GiB");  // 1.6e9 / 2^30 = 1.4901
  CHECK(cpkit::byte_text(512) == "512 B");
  CHECK(cpkit::parse_byte_size("1.5K", "--max-output") == 1536.0);
  CHECK(cpkit::parse_byte_size("2GiB", "--max-output") == 2147483648.0);
  CHECK_THROWS_WITH(cpkit::parse_byte_size("-3M", "--max-output"), Contains("--max-output must be"));
}

TEST_CASE("load CSV: one point and N points through the one row loop", "[simulate_config]") {
  // Two points: t, F_T1, F_N1, F_T2, F_N2 per row; a header, a comment and a blank line skipped.
  const std::string text = "t, FT1, FN1, FT2, FN2\n# comment\n0, 0, 1, 0, 2\n\n0.5; 0.25 1 -0.25\t2\n";
  const std::vector<SystemLoadPoint> pts = parse_system_load_csv(text, "two.csv", 2);
  REQUIRE(pts.size() == 2);
  CHECK(pts[1].t == 0.5);
  CHECK(pts[1].F(0) == 0.25);
  CHECK(pts[1].F(2) == -0.25);
  CHECK(pts[1].F(3) == 2);
  CHECK_THROWS_WITH(parse_system_load_csv("0, 1, 2\n", "bad.csv", 2),
                    Contains("bad.csv:1: 3 values; a system of 2 points needs t and 4 forces"));
  CHECK_THROWS_WITH(parse_system_load_csv("# nothing\n", "empty.csv", 1),
                    Contains("empty.csv: the load history is empty"));
  CHECK_THROWS_WITH(parse_system_load_csv("0, 1, 2\n1, 0x10, 2\n", "hex.csv", 1),
                    Contains("hex.csv:2"));
  const LoadHistory h = parse_load_csv("t,F_T,F_N\n0,0,1\n1,0.5,1\n", "one.csv");
  REQUIRE(h.points.size() == 2);
  CHECK(h.points[1].F_T == 0.5);
  CHECK_THROWS_WITH(parse_load_csv("0,0,1\n1,0.5\n", "one.csv"),
                    Contains("one.csv:2: expected three columns t, F_T, F_N"));
}
