// The map functions moved out of `cpkit map` into the library (issue 25), called directly:
// the JSON and CSV of the N-point maps against the one-point closed form (the analytic route),
// the 3-D map plan and its JSON against the 2-D closed form on the great circle g = 0, the
// estimate and output size against hand counts, the system fingerprint against FNV-1a computed
// independently (Python struct packing of the documented byte order), the grid files against
// the NPY format specification (numpy.lib.format: magic, version 1.0, header dict, 64-byte
// aligned data).
#include <Eigen/Dense>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstring>
#include <map>
#include <unistd.h>
#include <sstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/direction_map.hpp"
#include "cpkit/rate_problem/maps/map_3d_plan.hpp"
#include "cpkit/rate_problem/maps/map_files.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"
#include "cpkit/rate_problem/maps/map_request.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"
#include "cpkit/rate_problem/maps/system_grid_map_run.hpp"
#include "cpkit/rate_problem/rate/analytic.hpp"
#include "cpkit/rate_problem/report/map_json.hpp"

using namespace cpkit::rate;

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

/// One point in state b, a11 = 1, a12 = 0.8, a22 = 1.5, mu = 2 > a11/a12: a wedge of load
/// directions with three solutions (the Fig. 5 situation).
ContactSystem wedge_system() {
  ContactSystem S;
  S.name = "wedge";
  S.A.resize(2, 2);
  S.A << 1.0, 0.8, 0.8, 1.5;
  SystemPoint p;
  p.mu = 2.0;
  p.C_T = 0.25;
  S.points = {p};
  return S;
}

/// The same point as a one-point model (the closed form's input).
ContactParameters wedge_params(double mu = 2.0) {
  ContactParameters p;
  p.a11 = 1.0;
  p.a12 = 0.8;
  p.a22 = 1.5;
  p.mu = mu;
  p.C_T = 0.25;
  return p;
}

Map3dRequest request_3d(const std::string& text, const std::string& kind) {
  Map3dRequest r;
  r.system = "test.json";
  r.file = parse_system_file(text, "test.json");
  r.kind = kind;
  return r;
}

// The decoupled isotropic point of test_sphere_map_3d.cpp: its great circle g = 0 is the 2-D
// model with a11 = 1, a12 = 0.8, a22 = 1.5.
const char* kDecoupled3d = R"({"name": "decoupled", "dim": 3,
  "A": [[1.0, 0.0, 0.8], [0.0, 2.0, 0.0], [0.8, 0.0, 1.5]],
  "points": [{"state": "b", "mu": 2, "C_T": 0.25, "alpha": [1, 1]}]})";

}  // namespace

TEST_CASE("system direction map JSON: N = 1 measures equal the one-point closed form",
          "[rate][maps][report]") {
  const ContactSystem S = wedge_system();
  const SystemDirectionMap m = compute_system_direction_map(S);
  const nlohmann::json j = system_direction_map_json(m, S, "wedge.json");
  CHECK(j["kind"] == "direction");
  CHECK(j["complete"] == true);
  CHECK(j["input"]["system"] == "wedge.json");
  CHECK(j["input"]["n_points"] == 1);
  // Default patterns (docs/maps.md): e1 = (1, 0), e2 = (0, 1).
  CHECK(j["input"]["patterns"] == nlohmann::json::parse("[[1.0, 0.0], [0.0, 1.0]]"));
  // The open sectors cover the circle: their measures add up to 2 pi.
  double total = 0;
  for (const auto& [count, v] : j["counts"].items()) total += v["radians"].get<double>();
  CHECK(total == Approx(kTwoPi).epsilon(1e-12));
  // Per count, the measure of the directions with that count from the one-point analytic
  // route, sampled densely (the sector ends are the only error: 2 pi / samples per end).
  std::map<int, double> sampled;
  const int samples = 20000;
  for (int k = 0; k < samples; ++k) {
    const double t = (k + 0.5) * kTwoPi / samples;
    const RateSummary r =
        summarize_rate_analytic(wedge_params(), ContactState{}, LoadRate{std::cos(t), std::sin(t)});
    sampled[r.count] += kTwoPi / samples;
  }
  REQUIRE(sampled.size() >= 2);  // the wedge: 1 and 3 solutions
  for (const auto& [count, w] : sampled) {
    CAPTURE(count);
    REQUIRE(j["counts"].contains(std::to_string(count)));
    CHECK(std::abs(j["counts"][std::to_string(count)]["radians"].get<double>() - w) <
          4 * kTwoPi / samples);
  }
  // The CSV: a header, one line per sector and per critical direction.
  std::ostringstream csv;
  write_system_direction_csv(m, 1, csv);
  std::istringstream in(csv.str());
  std::string line;
  int lines = 0;
  std::getline(in, line);
  CHECK(line == "kind,theta_from,theta_to,count,types");
  while (std::getline(in, line)) ++lines;
  CHECK(lines == static_cast<int>(j["sectors"].size() + j["critical"].size()));
}

TEST_CASE("system param-direction JSON: every cell's count is the one-point closed form",
          "[rate][maps][report]") {
  const ContactSystem S = wedge_system();
  SystemMapAxis axis;
  axis.param = parse_system_map_parameter("mu", 1);
  axis.from = 0.5;
  axis.to = 3.0;
  axis.n = 6;
  const int theta_n = 24;
  const SystemParamDirectionMap m = compute_system_param_direction_map(S, axis, theta_n);
  const nlohmann::json input = {{"system", "wedge.json"}};
  const nlohmann::json j = system_param_direction_json(m, 1, input);
  CHECK(j["kind"] == "param-direction");
  CHECK(j["input"] == input);
  CHECK(j["cells"] == 6 * 24);
  CHECK(j["complete"] == true);
  // Cells per count from the analytic route at the cell centres theta_j = (j + 1/2) 2 pi / n.
  std::map<int, int64_t> expected;
  for (int i = 0; i < axis.n; ++i)
    for (int k = 0; k < theta_n; ++k) {
      const double t = (k + 0.5) * kTwoPi / theta_n;
      const double mu = 0.5 + 2.5 * i / 5.0;
      ++expected[summarize_rate_analytic(wedge_params(mu), ContactState{},
                                         LoadRate{std::cos(t), std::sin(t)})
                     .count];
    }
  REQUIRE(expected.size() >= 2);
  std::map<int, int64_t> got;
  int64_t cells = 0;
  for (const auto& c : j["counts"]) {
    got[c["count"].get<int>()] = c["cells"].get<int64_t>();
    cells += c["cells"].get<int64_t>();
  }
  CHECK(got == expected);
  CHECK(cells == 6 * 24);
  int64_t pattern_cells = 0;
  for (const auto& p : j["patterns"]) pattern_cells += p["cells"].get<int64_t>();
  CHECK(pattern_cells == 6 * 24);
  // CSV: the header names the axis; the first row is mu = 0.5 at theta_0 = pi / 24.
  std::ostringstream csv;
  write_system_csv_header(axis, csv);
  CHECK(csv.str() == "mu,theta,count,pattern\n");
  SystemParamDirectionRows rows;
  rows.row_begin = 0;
  rows.row_end = 1;
  rows.count = m.count.data();
  rows.pattern = m.pattern.data();
  std::ostringstream row;
  write_system_csv_rows(axis, m.theta, rows, row);
  std::istringstream in(row.str());
  double mu = 0, theta = 0;
  char comma = 0;
  in >> mu >> comma >> theta;
  CHECK(mu == 0.5);
  CHECK(theta == Approx(kTwoPi / 48).epsilon(1e-15));
}

TEST_CASE("system param-param JSON: documented class codes, cells add up",
          "[rate][maps][report]") {
  const ContactSystem S = wedge_system();
  SystemMapAxis a1, a2;
  a1.param = parse_system_map_parameter("mu", 1);
  a1.from = 0.5;
  a1.to = 3.0;
  a1.n = 4;
  a2.param = parse_system_map_parameter("C_T", 1);
  a2.from = 0.0;
  a2.to = 1.0;
  a2.n = 3;
  const SystemParamParamMap m = compute_system_param_param_map(S, a1, a2);
  const nlohmann::json j = system_param_param_json(m, 1, nlohmann::json::object());
  // docs/maps.md: unique 0, non-unique 1, no-solution 2, none-and-several 3.
  CHECK(j["class_codes"] == nlohmann::json::parse(
                                R"({"unique": 0, "non-unique": 1, "no-solution": 2,
                                    "none-and-several": 3})"));
  CHECK(j["cells"] == 12);
  int64_t cells = 0;
  for (const auto& c : j["classes"]) cells += c["cells"].get<int64_t>();
  CHECK(cells == 12);
  // Per cell, the class from the one-point analytic route sampled densely over directions
  // (unique: 1 everywhere; non-unique: some > 1, none 0; no-solution: some 0, none > 1).
  std::map<std::string, int64_t> expected, got;
  for (int i = 0; i < a1.n; ++i)
    for (int k = 0; k < a2.n; ++k) {
      ContactParameters q = wedge_params(a1.value(i));
      q.C_T = a2.value(k);
      bool none = false, several = false;
      for (int t = 0; t < 4000; ++t) {
        const double th = (t + 0.5) * kTwoPi / 4000;
        const int c = summarize_rate_analytic(q, ContactState{}, LoadRate{std::cos(th), std::sin(th)}).count;
        none = none || c == 0;
        several = several || c > 1 || c < 0;
      }
      ++expected[none && several ? "none-and-several"
                 : none          ? "no-solution"
                 : several       ? "non-unique"
                                 : "unique"];
    }
  for (const auto& c : j["classes"]) got[c["class"].get<std::string>()] = c["cells"].get<int64_t>();
  CHECK(got == expected);
  CHECK(expected.size() >= 2);
}

TEST_CASE("system fingerprint: FNV-1a of the documented byte order", "[rate][maps]") {
  ContactSystem S;
  S.A.resize(2, 2);
  S.A << 2.0, 0.5, 0.5, 1.0;
  SystemPoint p;
  p.mu = 0.7;
  p.C_T = 0.25;
  S.points = {p};
  // Python: struct.pack('<qq4d8d3ii3q', ...) hashed with FNV-1a 64 (offset 1469598103934665603,
  // prime 1099511628211).
  CHECK(system_data_fingerprint(S) == "a447e5c029e6decd");
  Eigen::VectorXd dF(2);
  dF << 1.0, -0.5;
  S.dF = dF;
  CHECK(system_data_fingerprint(S) == "c522d79dcc465047");
}

TEST_CASE("3-D map plan: the sphere map on g = 0 is the 2-D closed form; JSON and sizes",
          "[rate3d][maps][report]") {
  Map3dRequest r = request_3d(kDecoupled3d, "sphere");
  r.n = 9;
  r.n2 = 8;  // g = 0 is column 3 (g in (-pi, pi])
  const Map3dPlan p = make_map_3d_plan(r);
  CHECK(p.cells == 72);
  CHECK(p.cells_text == "9 x 8 cells (--n x --n2)");
  CHECK(p.fewer == "use a smaller --n or --n2");
  CHECK(p.input["route"] == "exact");
  CHECK(p.input["others"] == "zero");
  CHECK(p.input["beta_to"].get<double>() == Approx(kTwoPi / 2));
  // 3 bytes a cell, 8 per axis value, 5 headers of 4096: 216 + 136 + 20480.
  CHECK(map_3d_output_bytes(p) == 20832.0);
  const Map3d m = compute_map_3d(p, p.options);
  REQUIRE(m.rows == 9);
  REQUIRE(m.cols == 8);
  REQUIRE(m.y[3] == 0.0);
  ContactParameters p2 = wedge_params();
  for (int i = 0; i < m.rows; ++i) {
    const double b = m.x[static_cast<std::size_t>(i)];
    const RateSummary two = summarize_rate_analytic(p2, ContactState{},
                                                    LoadRate{std::sin(b), std::cos(b)});
    CAPTURE(i, b);
    CHECK(m.count_at(i, 3) == two.count);
  }
  const nlohmann::json j = map_3d_json(m, "sphere", p.input, p.xname, p.yname);
  CHECK(j["dim"] == 3);
  CHECK(j["axes"] == nlohmann::json::parse(R"({"x": "beta", "y": "gamma"})"));
  // docs/contact_3d.md: open 1, separation 2, stick 4, slip 8.
  CHECK(j["type_bits"] ==
        nlohmann::json::parse(R"({"open": 1, "separation": 2, "stick": 4, "slip": 8})"));
  CHECK(j["complete"] == true);
  CHECK(j["time_limit_reached"] == false);
  int64_t by_count = 0, by_type = 0;
  for (const auto& c : j["counts"]) by_count += c["cells"].get<int64_t>();
  for (const auto& t : j["types"]) by_type += t["cells"].get<int64_t>();
  CHECK(by_count == 72);
  CHECK(by_type == 72);
}

TEST_CASE("3-D map plan: estimate, and bad requests named", "[rate3d][maps]") {
  SECTION("a map no larger than the 4 x 8 sample is not estimated") {
    Map3dRequest r = request_3d(kDecoupled3d, "sphere");
    r.n = 3;
    r.n2 = 8;
    const Map3dPlan p = make_map_3d_plan(r);
    int64_t sampled = -7;
    const cpkit::Stopwatch clock;
    CHECK(estimate_map_3d_seconds(p, 1, sampled, clock, 600) == -1);
    CHECK(sampled == 0);
  }
  SECTION("a larger one is estimated from the 4 x 8 sample") {
    Map3dRequest r = request_3d(kDecoupled3d, "sphere");
    r.n = 20;
    r.n2 = 30;
    const Map3dPlan p = make_map_3d_plan(r);
    int64_t sampled = 0;
    const cpkit::Stopwatch clock;
    CHECK(estimate_map_3d_seconds(p, 2, sampled, clock, 600) > 0);
    CHECK(sampled == 32);
  }
  SECTION("param-direction: the directions and the echo") {
    Map3dRequest r = request_3d(kDecoupled3d, "param-direction");
    r.param = "mu";
    r.from = 1;
    r.to = 3;
    r.n = 5;
    r.theta_n = 12;
    const Map3dPlan p = make_map_3d_plan(r);
    CHECK(p.cells == 60);
    CHECK(p.cells_text == "5 x 12 cells (--n x --theta-n)");
    CHECK(p.xname == "mu");
    CHECK(p.yname == "theta");
    CHECK(p.input["theta_to"].get<double>() == Approx(kTwoPi));
  }
  SECTION("refusals name the option") {
    Map3dRequest r = request_3d(kDecoupled3d, "sphere");
    r.facets = 2;
    CHECK_THROWS_WITH(make_map_3d_plan(r), "--facets must be in [3, 64], got 2");
    r = request_3d(kDecoupled3d, "sphere");
    r.point = 2;
    CHECK_THROWS_WITH(make_map_3d_plan(r), "--point must be in [1, 1], got 2");
    r = request_3d(kDecoupled3d, "param-param");
    r.param = "mu";
    r.param2 = "C_T";
    r.from = 1;
    r.to = 2;
    r.from2 = 0;
    r.to2 = 1;
    CHECK_THROWS_WITH(make_map_3d_plan(r), Catch::Contains("needs \"dF\""));
  }
}

TEST_CASE("grid files: .partial until finish, NPY v1.0 bytes, nothing left by discard",
          "[rate][maps]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("cpkit_test_map_files_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string prefix = (dir / "m").string();
  auto read = [](const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  SECTION("finish") {
    nlohmann::json files = nlohmann::json::object();
    GridFiles g(prefix, files);
    g.add_npy("count", "|i1", 2, 3);
    g.write_vector("x", {0.5, 2.0});
    const int8_t cells[6] = {1, 3, 0, -1, 1, 1};
    g.append({cells}, 6);
    CHECK(fs::exists(prefix + "_count.npy.partial"));
    CHECK_FALSE(fs::exists(prefix + "_count.npy"));
    g.finish();
    CHECK_FALSE(fs::exists(prefix + "_count.npy.partial"));
    CHECK(files == nlohmann::json::parse(R"({"count": "m_count.npy", "x": "m_x.npy"})"));
    const std::string npy = read(prefix + "_count.npy");
    REQUIRE(npy.size() > 10);
    CHECK(npy.substr(0, 8) == std::string("\x93NUMPY\x01\x00", 8));
    const std::size_t header = static_cast<unsigned char>(npy[8]) + 256u * static_cast<unsigned char>(npy[9]);
    CHECK((10 + header) % 64 == 0);
    const std::string dict = npy.substr(10, header);
    CHECK(dict.find("'descr': '|i1'") != std::string::npos);
    CHECK(dict.find("'fortran_order': False") != std::string::npos);
    CHECK(dict.find("'shape': (2, 3)") != std::string::npos);
    REQUIRE(npy.size() == 10 + header + 6);
    CHECK(npy.substr(10 + header) == std::string(reinterpret_cast<const char*>(cells), 6));
    const std::string x = read(prefix + "_x.npy");
    REQUIRE(x.size() >= 16);
    double last = 0;
    std::memcpy(&last, x.data() + x.size() - 8, 8);
    CHECK(last == 2.0);
  }
  SECTION("discard") {
    nlohmann::json files = nlohmann::json::object();
    GridFiles g(prefix, files);
    g.add_npy("types", "|u1", 1, 1);
    g.open_csv() << "a,b\n";
    g.discard();
    CHECK(fs::is_empty(dir));
  }
  SECTION("write_text_file") {
    write_text_file(prefix + ".json", [](std::ostream& o) { o << "{}\n"; });
    CHECK(read(prefix + ".json") == "{}\n");
    CHECK_FALSE(fs::exists(prefix + ".json.partial"));
  }
  fs::remove_all(dir);
}

TEST_CASE("map request: the one-point setup from a preset and the options over it",
          "[rate][maps]") {
  MapRequest a;
  SECTION("fig5b is the paper's Fig. 5(b) model; --mu overrides it") {
    a.preset = "fig5b";
    MapSetup s = make_map_setup(a);
    // Stromberg-Johansson-Klarbring Fig. 5: a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 3.
    CHECK(s.params.a11 == 1.0);
    CHECK(s.params.a12 == 0.5);
    CHECK(s.params.a22 == 1.0);
    CHECK(s.params.C_T == 0.25);
    CHECK(s.params.mu == 3.0);
    CHECK(s.state.label == StateLabel::kB);
    CHECK(s.kind == MapKind::kDirection);
    a.mu = 0.75;
    s = make_map_setup(a);
    CHECK(s.params.mu == 0.75);
  }
  SECTION("a model from the options; a param-direction axis") {
    a.a11 = 2;
    a.a12 = 0.5;
    a.a22 = 1;
    a.kind = "param-direction";
    a.param = "mu";
    a.from = 0.1;
    a.to = 2;
    a.n = 7;
    const MapSetup s = make_map_setup(a);
    CHECK(s.kind == MapKind::kParamDirection);
    CHECK(s.axis.param == map_parameter("mu"));
    CHECK(s.axis.n == 7);
    CHECK(s.axis.value(6) == Approx(2.0).epsilon(1e-15));
    CHECK(s.params.a11 == 2.0);
  }
  SECTION("refusals and notes") {
    a.preset = "fig5a";
    a.P_N = 1;
    CHECK_THROWS_WITH(make_map_setup(a), Catch::StartsWith("--P_N has no effect in state b"));
    a.P_N.reset();
    a.mu = 0;
    a.kind = "param-direction";
    a.param = "mu";
    a.from = 0;
    a.to = 1;
    CHECK_THROWS_WITH(make_map_setup(a),
                      Catch::StartsWith("--mu has no effect: mu varies along the map's"));
    MapRequest b;
    b.a11 = 1;
    CHECK_THROWS_WITH(make_map_setup(b), Catch::Contains("(missing: --a12 --a22 --mu)"));
    MapRequest c;
    c.preset = "fig5a";
    c.k_a = 0.5;
    std::vector<std::string> notes;
    (void)make_map_setup(c, [&](const std::string& n) { notes.push_back(n); });
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].rfind("--k_a does not enter state b", 0) == 0);
  }
}

TEST_CASE("N-point grid plan: axes, echo and refusals from the request", "[rate][maps]") {
  SystemMapRequest r;
  r.path = "two.json";
  r.file = parse_system_file(R"({"name": "two", "A": [[2, 0.5, 0.2, 0], [0.5, 1, 0, 0.1],
      [0.2, 0, 2, 0.5], [0, 0.1, 0.5, 1]],
      "points": [{"state": "b", "mu": 1}, {"state": "c", "mu": 1, "P_N": 1}]})", "two.json");
  r.kind = "param-direction";
  r.param = "mu@2";
  r.from = 0.5;
  r.to = 1.5;
  r.n = 11;
  r.theta_n = 90;
  SECTION("param-direction") {
    const SystemGridPlan p = make_system_grid_plan(r);
    CHECK(p.sys.n_points() == 2);
    CHECK(p.axis.param.name() == "mu@2");
    CHECK(p.axis.value(10) == 1.5);
    CHECK(p.cells_text == "11 x 90 cells (--n x --theta-n)");
    CHECK(p.fewer == "use a smaller --n or --theta-n");
    CHECK(p.input["n_points"] == 2);
    CHECK(p.input["theta_to"].get<double>() == Approx(kTwoPi));
    // Default patterns (docs/maps.md): e1 = (1, 0, 1, 0), e2 = (0, 1, 0, 1).
    CHECK(p.input["patterns"] ==
          nlohmann::json::parse("[[1.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 1.0]]"));
  }
  SECTION("param-param") {
    r.kind = "param-param";
    r.param2 = "coupling";
    r.from2 = 0;
    r.to2 = 1;
    r.n2 = 5;
    const SystemGridPlan p = make_system_grid_plan(r);
    CHECK(p.axis2.param.name() == "coupling");
    CHECK(p.cells_text == "11 x 5 cells (--n x --n2)");
    CHECK(p.input["param2"] == "coupling");
    CHECK_FALSE(p.input.contains("theta_n"));
  }
  SECTION("refusals") {
    r.param = "mu@3";
    CHECK_THROWS_AS(make_system_grid_plan(r), cpkit::InputError);
    r.param = "mu";
    r.theta_from = 1;
    r.theta_to = 0.5;
    CHECK_THROWS_WITH(make_system_grid_plan(r), Catch::StartsWith("--theta-from/--theta-to: "));
  }
}

TEST_CASE("grid map file sinks: the .npy cells are the one-point closed form", "[rate][maps]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("cpkit_test_map_sinks_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string prefix = (dir / "pd").string();
  MapAxis axis;
  axis.param = map_parameter("mu");
  axis.from = 0.5;
  axis.to = 3.0;
  axis.n = 4;
  const int theta_n = 12;
  const ParamDirectionMap m =
      compute_param_direction_map(wedge_params(), ContactState{}, axis, theta_n);
  nlohmann::json files = nlohmann::json::object();
  GridFiles out(prefix, files);
  const ParamDirectionSink sink = param_direction_files(out, axis, m.theta, true, false, false);
  for (int i = 0; i < axis.n; i += 2) {  // two blocks of two rows, in row order
    ParamDirectionRows rows;
    rows.row_begin = i;
    rows.row_end = i + 2;
    rows.count = m.count.data() + static_cast<std::size_t>(i) * theta_n;
    rows.types = m.types.data() + static_cast<std::size_t>(i) * theta_n;
    sink(rows);
  }
  out.finish();
  CHECK(files == nlohmann::json::parse(R"({"count": "pd_count.npy", "types": "pd_types.npy",
                                           "x": "pd_x.npy", "theta": "pd_theta.npy"})"));
  std::ifstream in(prefix + "_count.npy", std::ios::binary);
  const std::string npy((std::istreambuf_iterator<char>(in)), {});
  REQUIRE(npy.size() > 10);
  const std::size_t header = static_cast<unsigned char>(npy[8]) + 256u * static_cast<unsigned char>(npy[9]);
  CHECK(npy.find("'shape': (4, 12)") != std::string::npos);
  REQUIRE(npy.size() == 10 + header + 48);
  for (int i = 0; i < axis.n; ++i)
    for (int k = 0; k < theta_n; ++k) {
      const double t = (k + 0.5) * kTwoPi / theta_n;
      const int expected = summarize_rate_analytic(wedge_params(axis.value(i)), ContactState{},
                                                   LoadRate{std::cos(t), std::sin(t)})
                               .count;
      CAPTURE(i, k);
      CHECK(static_cast<int8_t>(npy[10 + header + static_cast<std::size_t>(i * theta_n + k)]) ==
            expected);
    }
  fs::remove_all(dir);
}

TEST_CASE("map requests: the options given, in the order the first refused is named",
          "[rate][maps]") {
  MapRequest a;
  CHECK(map_options_given(a).empty());
  a.theta_n = 12;
  a.mu = 1;
  a.C_T = 0.5;
  // Byte order, as `cpkit map` has always named the first refused option: "--C_T" < "--mu".
  CHECK(map_options_given(a) == std::vector<std::string>{"--C_T", "--mu", "--theta-n"});
  a.system = "two.json";
  CHECK_THROWS_WITH(system_map_request(a, SystemFile{}, 1),
                    Catch::StartsWith("--C_T does not apply with --system --kind direction"));
  // Every option given: 36 distinct names, sorted as std::string compares them.
  a.preset = a.kind = a.state = a.criterion = a.method = a.out = a.param = a.param2 = "x";
  a.format = a.max_output = a.others = "x";
  a.time_limit = a.a11 = a.a12 = a.a22 = a.k_a = a.P_s = a.P_N = a.gamma = 1;
  a.from = a.to = a.from2 = a.to2 = a.theta_from = a.theta_to = 1;
  a.sgnPT = a.n = a.n2 = a.threads = a.facets = a.point = 1;
  a.resume = true;
  const std::vector<std::string> all = map_options_given(a);
  CHECK(all.size() == 36);
  CHECK(std::is_sorted(all.begin(), all.end()));
  CHECK(std::adjacent_find(all.begin(), all.end()) == all.end());
}

TEST_CASE("map requests: the options that apply to N-point and 3-D maps", "[rate][maps]") {
  MapRequest a;
  a.system = "two.json";
  SECTION("N points: defaults, and options that do not apply") {
    a.kind = "param-direction";
    a.param = "mu";
    a.from = 0;
    a.to = 1;
    const SystemMapRequest r = system_map_request(a, SystemFile{}, 1);
    CHECK(r.kind == "param-direction");
    CHECK(r.n == 100);  // docs/maps.md: --system maps default to 100 values per axis
    CHECK(r.theta_n == 360);
    CHECK(r.theta_to == Approx(kTwoPi));
    CHECK(r.max_output == 4.0 * 1024 * 1024 * 1024);  // --max-output 4G
    a.mu = 0;
    CHECK_THROWS_WITH(system_map_request(a, SystemFile{}, 1),
                      Catch::StartsWith("--mu does not apply with --system --kind param-direction"));
    MapRequest d;
    d.system = "two.json";
    CHECK_THROWS_WITH(system_map_request(d, SystemFile{}, 2),
                      Catch::StartsWith("a direction map is one exact computation"));
    d.kind = "param-direction";
    d.param = "mu";
    d.from = 0;
    CHECK_THROWS_WITH(system_map_request(d, SystemFile{}, 1),
                      "--system --kind param-direction needs --to");
  }
  SECTION("3-D: the kind is required; options of other kinds are refused") {
    CHECK_THROWS_WITH(check_map_3d_request(a), Catch::StartsWith("maps of a dim 3 system need --kind"));
    a.kind = "sphere";
    a.theta_n = 360;
    CHECK_THROWS_WITH(check_map_3d_request(a),
                      Catch::StartsWith("--theta-n has no effect with a dim 3 system and --kind sphere"));
    a.theta_n.reset();
    CHECK_NOTHROW(check_map_3d_request(a));
    CHECK_THROWS_WITH(check_map_3d_request(a, 2), Catch::StartsWith("3-D maps run on the threads of one process"));
  }
}
