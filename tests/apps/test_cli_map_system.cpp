// `cpkit map --system FILE`: the direction map against the one-point map (an uncoupled stick
// point does not change the other point's map), the grid maps (npy = CSV through numpy, N = 1
// param-param = the one-point map, pictures, refusals), the JSON layout, bad input; limits
// that depend on N checked right after the file is read (issue 24, item 12).
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "peer_skip.hpp"

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
  // Every block "```sh\ncpkit map --system docs/examples/X.json ...\n```\n```\n<output>```".
  std::ifstream f(std::string(CPKIT_SOURCE_DIR) + "/docs/maps.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const std::string start = "```sh\ncpkit map --system ";
  int checked = 0;
  for (auto b = md.find(start); b != std::string::npos; b = md.find(start, b + 1)) {
    const auto cmd_end = md.find('\n', b + 6);
    const std::string args = md.substr(b + 12, cmd_end - b - 12);  // "map --system ..."
    const std::string between = "\n```\n```\n";
    if (md.compare(cmd_end, between.size(), between) != 0) continue;  // a command without output
    const auto out_begin = cmd_end + between.size();
    const std::string sample = md.substr(out_begin, md.find("```", out_begin) - out_begin);
    const std::string rel = args.substr(13, args.find(' ', 13) - 13);
    const std::string file = std::string(CPKIT_SOURCE_DIR) + "/" + rel;
    std::string run_args = args;
    run_args.replace(13, rel.size(), "'" + file + "'");
    INFO(args);
    const auto r = cpkit::test::run_cpkit(run_args);
    REQUIRE(r.code == 0);
    std::string out = r.out;  // the docs show the path relative to the source tree
    for (auto at = out.find(file); at != std::string::npos; at = out.find(file))
      out.replace(at, file.size(), rel);
    CHECK(out == sample);
    ++checked;
  }
  CHECK(checked >= 5);  // two_point_system, the coupled points (3 kinds), the punch
}

TEST_CASE("cpkit map --system --kind param-direction: one-point product at coupling 0, options",
          "[cli][map][system]") {
  // Fig. 5b point (one-point map known: 3 solutions on a sector) uncoupled from a stick point:
  // every cell's count is the one-point count, and the coupling row 0 equals row 1 (A has no
  // coupling here).
  // 40 directions: cell centres at 4.5 + 9 k degrees, none on a critical direction of either
  // mu (45 degrees is one for mu = 1: there the two routes meet the knife edge of the next
  // test case).
  const std::string f = write_system("map_pd.json", kSystem);
  const auto r = cpkit::test::run_cpkit("map --system " + f +
                                        " --kind param-direction --param mu@1 --from 1 --to 1.5"
                                        " --n 2 --theta-n 40 --json --threads 2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.contains("run"));
  CHECK(j["complete"] == true);
  CHECK(j["cells"] == 80);
  CHECK(j["input"]["param"] == "mu@1");
  // The one-point maps at mu = 1 and 1.5 over the same 36 directions, through the one-point CLI.
  std::map<int, long> expect;
  for (const char* mu : {"1", "1.5"}) {
    const auto one = cpkit::test::run_cpkit(std::string("map --a11 1 --a12 2 --a22 5 --mu ") + mu +
                                            " --state b --kind param-direction --param C_T "
                                            "--from 0 --to 0 --n 1 --theta-n 40 --json");
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

namespace {
bool have_numpy() {
  return std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") == 0;
}
// One grazing point with the one-point Fig. 5b data: an N = 1 system.
const char* kFig5bAlone = R"({"name": "fig5b alone", "A": [[1, 2], [2, 5]], "points": [{"state": "b", "mu": 1}]})";
}  // namespace

// Issue 24 (the N-point route's bands in physical_pieces): one ulp past the critical direction
// L+ = dF_T - dF_N = 0 of the fig. 5b point (mu = 1, C_T = 0), the stick violates
// |dP_T| <= mu dP_N by one ulp, so the exact set of these doubles is the separation alone (the
// one-point route, which judges every sign against its rounding, says so). The N-point route
// listed the stick too and said complete; it now judges the stick's inequality against its
// rounding bound and says "not complete" (exit 5) rather than guess.
TEST_CASE("cpkit rate --system: one ulp past a critical direction, the stick is not a solution",
          "[cli][map][system]") {
  const std::string f = write_system("rate_knife.json", kSystem);
  const std::string dF = " --dF 0.7071067811865476 0.7071067811865475 0 0";
  const auto one = cpkit::test::run_cpkit(
      "rate --a11 1 --a12 2 --a22 5 --mu 1 --state b --dF 0.7071067811865476 0.7071067811865475 --json");
  REQUIRE(one.code == 0);
  CHECK(nlohmann::json::parse(one.out)["count"] == 1);  // separation: the one-point route
  const auto sys = cpkit::test::run_cpkit("rate --system " + f + dF + " --json");
  REQUIRE((sys.code == 0 || sys.code == 5));
  const auto j = nlohmann::json::parse(sys.out);
  // the N-point JSON has no "count": its solutions are listed (a const operator[] on a missing
  // key is an assertion failure in Debug builds and undefined behaviour in Release)
  CHECK((j.at("solutions").size() == 1 || j.at("complete") == false));
}

TEST_CASE("cpkit map --system grid maps: .npy files read by numpy equal the CSV of the same map",
          "[cli][map][system][npy]") {
  if (!have_numpy()) {
    CPKIT_SKIP_CHECK("/usr/bin/python3 has no numpy (Debian: apt-get install python3-numpy)");
    return;
  }
  const std::string f = write_system("map_npy.json", kSystem);
  for (const std::string kind : {"param-direction", "param-param"}) {
    CAPTURE(kind);
    const auto dir = cpkit::test::scratch_dir();
    const std::string a = (dir / ("sys_npy_" + kind)).string(), b = (dir / ("sys_csv_" + kind)).string();
    const std::string common =
        kind == "param-direction"
            ? "map --system " + f + " --kind param-direction --param mu@1 --from 0.5 --to 3 --n 13 --theta-n 37 --out "
            : "map --system " + f + " --kind param-param --param mu@1 --from 0.5 --to 3 --n 7 --param2 coupling --from2 0 --to2 1 --n2 5 --out ";
    const auto ra = cpkit::test::run_cpkit(common + "'" + a + "'");
    INFO(ra.err);
    REQUIRE(ra.code == 0);
    const auto rb = cpkit::test::run_cpkit(common + "'" + b + "' --format csv");
    REQUIRE(rb.code == 0);
    const auto j = nlohmann::json::parse(cpkit::test::slurp(a + ".json"));
    CHECK(j["format"] == "npy");
    CHECK(j.contains("run"));
    CHECK(!j["files"].contains("csv"));
    const auto script = dir / "compare_sys_npy.py";
    std::ofstream(script) << R"(import csv, json, sys, numpy as np
pre_npy, pre_csv, kind = sys.argv[1], sys.argv[2], sys.argv[3]
s = json.load(open(pre_npy + ".json"))
rows = list(csv.reader(open(pre_csv + ".csv")))[1:]
d = pre_npy.rsplit("/", 1)[0] + "/"
load = lambda key: np.load(d + s["files"][key])
inp = s["input"]
cnt = lambda c: "inf" if c < 0 else str(c)
pat = load("pattern")
assert pat.dtype == np.uint16, pat.dtype
assert len(rows) == s["cells"]
assert int(pat.max()) < len(s["patterns"])
# the pattern table's cell counts are the array's
for p in s["patterns"]:
    assert int((pat == p["id"]).sum()) == p["cells"], p
if kind == "param-direction":
    c, x, th = load("count"), load("x"), load("theta")
    assert c.dtype == np.int8 and c.shape == (inp["n"], inp["theta_n"]), c.shape
    for k, r in enumerate(rows):
        i, jj = divmod(k, c.shape[1])
        assert abs(float(r[0]) - x[i]) <= 1e-12 * max(1, abs(x[i])), (r, x[i])
        assert abs(float(r[1]) - th[jj]) <= 1e-12 * max(1, th[jj]), (r, th[jj])
        assert r[2] == cnt(c[i, jj]) and int(r[3]) == pat[i, jj], r
else:
    cl, lo, hi, x, y = load("class"), load("min_count"), load("max_count"), load("x"), load("y")
    codes = {v: k for k, v in s["class_codes"].items()}
    assert cl.shape == (inp["n"], inp["n2"]) and pat.shape == cl.shape
    for k, r in enumerate(rows):
        i, jj = divmod(k, cl.shape[1])
        assert abs(float(r[0]) - x[i]) <= 1e-12 * max(1, abs(x[i])) and abs(float(r[1]) - y[jj]) <= 1e-12
        assert r[2] == codes[int(cl[i, jj])] and r[3] == cnt(lo[i, jj]) and r[4] == cnt(hi[i, jj]), r
        assert int(r[5]) == pat[i, jj], r
)";
    const int rc = std::system(("/usr/bin/python3 '" + script.string() + "' '" + a + "' '" + b + "' " + kind).c_str());
    CHECK(rc == 0);
  }
}

TEST_CASE("cpkit map --system --kind param-param: N = 1 equals the one-point param-param map",
          "[cli][map][system]") {
  // The one-point map decides each cell from the closed-form direction map; the system map from
  // the N-point exact direction map. Same grid (mu x C_T), same classes and count ranges.
  const std::string f = write_system("map_fig5b_alone.json", kFig5bAlone);
  const auto sys = cpkit::test::run_cpkit("map --system " + f + " --kind param-param --param mu "
                                          "--from 0.2 --to 3 --n 8 --param2 C_T --from2 0 --to2 2 --n2 5 --json");
  INFO(sys.err);
  REQUIRE(sys.code == 0);
  const auto one = cpkit::test::run_cpkit("map --a11 1 --a12 2 --a22 5 --state b --kind param-param "
                                          "--param mu --from 0.2 --to 3 --n 8 --param2 C_T --from2 0 --to2 2 --n2 5 --json");
  INFO(one.err);
  REQUIRE(one.code == 0);
  const auto j = nlohmann::json::parse(sys.out), k = nlohmann::json::parse(one.out);
  CHECK(j["complete"] == true);
  std::map<std::string, long> a, b;
  for (const auto& c : j["classes"]) a[c["class"].get<std::string>()] = c["cells"].get<long>();
  for (const auto& c : k["classes"]) b[c["class"].get<std::string>()] = c["cells"].get<long>();
  CHECK(a == b);
  CHECK(a.size() >= 2);  // Fig. 5b: unique below mu = a11/a12 = 0.5, not above
}

TEST_CASE("cpkit map --system grid maps: pictures, refusals, no partial files", "[cli][map][system]") {
  const std::string f = write_system("map_grid_opts.json", kSystem);
  const auto dir = cpkit::test::scratch_dir();
  namespace fs = std::filesystem;
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0) {
    for (const std::string kind : {"param-direction", "param-param"}) {
      const std::string p = (dir / ("sys_plot_" + kind)).string();
      const auto r = cpkit::test::run_cpkit(
          "map --system " + f + " --kind " + kind + " --param mu@1 --from 0.5 --to 3 --n 6 " +
          (kind == "param-param" ? "--param2 mu@2 --from2 0.5 --to2 2 --n2 4" : "--theta-n 24") +
          " --out '" + p + "' --plot");
      INFO(kind << ": " << r.err);
      CHECK(r.code == 0);
      CHECK(fs::file_size(p + ".png") > 10000);
      CHECK(fs::exists(p + ".svg"));
      const auto j = nlohmann::json::parse(cpkit::test::slurp(p + ".json"));
      CHECK(j["files"]["png"] == "sys_plot_" + kind + ".png");
    }
  } else {
    CPKIT_SKIP_CHECK("pictures not checked: /usr/bin/python3 has no matplotlib");
  }
  // a zoomed direction range is recorded and the directions lie in it
  const auto z = cpkit::test::run_cpkit("map --system " + f + " --kind param-direction --param mu --from 1 "
                                        "--to 2 --n 2 --theta-n 10 --theta-from 0.5 --theta-to 0.6 --json");
  INFO(z.err);
  REQUIRE(z.code == 0);
  const auto jz = nlohmann::json::parse(z.out);
  CHECK(jz["input"]["theta_from"] == 0.5);
  for (const auto& c : jz["counts"]) {
    CHECK(c["theta_min"].get<double>() > 0.5);
    CHECK(c["theta_max"].get<double>() < 0.6);
  }
  // refused before any cell: 1e11 cells cannot be done in 60 s (that would be 1.7e9 cells/s)
  const auto t = cpkit::test::run_cpkit("map --system " + f + " --kind param-direction --param mu --from 1 "
                                        "--to 2 --n 100000 --theta-n 1000000 --time-limit 60");
  CHECK(t.code == 2);
  CHECK(t.err.find("--time-limit") != std::string::npos);
  CHECK(t.out.empty());
  // an invalid row (mu@1 = -1, the first grid value) is named; no partial files
  const std::string bad = (dir / "sys_bad_row").string();
  const auto b = cpkit::test::run_cpkit("map --system " + f + " --kind param-param --param mu@1 --from -1 "
                                        "--to 2 --n 3 --param2 coupling --from2 0 --to2 1 --n2 6 --out '" + bad + "'");
  CHECK(b.code == 2);
  CHECK(b.err.find("mu@1 = -1") != std::string::npos);
  for (const char* s : {"_class.npy", "_pattern.npy", "_x.npy", ".json"}) CHECK_FALSE(fs::exists(bad + s));
  for (const char* opt : {" --kind param-param --param mu --from 1 --to 2 --param2 C_T --from2 0 --to2 1 --theta-n 5",
                          " --kind param-param --param mu --from 1 --to 2 --param2 mu --from2 0 --to2 1",
                          " --kind param-direction --param mu --from 1 --to 2 --plot",
                          " --kind param-direction --param mu --from 1 --to 2 --format csv",
                          " --kind param-direction --param mu --from 1 --to 2 --format npz --out x",
                          " --kind direction --plot --out x",
                          " --kind param-direction --param mu --from 1 --to 2 --theta-from 1 --theta-to 8"}) {
    const auto e = cpkit::test::run_cpkit("map --system " + f + opt);
    INFO(opt << ": " << e.err);
    CHECK(e.code == 2);
    CHECK(!e.err.empty());
    CHECK(e.out.empty());
  }
}

TEST_CASE("cpkit map --system: a system too large for a map is refused right after it is read "
          "(issue 24, item 12)", "[cli][map][system]") {
  // The issue's 1000 grazing points (a rate LCP of size 3000 > 12) were refused only after 36 s
  // and 1.27 GB: the N^3 precomputation came first. Here 400 points (LCP size 1200; a few
  // seconds before the fix): the refusal must cost about what reading the file costs (measured
  // by a command that reads it and stops at once: a --dF of the wrong size), whatever the
  // build's speed.
  const int n = 400;
  std::string text = "{\"A\": [";
  text.reserve(static_cast<std::size_t>(4 * n) * static_cast<std::size_t>(4 * n) / 2 + 64 * n);
  for (int i = 0; i < 2 * n; ++i) {
    text += i ? ",[" : "[";
    for (int k = 0; k < 2 * n; ++k) text += k ? (i == k ? ",2" : ",0") : (i == k ? "2" : "0");
    text += "]";
  }
  text += "], \"points\": [";
  for (int i = 0; i < n; ++i) text += i ? ",{\"state\": \"b\", \"mu\": 1}" : "{\"state\": \"b\", \"mu\": 1}";
  text += "]}";
  const std::string sys = write_system("many_points.json", text);
  auto timed = [](const std::string& args, cpkit::test::CliRun& r) {
    const auto t0 = std::chrono::steady_clock::now();
    r = cpkit::test::run_cpkit(args);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  cpkit::test::CliRun r;
  const double read = timed("rate --system " + sys + " --dF 1", r);
  REQUIRE(r.code == 2);
  for (const std::string& kind :
       {std::string("--kind direction"),
        std::string("--kind param-direction --param mu --from 1 --to 2 --n 2 --theta-n 4"),
        std::string("--kind param-param --param mu --from 1 --to 2 --n 2 --param2 C_T --from2 0 "
                    "--to2 1 --n2 2")}) {
    CAPTURE(kind);
    const double map = timed("map --system " + sys + " " + kind, r);
    CHECK(r.code == 2);
    CHECK(r.err.find("the rate LCP has size 1200") != std::string::npos);
    CHECK(map < 3 * read + 1);
  }
}
