// Keeps the documentation's examples true: every example in README.md and docs/*.md that shows
// a `$ cpkit ...` command followed by its output is run, and the documented output must be what
// the program prints (numbers to the precision shown, timings excepted, "..." skips). Also the
// JSON fields the docs promise. Independent source: the docs' own text, written by hand.
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
