// Text and JSON reports: stable field names, non-finite numbers as null.
#include <catch2/catch.hpp>

#include <cmath>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/report.hpp"

TEST_CASE("to_json has the documented fields", "[report]") {
  const cpkit::LcpProblem p(cpkit::Mat::Identity(2, 2), cpkit::Vec{{-1, 2}});
  cpkit::SolveResult c;
  c.status = cpkit::Status::kSolved;
  c.solver = "lemke";
  c.z = cpkit::Vec{{1, 0}};
  c.iterations = 2;
  const auto r = cpkit::finalize(p, c, {});
  const auto j = cpkit::to_json(r);
  CHECK(j.at("status") == "solved");
  CHECK(j.at("solver") == "lemke");
  CHECK(j.at("z") == nlohmann::json::array({1.0, 0.0}));
  CHECK(j.at("w") == nlohmann::json::array({0.0, 2.0}));
  CHECK(j.at("iterations") == 2);
  CHECK(j.at("residual") == 0.0);
  CHECK(j.at("residuals").contains("scale"));
  CHECK_FALSE(j.contains("certificate"));
  CHECK_FALSE(j.contains("ray"));
  const auto text = cpkit::to_text(r);
  CHECK(text.find("status:     solved") != std::string::npos);
  CHECK(text.find("iterations: 2") != std::string::npos);
}

TEST_CASE("to_json: certificate when infeasible, non-finite as null", "[report]") {
  const cpkit::LcpProblem p(cpkit::Mat{{-1}}, cpkit::Vec{{-1}});
  cpkit::SolveResult c;
  c.status = cpkit::Status::kInfeasible;
  c.certificate = cpkit::Certificate{};
  c.certificate->y = cpkit::Vec{{2}};
  const auto r = cpkit::finalize(p, c, {});
  const auto j = cpkit::to_json(r);
  CHECK(j.at("status") == "infeasible");
  REQUIRE(j.contains("certificate"));
  CHECK(j["certificate"].at("y") == nlohmann::json::array({1.0}));
  CHECK(j["certificate"].at("q_dot_y") == -1.0);
  CHECK(j["certificate"].at("checked") == true);
  CHECK(cpkit::to_json(cpkit::Vec{{1, NAN, INFINITY}}) ==
        nlohmann::json::array({1.0, nullptr, nullptr}));
}
