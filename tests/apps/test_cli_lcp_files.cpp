// `cpkit lcp solve|enumerate` on every problem-file format: Siconos' own .dat files give the
// problems Siconos states (issue 11: read as bare matrices they gave "solved" for other
// problems), a Matrix Market M with its q beside it or from --q, and bad files exit 2 with a
// message (never 4, "internal error"), including file names that are not UTF-8.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace {

using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;
using Catch::Contains;

std::string siconos(const std::string& name) {
  return std::string("'") + CPKIT_TEST_DATA_DIR + "/siconos/" + name + "'";
}

std::string write(const std::string& name, const std::string& text) {
  const auto path = scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return "'" + path.string() + "'";
}

/// z of a `--json` run that must have solved the problem.
std::vector<double> solved_z(const std::string& args) {
  const auto r = run_cpkit(args + " --json");
  INFO(args << "\n" << r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("status") == "solved");
  return j.at("z").get<std::vector<double>>();
}

const std::string kM = "%%MatrixMarket matrix coordinate real general\n2 2 4\n1 1 2\n1 2 1\n2 1 1\n2 2 2\n";
const std::string kQ = "%%MatrixMarket matrix array real general\n2 1\n-5\n-6\n";

}  // namespace

TEST_CASE("cli: Siconos .dat files solve to the problems they state", "[cli][io]") {
  // deudeu: M = [[2, 1], [1, 2]], q = (-5, -6); unique solution (4/3, 7/3) (dense and sparse block).
  for (const char* file : {"lcp_deudeu.dat", "lcp_deudeu_block.dat"}) {
    const auto z = solved_z("lcp solve " + siconos(file));
    REQUIRE(z.size() == 2);
    CHECK(z[0] == Approx(4.0 / 3.0).epsilon(1e-12));
    CHECK(z[1] == Approx(7.0 / 3.0).epsilon(1e-12));
  }
  // trivial_block: M = diag(1..9), q = -1: z_i = 1/i.
  const auto z = solved_z("lcp solve " + siconos("lcp_trivial_block.dat"));
  REQUIRE(z.size() == 9);
  for (int i = 0; i < 9; ++i) CHECK(z[static_cast<std::size_t>(i)] == Approx(1.0 / (i + 1)).epsilon(1e-12));
  // CPS_1: the segment z1 + z2 = 1 (a continuum) is what the enumeration reports.
  const auto e = run_cpkit("lcp enumerate " + siconos("lcp_CPS_1.dat") + " --json");
  INFO(e.err);
  REQUIRE(e.code == 0);
  CHECK_THAT(e.out, Contains("continu"));
}

TEST_CASE("cli: a Matrix Market M with its q beside it or from --q", "[cli][io]") {
  const auto m = write("A.mtx", kM);
  write("A.q.mtx", kQ);
  for (const std::string& args : {"lcp solve " + m, "lcp solve " + write("B.mtx", kM) + " --q " +
                                                        write("rhs.mtx", kQ)}) {
    const auto z = solved_z(args);
    REQUIRE(z.size() == 2);
    CHECK(z[0] == Approx(4.0 / 3.0).epsilon(1e-12));
    CHECK(z[1] == Approx(7.0 / 3.0).epsilon(1e-12));
  }
  CHECK(run_cpkit("lcp enumerate " + m).code == 0);
  // M alone: exit 2 saying what to do.
  const auto r = run_cpkit("lcp solve " + write("C.mtx", kM));
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Contains("C.q.mtx beside it, which does not exist (give q with --q FILE"));
  // --q with a file that holds q itself.
  const auto j = run_cpkit("lcp solve " + siconos("lcp_deudeu.dat") + " --q " + write("q2.mtx", kQ));
  CHECK(j.code == 2);
  CHECK_THAT(j.err, Contains("a separate q file is only read with a Matrix Market (.mtx) or numpy (.npy) M"));
}

TEST_CASE("cli: numpy .npy M with q beside it or from --q", "[cli][io][npy]") {
  // tests/data/npy/make_npy.py: M = [[2, 1, 0], [1, 3, 1], [0, 1, 4]], q = (-2, 0, 3), unique
  // solution z = (1, 0, 0)
  const std::string dir = std::string("'") + CPKIT_TEST_DATA_DIR + "/npy/";
  for (const std::string& args : {"lcp solve " + dir + "lcp3.npy'",
                                  "lcp solve " + dir + "lcp3.npy' --q " + dir + "q_column.npy'",
                                  "lcp solve " + dir + "lcp3.npy' --solver fb-newton"}) {
    const auto z = solved_z(args);
    REQUIRE(z.size() == 3);
    CHECK(std::abs(z[0] - 1) < 1e-9);
    CHECK(std::abs(z[1]) < 1e-9);
    CHECK(std::abs(z[2]) < 1e-9);
  }
  const auto e = run_cpkit("lcp solve " + dir + "A_int64.npy' --q " + dir + "q_column.npy'");
  CHECK(e.code == 2);
  CHECK(e.out.empty());
  CHECK_THAT(e.err, Contains("A_int64.npy") && Contains("dtype '<i8' is not supported"));
}

TEST_CASE("cli: bad problem files exit 2 with the reason, never 4", "[cli][io]") {
  struct Case {
    std::string file, text, message;
  };
  const Case cases[] = {
      {"big.json", R"({"M": [[1]], "q": [1e400]})", "'1e400' is outside the range of double"},
      {"deep.json", std::string(10000, '[') + std::string(10000, ']'), "nesting deeper than 64"},
      {"unknown.json", R"({"M": [[1]], "q": [1], "Q": 1})", "unknown field \"Q\""},
      {"size.json", R"({"n": 3, "M": [[2, 1], [1, 2]], "q": [-5, -6]})",
       "field \"n\" is 3 but M is 2 x 2"},
      {"storage2.dat", "2\n2\n2\n2\n0\n1 2\n", "storage2.dat:2: storage type 2"},
      {"old.dat", "2\n1 2\n3 4\n5 6\n", "old.dat:3:"},
      {"sym.mtx", "%%MatrixMarket matrix coordinate real symmetric\n2 3 1\n1 3 1\n",
       "a symmetric matrix must be square"},
  };
  write("sym.q.mtx", kQ);
  for (const auto& c : cases) {
    const auto r = run_cpkit("lcp solve " + write(c.file, c.text) + " --json");
    INFO(c.file << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains(c.message));
  }
}

TEST_CASE("cli: an LCP file with its size \"n\" is read", "[cli][io]") {
  // Issue 27. M = [[2, 1], [1, 2]], q = (-5, -6): w = 0 gives z = M^-1 (5, 6) = (4/3, 7/3) by hand.
  const auto r =
      run_cpkit("lcp solve " + write("with_n.json", R"({"n": 2, "M": [[2, 1], [1, 2]], "q": [-5, -6]})") +
                " --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto z = nlohmann::json::parse(r.out)["z"];
  CHECK(std::abs(z[0].get<double>() - 4.0 / 3) < 1e-12);
  CHECK(std::abs(z[1].get<double>() - 7.0 / 3) < 1e-12);
}

TEST_CASE("cli: a file name that is not UTF-8 is printed as valid JSON", "[cli][io]") {
  // The .dat problem's name is its file's stem: it used to make the JSON output throw (exit 4).
  std::ifstream in(std::string(CPKIT_TEST_DATA_DIR) + "/siconos/lcp_deudeu.dat");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto file = write("bad\xff.dat", text);
  for (const char* command : {"lcp solve", "lcp enumerate", "lcp verify"}) {
    const auto r = run_cpkit(std::string(command) + " " + file + " --json");
    INFO(command << ": " << r.err);
    CHECK(r.code == 0);
    CHECK_NOTHROW(nlohmann::json::parse(r.out));
    CHECK_THAT(r.out, Contains("bad\xEF\xBF\xBD"));
  }
  const auto missing = run_cpkit("lcp solve '" + (scratch_dir() / "missing\xff.json").string() + "'");
  CHECK(missing.code == 2);
}
