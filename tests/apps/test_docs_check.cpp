// Keeps the documentation current: every example in README.md and docs/*.md that shows a
// `$ cpkit ...` command followed by its output is run, and the documented output must be what
// the program prints (numbers to the precision shown, timings excepted, "..." skips). Also the
// JSON fields the docs promise. The outputs in the docs are pasted program output, so that part
// only says the docs are up to date, not that the numbers are right. The numbers a reader relies
// on are checked independently in the last test case: recomputed here by hand from the model's
// equations (docs/contact_model.md, docs/simulation.md) and compared with the docs' text.
#include <sys/wait.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;
using cpkit::test::slurp;

struct Token {
  std::string text;
  bool timing = false;  ///< a wall-clock time: any number matches
};

/// Tokens of an output text, line by line. A number is a timing when it is followed by "s"
/// ("0.01 s", "(1.2 s)") or sits in the column of a table header named "seconds".
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> out;
  std::istringstream lines(text);
  std::string line;
  int seconds_column = -1;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    int header = -1;
    for (std::size_t k = 0; k < words.size(); ++k)
      if (words[k] == "seconds") header = static_cast<int>(k);
    for (std::size_t k = 0; k < words.size(); ++k) {
      Token t{words[k], false};
      if (k + 1 < words.size() && (words[k + 1] == "s" || words[k + 1].rfind("s)", 0) == 0))
        t.timing = true;
      if (header < 0 && seconds_column >= 0 && static_cast<int>(k) == seconds_column)
        t.timing = true;
      out.push_back(t);
    }
    if (header >= 0) seconds_column = header;
    if (words.empty()) seconds_column = -1;
  }
  return out;
}

/// Equal tokens: the same text around the numbers, and each number equal to the precision the
/// docs show (relative 1e-3, or half a unit of the last digit shown); two numbers below 1e-9
/// (residuals at rounding level, which differ between machines) are equal.
bool same_token(const Token& doc, const std::string& actual) {
  static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  auto skeleton = [](const std::string& s) { return std::regex_replace(s, number, "#"); };
  if (skeleton(doc.text) != skeleton(actual)) return false;
  if (doc.timing) return true;
  auto a = std::sregex_iterator(doc.text.begin(), doc.text.end(), number);
  auto b = std::sregex_iterator(actual.begin(), actual.end(), number);
  for (; a != std::sregex_iterator() && b != std::sregex_iterator(); ++a, ++b) {
    const std::string ds = a->str();
    const double x = std::stod(ds), y = std::stod(b->str());
    const auto dot = ds.find('.');
    const bool has_exp = ds.find_first_of("eE") != std::string::npos;
    const double unit = (dot == std::string::npos || has_exp)
                            ? 0.0
                            : 0.5 * std::pow(10.0, -static_cast<double>(ds.size() - dot - 1));
    if (std::abs(x) < 1e-9 && std::abs(y) < 1e-9) continue;  // both at rounding level
    if (std::abs(x - y) > std::max(unit * 1.0001, 1e-3 * std::abs(x)) + 1e-300) return false;
  }
  return true;
}

/// The documented output must appear in the actual output from its first token on, token by
/// token; a "..." in the docs skips actual tokens up to the next documented one.
std::string mismatch(const std::vector<Token>& doc, const std::vector<Token>& act) {
  std::size_t j = 0;
  // Start where the first documented token appears.
  while (j < act.size() && !doc.empty() && !same_token(doc[0], act[j].text)) ++j;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    if (doc[i].text == "...") {
      if (i + 1 < doc.size() && doc[i + 1].text == "...") continue;  // one skip is enough
      if (i + 1 == doc.size()) return {};
      while (j < act.size() && !same_token(doc[i + 1], act[j].text)) ++j;
      continue;
    }
    if (j >= act.size()) return "the output ends before '" + doc[i].text + "'";
    if (!same_token(doc[i], act[j].text))
      return "documented '" + doc[i].text + "', printed '" + act[j].text + "'";
    ++j;
  }
  return {};
}

struct Example {
  std::string file, command, output;
};

/// `$ cpkit ...` examples of a Markdown file: fenced blocks whose lines start with "$ cpkit".
std::vector<Example> examples_of(const std::string& rel) {
  std::ifstream in(fs::path(CPKIT_SOURCE_DIR) / rel);
  std::vector<Example> out;
  bool fenced = false;
  Example* cur = nullptr;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      cur = nullptr;
      continue;
    }
    if (!fenced) continue;
    if (line.rfind("$ cpkit ", 0) == 0) {
      out.push_back({rel, line.substr(8), ""});
      cur = &out.back();
    } else if (cur) {
      cur->output += line + "\n";
    }
  }
  return out;
}

/// A working folder with what the examples read (tests/data, docs/examples): the examples run
/// there, so their outputs (the simulate config's out/) never land in the source tree.
fs::path example_dir() {
  static const fs::path dir = [] {
    const fs::path d = scratch_dir() / "docs_examples";
    fs::create_directories(d / "docs");
    fs::create_directories(d / "tests");
    fs::copy(fs::path(CPKIT_SOURCE_DIR) / "docs" / "examples", d / "docs" / "examples",
             fs::copy_options::recursive | fs::copy_options::skip_existing);
    fs::create_directory_symlink(fs::path(CPKIT_SOURCE_DIR) / "tests" / "data", d / "tests" / "data");
    return d;
  }();
  return dir;
}

}  // namespace

TEST_CASE("every documented `$ cpkit ...` example prints what the docs show", "[cli][docs]") {
  std::vector<std::string> files = {"README.md"};
  for (const auto& e : fs::directory_iterator(fs::path(CPKIT_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") files.push_back("docs/" + e.path().filename().string());
  // CPKIT_DOCS_CHECK_SKIP: ';'-separated substrings; a documented command containing one is not
  // run, and says so. scripts/run-sanitizers.sh uses it for the one example that costs minutes
  // under ASan (the Release suite runs every example).
  std::vector<std::string> skip;
  if (const char* env = std::getenv("CPKIT_DOCS_CHECK_SKIP")) {
    std::istringstream in(env);
    for (std::string s; std::getline(in, s, ';');)
      if (!s.empty()) skip.push_back(s);
  }
  int checked = 0, skipped = 0;
  for (const auto& f : files)
    for (const Example& ex : examples_of(f)) {
      CAPTURE(ex.file, ex.command);
      bool skip_this = false;
      for (const auto& s : skip) skip_this = skip_this || ex.command.find(s) != std::string::npos;
      if (skip_this) {
        std::cout << "docs check: not run (CPKIT_DOCS_CHECK_SKIP): " << ex.file << ": cpkit "
                  << ex.command << "\n";
        ++skipped;
        continue;
      }
      // Run from the example folder (relative paths as in the docs).
      const std::string cmd = "cd '" + example_dir().string() + "' && '" + CPKIT_BINARY_DIR +
                              "/apps/cpkit' " + ex.command + " > out.txt 2> err.txt";
      const int status = std::system(cmd.c_str());
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      const std::string out = slurp(example_dir() / "out.txt");
      CAPTURE(out, slurp(example_dir() / "err.txt"));
      CHECK((code == 0 || code == 1));  // documented examples are runs, not usage errors
      const std::string why = mismatch(tokenize(ex.output), tokenize(out));
      CAPTURE(ex.output);
      CHECK(why == "");
      ++checked;
    }
  CHECK(checked >= 8);  // README, contact_model, mpcc, simulation (the checker finds them)
  CHECK(skipped <= 1);  // the skip list names single expensive examples, never whole documents
}

TEST_CASE("maps.md's sample output of `cpkit map --preset fig5b` is what it prints", "[cli][docs]") {
  const std::string md = slurp(fs::path(CPKIT_SOURCE_DIR) / "docs" / "maps.md");
  const std::string head = "Output of `cpkit map --preset fig5b`:\n```\n";
  const auto at = md.find(head);
  REQUIRE(at != std::string::npos);
  const auto end = md.find("```", at + head.size());
  const std::string doc = md.substr(at + head.size(), end - at - head.size());
  const cpkit::test::CliRun r = run_cpkit("map --preset fig5b");
  REQUIRE(r.code == 0);
  CHECK(mismatch(tokenize(doc), tokenize(r.out)) == "");
}

TEST_CASE("documented JSON fields are present", "[cli][docs]") {
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/battle_of_the_sexes.json";
  auto json_of = [](const std::string& args) {
    const cpkit::test::CliRun r = run_cpkit(args);
    INFO(args << "\n" << r.err);
    REQUIRE((r.code == 0 || r.code == 1));
    return nlohmann::json::parse(r.out);
  };
  auto has_all = [](const nlohmann::json& j, std::initializer_list<const char*> keys) {
    for (const char* k : keys) {
      CAPTURE(k);
      CHECK(j.contains(k));
    }
  };
  // README: "With --json, stdout is one JSON object" (also with --all-solvers).
  CHECK(json_of("lcp solve '" + lcp + "' --all-solvers --json").is_object());
  // conventions.md: the run object of every JSON result.
  for (const std::string& args :
       {"lcp solve '" + lcp + "' --json", "lcp enumerate '" + lcp + "' --json",
        std::string("rate --state b --a11 1 --a12 0.5 --a22 1 --mu 3 --dF 1 1 --json"),
        std::string("step --a11 1 --a12 0 --a22 1 --mu 0.5 --P_T0 0 --P_N0 1 --g0 0 --DF 0.1 0 --json"),
        std::string("map --preset fig5b --json"),
        std::string("simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --load ramp --F_N1 1 --steps 4 --json")}) {
    CAPTURE(args);
    const auto j = json_of(args);
    REQUIRE(j.contains("run"));
    CHECK(j["run"]["cpkit_version"].is_string());
    CHECK(j["run"]["command"].is_array());
    CHECK(j["run"]["options"].is_object());
  }
  // enumeration.md: the enumerate fields, message included.
  has_all(json_of("lcp enumerate '" + lcp + "' --json"),
          {"complete", "count", "num_extreme", "solutions", "continuum", "ambiguous", "nodes",
           "seconds", "message"});
  // contact_model.md: the rate fields, D_plus and D_minus as the text prints D_+ and D_-.
  const auto rate = json_of("rate --state b --a11 1 --a12 0.5 --a22 1 --mu 3 --dF 1 1 --json");
  has_all(rate, {"complete", "count", "types", "solutions", "Lambda", "D_plus", "D_minus",
                 "unique_for_all_directions"});
  CHECK(rate["D_plus"] == Approx(1 - 3 * 0.5));  // D_s = a11 - s mu a12
  CHECK(rate["D_minus"] == Approx(1 + 3 * 0.5));
  // conventions.md: options echoed with the values used, defaults included.
  CHECK(rate["run"]["options"]["mu"] == 3);
  CHECK(rate["run"]["options"]["C_T"] == 0);
  CHECK(rate["run"]["options"]["json"] == true);
}

TEST_CASE("the docs stand alone: every relative link resolves, nothing points outside",
          "[docs]") {
  // Docs that send the reader to a file not in the repository (model.md once) are broken.
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  std::vector<fs::path> files = {fs::path(CPKIT_SOURCE_DIR) / "README.md"};
  for (const auto& e : fs::recursive_directory_iterator(fs::path(CPKIT_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  int links = 0;
  for (const auto& f : files) {
    const std::string text = slurp(f);
    CAPTURE(f.string());
    CHECK(text.find("shared/docs") == std::string::npos);  // the team's notes are not shipped
    CHECK(text.find("/work/") == std::string::npos);
    for (auto m = std::sregex_iterator(text.begin(), text.end(), link); m != std::sregex_iterator();
         ++m) {
      std::string target = (*m)[1].str();
      if (target.rfind("http", 0) == 0 || target[0] == '#') continue;
      target = target.substr(0, target.find('#'));
      CAPTURE(target);
      CHECK(fs::exists(f.parent_path() / target));
      ++links;
    }
  }
  CHECK(links > 20);
}

namespace {

/// A number the docs show: the first capture of `pattern` in the documented output of the
/// example of `file` whose command contains `command` (the docs' text, not a program run).
std::string doc_number(const std::string& file, const std::string& command,
                       const std::string& pattern) {
  for (const Example& ex : examples_of(file)) {
    if (ex.command.find(command) == std::string::npos) continue;
    std::smatch m;
    if (std::regex_search(ex.output, m, std::regex(pattern))) return m[1].str();
  }
  return "(not found: " + file + ": " + command + ": " + pattern + ")";
}

/// The shown number equals `hand` to the digits shown (half a unit of its last digit).
bool shows(const std::string& shown, double hand) {
  const auto dot = shown.find('.');
  const double unit =
      dot == std::string::npos ? 0.5 : 0.5 * std::pow(10.0, -static_cast<double>(shown.size() - dot - 1));
  try {
    return std::abs(std::stod(shown) - hand) <= unit * 1.0001;
  } catch (const std::exception&) {
    return false;
  }
}

#define CHECK_SHOWN(file, command, key, hand)                      \
  do {                                                             \
    const std::string shown_ = doc_number(file, command, key);     \
    INFO(file << ": `cpkit " << command << "`: " << key << " shows " << shown_ << ", by hand " \
              << (hand));                                          \
    CHECK(shows(shown_, hand));                                    \
  } while (false)

const std::string kNum = R"(([-+]?[0-9]*\.?[0-9]+))";

}  // namespace

TEST_CASE("the numbers the docs' examples show, recomputed by hand", "[docs]") {
  // Rate and step problems (docs/contact_model.md, docs/simulation.md): equilibrium
  // dF - dP = A dw with A = [[a11, a12], [a12, a22]] (C_T = 0: dw_T^i = dw_T); separation dP = 0,
  // stick dw = 0 (dP = dF), slip+ dP_T = mu dP_N with dw_N = 0. 2x2 systems by Cramer's rule.
  {
    // contact_model.md, state b: A = [[1, 2], [2, 5]] (det 1), mu = 1, dF = (1, 1.2).
    const std::string f = "docs/contact_model.md", c = "--mu 1 --dF 1 1.2";
    const double det = 1 * 5 - 2 * 2;
    // separation: dw = A^-1 dF = (5 - 2.4, -2 + 1.2) / det = (2.6, -0.8)
    CHECK_SHOWN(f, c, "separation point:.*dw_T=" + kNum, (5 * 1 - 2 * 1.2) / det);
    CHECK_SHOWN(f, c, "separation point:.*dw_N=" + kNum, (-2 * 1 + 1 * 1.2) / det);
    CHECK_SHOWN(f, c, "stick point: dP_T=" + kNum, 1.0);
    CHECK_SHOWN(f, c, "stick point:.*dP_N=" + kNum, 1.2);
    // slip+: dw = A^-1 (dF - (p, p)), dw_N = 0: -2 (1 - p) + (1.2 - p) = 0, p = 0.8;
    // dw_T = (5 (1 - p) - 2 (1.2 - p)) / det = 0.2.
    const double p = (2 * 1 - 1.2) / (2 - 1);
    CHECK_SHOWN(f, c, "slip\\+ point: dP_T=" + kNum, p);
    CHECK_SHOWN(f, c, "slip\\+ point:.*dP_N=" + kNum, p);
    CHECK_SHOWN(f, c, "slip\\+ point:.*dw_T=" + kNum, (5 * (1 - p) - 2 * (1.2 - p)) / det);
  }
  {
    // simulation.md, one step from P = (2, 1) on the cone (mu = 2), A = [[1, 0.9], [0.9, 1]]
    // (det 0.19), dF = (-0.01, 0).
    const std::string f = "docs/simulation.md", c = "--mu 2 --P_T0 2 --P_N0 1";
    const double det = 1 - 0.81, dFT = -0.01, dFN = 0;
    // separation jumps to P = 0: DP = (-2, -1), Dw = A^-1 (dF - DP) = A^-1 (1.99, 1).
    CHECK_SHOWN(f, c, "separation \\(point, jump\\):.*Dw_T=" + kNum, (1.99 - 0.9 * 1) / det);
    CHECK_SHOWN(f, c, "separation \\(point, jump\\):.*Dw_N=" + kNum, (-0.9 * 1.99 + 1) / det);
    CHECK_SHOWN(f, c, "separation \\(point, jump\\):.*g1=" + kNum, (-0.9 * 1.99 + 1) / det);
    CHECK_SHOWN(f, c, "stick \\(point\\):.*P_T1=" + kNum, 2 + dFT);
    // slip+: DP_T = 2 DP_N, Dw_N = 0: -0.9 (dFT - 2 x) + (dFN - x) = 0, x = -0.009 / 0.8.
    const double x = (0.9 * dFT - dFN) / (2 * 0.9 - 1);
    CHECK_SHOWN(f, c, "slip\\+ \\(point\\): DP_T=" + kNum, 2 * x);
    CHECK_SHOWN(f, c, "slip\\+ \\(point\\):.*DP_N=" + kNum, x);
    CHECK_SHOWN(f, c, "slip\\+ \\(point\\):.*Dw_T=" + kNum, ((dFT - 2 * x) - 0.9 * (dFN - x)) / det);
    CHECK_SHOWN(f, c, "slip\\+ \\(point\\):.*P_N1=" + kNum, 1 + x);
  }
  {
    // simulation.md, criterion (35): Y(P) = mu P - k P^2 >= 0 needs P_N <= mu / k = 3 P_s mu /
    // k_a = 3 * 1 * 0.5 / 0.3 = 5 (P_s = 1, the default). The ramp F_N = 10 t in 100 steps of
    // 0.01 first asks for more at step 51: t = 0.51, F_N = 5.1 (W = I: P_N = F_N in contact).
    const std::string f = "docs/simulation.md", c = "--criterion 35 --load ramp";
    CHECK_SHOWN(f, c, "mu / k_a = " + kNum, 3 * 1 * 0.5 / 0.3);
    CHECK_SHOWN(f, c, "stopped before t = " + kNum, 51 * 0.01);
    CHECK_SHOWN(f, c, "load \\(0, " + kNum, 10 * 0.51);
  }
  {
    // simulation.md, docs/examples/fretting.json: Archard wear dw^w = k P_N |dw_T^i|,
    // k = k_a / (3 P_s), integrated here step by step from the equations of simulation.md Sec. 1
    // (backward Euler, wear at the end of the step), in total form from the unloaded state:
    //   F_T - P_T = a11 w_T + a12 w_N,  F_N - P_N = a12 w_T + a22 w_N,
    //   w_T = C_T P_T + w_T^i,  w_N = w^w (in contact, g = 0),  |P_T| <= mu P_N (criterion 38).
    // A step sticks (w_T^i fixed) when that is admissible; else it slips with P_T = s mu P_N, a
    // 2x2 linear system in (P_N, w_T^i) for a given w^w, iterated with the wear law.
    const double a11 = 2.0, a12 = 0.3, a22 = 1.5, mu = 0.5, C_T = 0.4, k = 0.003 / (3 * 1.0);
    const double F_N = 1.0, amplitude = 1.2, dt = 1.0 / 100;
    double wi = 0, ww = 0, slip = 0, archard = 0, P_T = 0, P_N = 0;
    for (int step = 1; step <= 10 + 20 * 100; ++step) {
      const double FN = step <= 10 ? F_N * step / 10 : F_N;
      const double FT = step <= 10 ? 0 : amplitude * std::sin(2 * std::acos(-1.0) * (step - 10) * dt);
      P_T = (FT - a11 * wi - a12 * ww) / (1 + a11 * C_T);  // stick
      P_N = FN - a12 * (C_T * P_T + wi) - a22 * ww;
      if (std::abs(P_T) <= mu * P_N) continue;
      const double s = P_T > 0 ? 1 : -1;
      // [s mu (1 + a11 C_T), a11; 1 + a12 C_T s mu, a12] (P_N, w_T^i) = (FT - a12 w^w, FN - a22 w^w)
      const double m11 = s * mu * (1 + a11 * C_T), m12 = a11, m21 = 1 + a12 * C_T * s * mu,
                   m22 = a12, d = m11 * m22 - m12 * m21;
      double w = ww, x = 0, y = 0;
      for (int it = 0; it < 60; ++it) {
        const double r1 = FT - a12 * w, r2 = FN - a22 * w;
        x = (r1 * m22 - m12 * r2) / d;
        y = (m11 * r2 - m21 * r1) / d;
        w = ww + k * x * std::abs(y - wi);
      }
      REQUIRE(s * (y - wi) >= 0);  // the slip goes the way P_T points
      slip += std::abs(y - wi);
      archard += k * x * std::abs(y - wi);
      wi = y;
      ww = w;
      P_N = x;
      P_T = s * mu * x;
    }
    const std::string f = "docs/simulation.md", c = "--config docs/examples/fretting.json";
    CHECK_SHOWN(f, c, "final wear depth " + kNum, ww);
    CHECK_SHOWN(f, c, "Archard integral " + kNum, archard);
    CHECK_SHOWN(f, c, "total slip " + kNum, slip);
    CHECK_SHOWN(f, c, "P_T = " + kNum, P_T);
    CHECK_SHOWN(f, c, "P_N = " + kNum, P_N);
  }
}
