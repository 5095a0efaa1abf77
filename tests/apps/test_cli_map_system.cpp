// `cpkit map --system FILE --kind direction`: against the one-point map (an uncoupled stick
// point does not change the other point's map), the JSON layout, bad input.
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace {

std::string write_system(const std::string& name, const std::string& text) {
  const auto p = cpkit::test::scratch_dir() / name;
  std::ofstream(p) << text;
  return "'" + p.string() + "'";
}

// Point 1: Fig. 5b (A = [[1,2],[2,5]], mu = 1, state b); point 2: state c, uncoupled (always
// exactly one solution, stick). Default patterns e1 = (1,0,1,0), e2 = (0,1,0,1).
const char* kSystem = R"({"name": "fig5b + stick", "A": [[1, 2, 0, 0], [2, 5, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
 "points": [{"state": "b", "mu": 1}, {"state": "c", "mu": 1, "P_N": 1}]})";

}  // namespace

TEST_CASE("cpkit map --system: an uncoupled stick point leaves the one-point map", "[cli][map][system]") {
  const std::string f = write_system("map_fig5b.json", kSystem);
  const auto r = cpkit::test::run_cpkit("map --system " + f + " --kind direction --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto one = cpkit::test::run_cpkit("map --a11 1 --a12 2 --a22 5 --mu 1 --state b --kind direction --json");
  REQUIRE(one.code == 0);
  const auto k = nlohmann::json::parse(one.out);
  CHECK(j.contains("cpkit_version"));
  CHECK(j.contains("run"));
  CHECK(j["input"]["n_points"] == 2);
  CHECK(j["complete"] == true);
  REQUIRE(j["sectors"].size() == k["sectors"].size());
  REQUIRE(j["critical"].size() == k["critical"].size());
  for (const char* part : {"sectors", "critical"}) {
    for (std::size_t i = 0; i < k[part].size(); ++i) {
      const auto& a = j[part][i];
      const auto& b = k[part][i];
      CHECK(a["count"] == b["count"]);
      if (b.contains("theta")) CHECK(a["theta"].get<double>() == Approx(b["theta"].get<double>()).margin(1e-9));
      else CHECK(a["theta_from"].get<double>() == Approx(b["theta_from"].get<double>()).margin(1e-9));
      // one-point types "slip+|stick" -> tuples "slip+/stick", "stick/stick"
      REQUIRE(a["types"].size() == b["types"].size());
      for (const auto& t : a["types"]) {
        const std::string s = t.get<std::string>();
        REQUIRE(s.size() > 6);
        CHECK(s.substr(s.size() - 6) == "/stick");
        bool in_one = false;
        for (const auto& u : b["types"]) in_one = in_one || u.get<std::string>() == s.substr(0, s.size() - 6);
        CHECK(in_one);
      }
    }
  }
}

TEST_CASE("cpkit map --system: the example's map and --out", "[cli][map][system]") {
  const auto dir = cpkit::test::scratch_dir();
  const std::string prefix = (dir / "two_point_map").string();
  const auto r = cpkit::test::run_cpkit("map --system '" + std::string(CPKIT_SOURCE_DIR) +
                                        "/docs/examples/two_point_system.json' --out '" + prefix + "'");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("critical directions:") != std::string::npos);
  std::ifstream csv(prefix + ".csv");
  std::string header;
  std::getline(csv, header);
  CHECK(header == "kind,theta_from,theta_to,count,types");
  std::ifstream js(prefix + ".json");
  const auto j = nlohmann::json::parse(js);
  double total = 0;
  for (const auto& s : j["sectors"]) total += s["theta_to"].get<double>() - s["theta_from"].get<double>();
  CHECK(total == Approx(6.283185307179586));
}

TEST_CASE("cpkit map --system: bad input exits 2 naming the option", "[cli][map][system]") {
  const std::string f = write_system("map_bad.json", kSystem);
  for (const char* extra : {"--mu 2", "--kind param-direction", "--preset fig5b", "--theta-n 10",
                            "--kind nonsense"}) {
    const auto r = cpkit::test::run_cpkit("map --system " + f + " " + extra);
    INFO(extra << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(std::string(extra).substr(0, std::string(extra).find(' '))) != std::string::npos);
  }
  const std::string par = write_system("map_par.json",
      R"({"A": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
 "points": [{"state": "b", "mu": 1}, {"state": "b", "mu": 1}], "patterns": [[1, 0, 1, 0], [2, 0, 2, 0]]})");
  const auto r = cpkit::test::run_cpkit("map --system " + par);
  CHECK(r.code == 2);
  CHECK(r.err.find("patterns") != std::string::npos);
}

TEST_CASE("maps.md's sample outputs of the N-point maps are what cpkit prints", "[cli][map][system][docs]") {
  std::ifstream f(std::string(CPKIT_SOURCE_DIR) + "/docs/maps.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  for (const std::string example : {"two_point_system", "three_point_punch_sliding"}) {
    const std::string rel = "docs/examples/" + example + ".json";
    const std::string head = "cpkit map --system " + rel + "\n```\n```\n";
    const auto b = md.find(head);
    INFO(example);
    REQUIRE(b != std::string::npos);
    const auto e = md.find("```", b + head.size());
    REQUIRE(e != std::string::npos);
    const std::string sample = md.substr(b + head.size(), e - b - head.size());
    const std::string file = std::string(CPKIT_SOURCE_DIR) + "/" + rel;
    const auto r = cpkit::test::run_cpkit("map --system '" + file + "'");
    REQUIRE(r.code == 0);
    std::string out = r.out;  // the docs show the path relative to the source tree
    const auto at = out.find(file);
    REQUIRE(at != std::string::npos);
    out.replace(at, file.size(), rel);
    CHECK(out == sample);
  }
}

TEST_CASE("cpkit map --system --kind param-direction: one-point product at coupling 0, options",
          "[cli][map][system]") {
  // Fig. 5b point (one-point map known: 3 solutions on a sector) uncoupled from a stick point:
  // every cell's count is the one-point count, and the coupling row 0 equals row 1 (A has no
  // coupling here).
  const std::string f = write_system("map_pd.json", kSystem);
  const auto r = cpkit::test::run_cpkit("map --system " + f +
                                        " --kind param-direction --param mu@1 --from 1 --to 1.5"
                                        " --n 2 --theta-n 36 --json --threads 2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.contains("run"));
  CHECK(j["complete"] == true);
  CHECK(j["cells"] == 72);
  CHECK(j["input"]["param"] == "mu@1");
  // The one-point maps at mu = 1 and 1.5 over the same 36 directions, through the one-point CLI.
  std::map<int, long> expect;
  for (const char* mu : {"1", "1.5"}) {
    const auto one = cpkit::test::run_cpkit(std::string("map --a11 1 --a12 2 --a22 5 --mu ") + mu +
                                            " --state b --kind param-direction --param C_T "
                                            "--from 0 --to 0 --n 1 --theta-n 36 --json");
    INFO(one.err);
    REQUIRE(one.code == 0);
    const auto k = nlohmann::json::parse(one.out);
    for (const auto& c : k["classes"])
      expect[c["count"].get<int>()] += c["cells"].get<long>();
  }
  std::map<int, long> got;
  for (const auto& c : j["counts"]) got[c["count"].get<int>()] += c["cells"].get<long>();
  CHECK(got == expect);
  // every pattern's second point sticks (state c, uncoupled)
  for (const auto& p : j["patterns"])
    for (const auto& t : p["types"]) CHECK(t.get<std::string>().find("/stick") != std::string::npos);

  for (const char* bad : {" --kind param-direction --param mu@3 --from 1 --to 2",
                          " --kind param-direction --param a11 --from 1 --to 2",
                          " --kind param-direction --param mu --from 1 --to 2 --param2 C_T",
                          " --kind param-direction --from 1 --to 2",
                          " --kind param-param --param mu --from 1 --to 2",
                          " --kind direction --param mu"}) {
    const auto e = cpkit::test::run_cpkit("map --system " + f + bad);
    INFO(bad << ": " << e.err);
    CHECK(e.code == 2);
    CHECK(!e.err.empty());
  }
}
