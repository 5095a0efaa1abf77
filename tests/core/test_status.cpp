// Status names: stable strings for the CLI and JSON, and their inverse.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "cpkit/core/enum_names.hpp"
#include "cpkit/core/status.hpp"

TEST_CASE("Status to_string / status_from_string round trip", "[status]") {
  using cpkit::Status;
  const std::pair<Status, const char*> table[] = {
      {Status::kNotRun, "not_run"},
      {Status::kSolved, "solved"},
      {Status::kSolvedInaccurate, "solved_inaccurate"},
      {Status::kInfeasible, "infeasible"},
      {Status::kRayTermination, "ray_termination"},
      {Status::kIterationLimit, "iteration_limit"},
      {Status::kTimeLimit, "time_limit"},
      {Status::kStalled, "stalled"},
      {Status::kNumericalFailure, "numerical_failure"},
      {Status::kInterrupted, "interrupted"},
      {Status::kUnsupported, "unsupported"},
      {Status::kCycleDetected, "cycle_detected"},
  };
  std::set<std::string> names;
  for (const auto& [s, name] : table) {
    CAPTURE(name);
    CHECK(cpkit::to_string(s) == name);
    REQUIRE(cpkit::status_from_string(name).has_value());
    CHECK(*cpkit::status_from_string(name) == s);
    names.insert(name);
  }
  CHECK(names.size() == 12);
  CHECK_FALSE(cpkit::status_from_string("Solved").has_value());
  CHECK_FALSE(cpkit::status_from_string("").has_value());
  CHECK_FALSE(cpkit::status_from_string("unknown").has_value());
}

TEST_CASE("is_solution is true only for solved and solved_inaccurate", "[status]") {
  using cpkit::Status;
  CHECK(cpkit::is_solution(Status::kSolved));
  CHECK(cpkit::is_solution(Status::kSolvedInaccurate));
  for (Status s : {Status::kNotRun, Status::kInfeasible, Status::kRayTermination,
                   Status::kIterationLimit, Status::kTimeLimit, Status::kStalled,
                   Status::kNumericalFailure, Status::kInterrupted, Status::kUnsupported,
                   Status::kCycleDetected})
    CHECK_FALSE(cpkit::is_solution(s));
}

TEST_CASE("name tables: the first name of a value is its name, later ones are aliases",
          "[status][names]") {
  enum class Colour { kRed, kGreen, kBlue };
  constexpr cpkit::EnumName<Colour> table[] = {
      {Colour::kRed, "red"}, {Colour::kRed, "r"}, {Colour::kGreen, "green"}};
  CHECK(cpkit::name_of(table, Colour::kRed) == "red");
  CHECK(cpkit::name_of(table, Colour::kGreen) == "green");
  CHECK(cpkit::name_of(table, Colour::kBlue) == "unknown");  // no entry
  CHECK(cpkit::value_of(table, "red") == Colour::kRed);
  CHECK(cpkit::value_of(table, "r") == Colour::kRed);
  CHECK(cpkit::value_of(table, "green") == Colour::kGreen);
  CHECK_FALSE(cpkit::value_of(table, "Red").has_value());  // exact, case-sensitive
  CHECK_FALSE(cpkit::value_of(table, "").has_value());
  CHECK_FALSE(cpkit::value_of(table, "unknown").has_value());
  static_assert(cpkit::name_of(table, Colour::kRed) == "red", "usable at compile time");
}
