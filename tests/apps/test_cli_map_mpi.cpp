// `mpirun -np 2 cpkit map ...`: the distributed grid maps (one-point and N-point) write what
// one process writes (the .npy files byte for byte, the CSV, the JSON apart from run figures); the summary
// records the ranks and the cells each computed; a rank killed mid-run fails the job with no
// complete-looking output, and --resume finishes it; what cannot be distributed is refused.
// bench_robustness spreads its problems the same way. Independent source: the single-process
// run. Exits 77 (skipped, reason printed) when this build has no MPI (CMake CPKIT_WITH_MPI=OFF)
// or mpirun is missing (a failure where peers are required, peer_skip.hpp).
#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>
#include <string>

#include "cli_runner.hpp"
#include "map_run_util.hpp"
#include "peer_skip.hpp"

namespace fs = std::filesystem;
using namespace cpkit::test;

namespace {
const std::string kSystem = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/coupled_grazing_points.json";

std::string mpirun(int ranks) {
  // --oversubscribe: the CI machine has 2 cores; as root (CI), Open MPI wants it said.
  return "mpirun -np " + std::to_string(ranks) + " --oversubscribe" +
         (geteuid() == 0 ? " --allow-run-as-root" : "") + " " + cpkit_program() + " ";
}

struct SkipUnlessMpi {
  SkipUnlessMpi() {
#ifndef CPKIT_TEST_WITH_MPI
    // A build configured without MPI (as scripts/run-sanitizers.sh is, on purpose) has nothing
    // to test here: skipped even where peers are required (scripts/run-tests.sh turns MPI on).
    std::cout << "skipped: this build has no MPI (configure with -DCPKIT_WITH_MPI=ON; "
                 "scripts/run-tests.sh does)\n";
    std::exit(77);
#endif
    if (shell("command -v mpirun > /dev/null 2>&1") != 0)
      skip_program("mpirun not found (Debian: apt-get install openmpi-bin)");
  }
} skip_unless_mpi;
}  // namespace

TEST_CASE("mpirun -np 2: the distributed maps equal the single-process maps", "[cli][map][mpi]") {
  const fs::path dir = scratch_dir() / "mpi";
  fs::create_directories(dir);
  // Fig. 5b as an N = 1 system: the one-point model through the N-point engine
  const fs::path one_point = dir / "fig5b.json";
  std::ofstream(one_point) << R"({"A": [[1, 2], [2, 5]], "points": [{"state": "b", "mu": 1}]})";
  const std::string sys = "map --system '" + kSystem + "' ";
  struct Case {
    std::string name, map;
    std::vector<std::string> files;
  };
  const std::vector<Case> cases = {
      {"pd", sys + "--kind param-direction --param coupling --from 0 --to 1 --n 70 --theta-n 180",
       {"_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"}},
      {"pp", sys + "--kind param-param --param coupling --from 0 --to 1 --n 12 --param2 mu "
                   "--from2 0.2 --to2 2 --n2 6",
       {"_class.npy", "_min_count.npy", "_max_count.npy", "_pattern.npy", "_x.npy", "_y.npy"}},
      {"pp_csv", sys + "--kind param-param --param mu@1 --from 0.5 --to 9 --n 9 --param2 mu@2 "
                       "--from2 0.5 --to2 3 --n2 5 --format csv",
       {".csv"}},
      {"n1", "map --system '" + one_point.string() +
                 "' --kind param-direction --param mu --from 0.1 --to 4 --n 90 --theta-n 360",
       {"_count.npy", "_pattern.npy"}},
      // one-point maps (the closed forms; the second rank's share depends on timing)
      {"fig5b_pd", "map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 "
                   "--n 400 --theta-n 720",
       {"_count.npy", "_types.npy", "_x.npy", "_theta.npy", "_critical.csv"}},
      {"fig5b_pp", "map --preset fig5b --kind param-param --param mu --from 0.1 --to 4 --n 90 "
                   "--param2 a12 --from2 -0.9 --to2 0.9 --n2 70",
       {"_class.npy", "_min_count.npy", "_max_count.npy", "_types.npy", "_x.npy", "_y.npy",
        "_critical.csv"}},
      {"state_d_csv", "map --preset state-d --kind param-direction --param mu --from 0.1 --to 4 "
                      "--n 60 --theta-n 90 --method analytic --format csv",
       {".csv", "_critical.csv"}},
      {"state_d_pp_csv", "map --preset state-d-mu-kappa --kind param-param --n 30 --n2 20 "
                         "--method analytic --format csv",
       {".csv", "_critical.csv"}}};
  for (const auto& c : cases) {
    CAPTURE(c.name);
    const std::string map = c.map + " --threads 1";
    const fs::path one = dir / (c.name + "_1"), two = dir / (c.name + "_2");
    const int rc1 = shell(cpkit_program() + " " + map + " --out '" + one.string() + "' > /dev/null 2> '" +
                          dir.string() + "/err1.txt'");
    INFO(slurp(dir / "err1.txt"));
    REQUIRE(rc1 == 0);
    const int rc = shell(mpirun(2) + map + " --out '" + two.string() + "' > '" + dir.string() +
                         "/out.txt' 2> '" + dir.string() + "/err.txt'");
    INFO(slurp(dir / "err.txt"));
    REQUIRE(rc == 0);
    for (const auto& f : c.files) {
      CAPTURE(f);
      REQUIRE(fs::exists(one.string() + f));
      CHECK(file_bytes(one.string() + f) == file_bytes(two.string() + f));
    }
    CHECK(map_result(one.string() + ".json") == map_result(two.string() + ".json"));
    const auto j = nlohmann::json::parse(file_bytes(two.string() + ".json"));
    CHECK(j["ranks"] == 2);
    REQUIRE(j["rank_cells"].size() == 2);
    CHECK(j["rank_cells"][0].get<long>() + j["rank_cells"][1].get<long>() == j["cells"].get<long>());
    if (c.name.rfind("fig5b", 0) != 0 && c.name.rfind("state_d", 0) != 0)
      CHECK(j["rank_cells"][1].get<long>() > 0);  // the second rank took chunks
    CHECK_FALSE(fs::exists(two.string() + ".parts"));
  }
}

TEST_CASE("mpirun: a killed rank fails the job without complete-looking files; --resume finishes it",
          "[cli][map][mpi]") {
  const fs::path dir = scratch_dir() / "mpi_kill";
  fs::create_directories(dir);
  const std::string map = "map --system '" + kSystem +
                          "' --kind param-direction --param coupling --from 0 --to 1 --n 300 "
                          "--theta-n 720 --threads 1";
  const fs::path ref = dir / "ref", cut = dir / "cut";
  REQUIRE(shell(cpkit_program() + " " + map + " --out '" + ref.string() + "' > /dev/null 2>&1") == 0);
  start_background(mpirun(2) + map + " --out '" + cut.string() + "'", dir / "rc", dir / "log");
  const fs::path parts = cut.string() + ".parts";
  REQUIRE(wait_for([&] { return chunk_files(parts) >= 3 || fs::exists(dir / "rc"); }, 300));
  REQUIRE_FALSE(fs::exists(dir / "rc"));
  // rank 1 of the job: the cpkit process whose environment says so
  const int killed = shell("for p in $(pgrep -f '" + cut.string() + "'); do "
                           "if tr '\\0' '\\n' < /proc/$p/environ 2>/dev/null | grep -qx "
                           "OMPI_COMM_WORLD_RANK=1; then kill -9 $p; exit 0; fi; done; exit 1");
  REQUIRE(killed == 0);
  REQUIRE(wait_for([&] { return fs::exists(dir / "rc"); }, 120));
  INFO(slurp(dir / "log"));
  CHECK(slurp(dir / "rc") != "0\n");
  for (const char* f : {".json", "_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"})
    CHECK_FALSE(fs::exists(cut.string() + f));
  // the finished chunks are kept; one process completes the map
  const CliRun r = run_cpkit(map + " --out '" + cut.string() + "' --resume");
  INFO(r.err);
  REQUIRE(r.code == 0);
  for (const char* f : {"_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"})
    CHECK(file_bytes(ref.string() + f) == file_bytes(cut.string() + f));
  CHECK(map_result(ref.string() + ".json") == map_result(cut.string() + ".json"));
}

TEST_CASE("mpirun: bad input is reported once, by rank 0, exit 2", "[cli][map][mpi]") {
  const fs::path dir = scratch_dir() / "mpi_bad";
  fs::create_directories(dir);
  const int rc = shell(mpirun(2) + "map --system '" + kSystem + "' --kind param-direction --param "
                       "nonsense --from 0 --to 1 --out '" + (dir / "m").string() + "' > '" +
                       (dir / "out.txt").string() + "' 2> '" + (dir / "err.txt").string() + "'");
  const std::string err = slurp(dir / "err.txt");
  INFO(err);
  CHECK(rc == 2);
  const auto first = err.find("unknown map parameter 'nonsense'");
  REQUIRE(first != std::string::npos);
  CHECK(err.find("unknown map parameter 'nonsense'", first + 1) == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "m.json"));
}

TEST_CASE("mpirun: what is not distributed is refused on every rank, exit 2", "[cli][map][mpi]") {
  const fs::path dir = scratch_dir() / "mpi_refuse";
  fs::create_directories(dir);
  for (const std::string& args :
       {std::string("map --preset fig5b --kind direction"),
        "map --system '" + kSystem + "' --kind direction",
        std::string("rate --state b --a11 1 --a12 0.5 --a22 1 --mu 3 --dF 1 1")}) {
    CAPTURE(args);
    const int rc = shell(mpirun(2) + args + " > '" + dir.string() + "/out.txt' 2> '" +
                         dir.string() + "/err.txt'");
    const std::string err = slurp(dir / "err.txt");
    INFO(err);
    CHECK(rc == 2);
    CHECK(err.find("mpirun") != std::string::npos);
    CHECK(slurp(dir / "out.txt").empty());
  }
}

TEST_CASE("mpirun -np 2 bench_robustness --quick: the same verdicts as one process",
          "[cli][mpi][bench]") {
  const fs::path bench = fs::path(CPKIT_BINARY_DIR) / "bench" / "bench_robustness";
  if (!fs::exists(bench)) {
    CPKIT_SKIP_CHECK(bench << " is not built (CPKIT_BUILD_BENCH=OFF)");
    return;
  }
  const fs::path dir = scratch_dir() / "robustness";
  const std::string b = "'" + bench.string() + "' ";
  REQUIRE(shell(b + "'" + (dir / "one").string() + "' --quick > /dev/null 2>&1") == 0);
  const std::string launcher = mpirun(2);  // "mpirun ... 'cpkit' ": use its launcher part only
  const std::string mpi = launcher.substr(0, launcher.find(cpkit_program()));
  REQUIRE(shell(mpi + b + "'" + (dir / "two").string() + "' --quick > '" + (dir / "two.txt").string() +
                "' 2>&1") == 0);
  CHECK(slurp(dir / "two.txt").find("processes: 2") != std::string::npos);
  // every column but the time (9th) is the same, row for row
  auto without_times = [](const fs::path& csv) {
    std::istringstream in(slurp(csv));
    std::string out;
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> f;
      std::istringstream ls(line);
      for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
      if (f.size() > 8) f.erase(f.begin() + 8);
      for (const auto& x : f) out += x + ",";
      out += "\n";
    }
    return out;
  };
  const std::string one = without_times(dir / "one" / "results.csv");
  CHECK(one.size() > 1000);
  CHECK(one == without_times(dir / "two" / "results.csv"));
}
