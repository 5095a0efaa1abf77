// The messages a newcomer meets (issue 37, "A newcomer's third hour"), each asserted against
// what the user typed: a missing option points to its subcommand's help; an unknown solver,
// option or subcommand gets the valid names or the nearest one ("did you mean"); a JSON LCP
// file given to `fc solve` is named as such; "1 contact"; `fc bench` names problems by file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace {

using cpkit::test::CliRun;
using cpkit::test::run_cpkit;

std::string fclib(const std::string& rel) {
  return std::string(CPKIT_TEST_DATA_DIR) + "/fclib/" + rel;
}

bool has(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

/// Exit 2, nothing on stdout, and every `what` on stderr.
void bad(const std::string& args, std::initializer_list<const char*> what) {
  INFO(args);
  const CliRun r = run_cpkit(args);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  for (const char* w : what) CHECK(has(r.err, w));
}

}  // namespace

TEST_CASE("a missing option points to the help of its subcommand", "[cli][messages]") {
  // `fc bench FILE` without --out: says --out is missing, and where --out is described.
  bad("fc bench '" + fclib("local/FrictionContact3D_1c.dat") + "'",
      {"--out is required", "run 'cpkit fc bench --help'"});
  bad("lcp solve", {"FILE is required", "run 'cpkit lcp solve --help'"});
  // That help does describe --out.
  const CliRun h = run_cpkit("fc bench --help");
  CHECK(h.code == 0);
  CHECK(has(h.out, "--out"));
}

TEST_CASE("an unknown friction solver in --solvers lists the valid names", "[cli][messages]") {
  bad("fc bench '" + fclib("local/FrictionContact3D_1c.dat") + "' --solvers nsgs,siconos --out '" +
          (cpkit::test::scratch_dir() / "never").string() + "'",
      {"unknown friction solver 'siconos' in --solvers", "(valid: ", "nsgs", "fb-soc", "prox"});
  CHECK_FALSE(std::filesystem::exists(cpkit::test::scratch_dir() / "never.csv"));
}

TEST_CASE("did you mean: the nearest option or subcommand of a typo", "[cli][messages]") {
  // One edit (a swap, a wrong letter, a missing letter) from a valid name: named.
  bad("mpa --preset fig5b", {"unknown subcommand 'mpa' for 'cpkit'", "did you mean map?",
                             "valid: "});
  bad("lcp slove x.json", {"unknown subcommand 'slove' for 'cpkit lcp'", "did you mean solve?"});
  bad("map --preset fig5b --kind param-direction --theta-m 5",
      {"unknown option --theta-m for 'cpkit map'", "did you mean --theta-n?"});
  bad("fc solve x.dat --solvr nsgs", {"unknown option --solvr", "did you mean --solver?"});
  bad("rate --state b --MU 2", {"unknown option --MU", "did you mean --mu?"});
  // Nothing near: no guess.
  for (const char* args : {"foo", "step --bogus", "lcp solve x.json --frobnicate 3"}) {
    INFO(args);
    const CliRun r = run_cpkit(args);
    CHECK(r.code == 2);
    CHECK_FALSE(has(r.err, "did you mean"));
  }
}

TEST_CASE("fc solve --help says it solves local and global problems", "[cli][messages]") {
  const CliRun h = run_cpkit("fc solve --help");
  CHECK(h.code == 0);
  CHECK(has(h.out, "local or global"));
  CHECK(has(h.out, "GlobalFrictionContact"));
  // And it does: a global Siconos file is solved (exit 0 or 5, never bad input).
  const CliRun g = run_cpkit("fc solve '" + fclib("global/GFC3D_Example1.dat") + "'");
  INFO(g.err);
  CHECK(g.code != 2);
  CHECK(has(g.out, "(global: "));
}

TEST_CASE("an LCP JSON file given to fc solve is named as such", "[cli][messages]") {
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/deudeu.json";
  bad("fc solve '" + lcp + "'",
      {"an LCP file (JSON with M and q)", "not a frictional contact problem", "cpkit lcp solve"});
  const CliRun r = run_cpkit("fc solve '" + lcp + "'");
  CHECK_FALSE(has(r.err, "contact dimension"));
  // Other JSON: said to be JSON, no LCP guess.
  const auto other = cpkit::test::scratch_dir() / "other.json";
  std::ofstream(other) << "  [1, 2, 3]\n";
  bad("fc solve '" + other.string() + "'", {"a JSON file, not a frictional contact problem"});
}

TEST_CASE("one contact is '1 contact'", "[cli][messages]") {
  const CliRun r = run_cpkit("fc solve '" + fclib("local/FrictionContact3D_1c.dat") + "'");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(has(r.out, "(1 contact)"));
  CHECK_FALSE(has(r.out, "1 contacts"));
  const CliRun s = run_cpkit("fc solutions '" + fclib("local/FrictionContact3D_1c.dat") +
                             "' --starts 2");
  CHECK(has(s.out, "(1 contact)"));
}

TEST_CASE("fc bench names each problem by its file in the progress log", "[cli][messages]") {
  // Two files of the same problem title would be indistinguishable by title; by file they are.
  const auto dir = cpkit::test::scratch_dir() / "bench_names";
  std::filesystem::create_directories(dir);
  const std::string a = fclib("local/FrictionContact3D_1c.dat");
  const std::string b = (dir / "copy_of_1c.dat").string();
  std::filesystem::copy_file(a, b);
  const CliRun r = run_cpkit("fc bench '" + a + "' '" + b + "' --solvers nsgs --no-plot --out '" +
                             (dir / "t").string() + "'");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(has(r.err, a + " nsgs: solved in "));
  CHECK(has(r.err, b + " nsgs: solved in "));
  // An FCLIB file: its title beside the file name.
  const std::string h = fclib("local/fclib_local_problem_test.hdf5");
  const CliRun f = run_cpkit("fc bench '" + h + "' --solvers nsgs --time-limit 5 --no-plot --out '" +
                             (dir / "h").string() + "'");
  INFO(f.err);
  CHECK(has(f.err, h + " ("));
  CHECK(has(f.err, ") nsgs: "));
}
