// `cpkit map ... --resume`: a grid map (N points or one point) stopped part-way (SIGTERM) and resumed equals
// the uninterrupted map byte for byte; no file that looks complete is left by the interrupted
// run; a checkpoint of another map is refused. Independent source: the uninterrupted run.
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "map_run_util.hpp"

namespace fs = std::filesystem;
using namespace cpkit::test;

namespace {
const std::string kSystem = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/coupled_grazing_points.json";
// About 4 s in Release on one core: long enough to interrupt after a few of its 64 chunks.
const std::string kMap = "map --system '" + kSystem +
                         "' --kind param-direction --param coupling --from 0 --to 1 --n 300 "
                         "--theta-n 720 --threads 1";
}  // namespace

TEST_CASE("an interrupted map resumed with --resume equals the uninterrupted map",
          "[cli][map][resume]") {
  struct Case {
    std::string name, map;
    std::vector<std::string> files;
  };
  // An N-point map, and a one-point parameter x parameter map (an exact direction map per
  // cell; about 5 s in Release on one core).
  const std::vector<Case> cases = {
      {"system", kMap, {"_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"}},
      {"one_point",
       "map --preset fig5b --kind param-param --param mu --from 0.1 --to 4 --n 1200 --param2 a12 "
       "--from2 -0.9 --to2 0.9 --n2 1200 --threads 1",
       {"_class.npy", "_min_count.npy", "_max_count.npy", "_types.npy", "_x.npy", "_y.npy",
        "_critical.csv"}}};
  for (const auto& c : cases) {
    CAPTURE(c.name);
    const fs::path dir = scratch_dir() / ("resume_" + c.name);
    fs::create_directories(dir);
    const fs::path ref = dir / "ref", cut = dir / "cut";
    REQUIRE(shell(cpkit_program() + " " + c.map + " --out '" + ref.string() + "' > /dev/null 2>&1") == 0);
    CHECK_FALSE(fs::exists(ref.string() + ".parts"));  // removed once the outputs are complete

    start_background(cpkit_program() + " " + c.map + " --out '" + cut.string() + "'", dir / "rc",
                     dir / "log");
    const fs::path parts = cut.string() + ".parts";
    REQUIRE(wait_for([&] { return chunk_files(parts) >= 3 || fs::exists(dir / "rc"); }, 300));
    REQUIRE_FALSE(fs::exists(dir / "rc"));  // still running: interrupt it
    // the cpkit process itself (not the shell that started it); SIGTERM, as a batch system
    // stops a job (a background job of a non-interactive shell ignores SIGINT)
    CHECK(shell("pkill -TERM -f '^" + std::string(CPKIT_BINARY_DIR) + "/apps/cpkit .*" +
                cut.string() + "'") == 0);
    REQUIRE(wait_for([&] { return fs::exists(dir / "rc"); }, 60));
    CHECK(slurp(dir / "rc") != "0\n");
    // nothing that looks complete: no summary, no final arrays
    CHECK_FALSE(fs::exists(cut.string() + ".json"));
    for (const auto& f : c.files) CHECK_FALSE(fs::exists(cut.string() + f));
    const int finished = chunk_files(parts);
    CHECK(finished >= 3);
    CHECK(finished < 60);  // of about 64 chunks

    const CliRun r = run_cpkit(c.map + " --out '" + cut.string() + "' --resume --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["resumed_cells"].get<long>() > 0);
    CHECK(j["rank_cells"][0].get<long>() + j["resumed_cells"].get<long>() ==
          j["cells"].get<long>());
    for (const auto& f : c.files) {
      CAPTURE(f);
      CHECK(file_bytes(ref.string() + f) == file_bytes(cut.string() + f));
    }
    CHECK(map_result(ref.string() + ".json") == map_result(cut.string() + ".json"));
    CHECK_FALSE(fs::exists(parts));
  }
}

TEST_CASE("--resume refuses a checkpoint of another map, and needs one", "[cli][map][resume]") {
  const fs::path dir = scratch_dir() / "resume_bad";
  fs::create_directories(dir);
  const fs::path p = dir / "m";
  const std::string small = "map --system '" + kSystem +
                            "' --kind param-direction --param coupling --from 0 --to 1 --n 8 --theta-n 12";
  // nothing to resume
  CliRun r = run_cpkit(small + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("nothing to resume") != std::string::npos);
  // a checkpoint of the map with --n 8; resuming it as --n 9 names the difference
  fs::create_directories(p.string() + ".parts");
  start_background(cpkit_program() + " " + small + " --out '" + p.string() + "'", dir / "rc", dir / "log");
  REQUIRE(wait_for([&] { return fs::exists(dir / "rc"); }, 120));
  REQUIRE(shell("mkdir -p '" + p.string() + ".parts' && echo '{\"kind\": \"param-direction\", "
                "\"input\": {\"n\": 8}}' > '" + p.string() + ".parts/manifest.json'") == 0);
  r = run_cpkit(small + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("different map") != std::string::npos);
  CHECK(r.out.empty());
  // --resume without --out, and for a direction map (one exact computation, no chunks)
  r = run_cpkit(small + " --resume");
  CHECK(r.code == 2);
  r = run_cpkit("map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("--resume") != std::string::npos);
  r = run_cpkit("map --preset fig5b --kind direction --out '" + (dir / "d").string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("--resume") != std::string::npos);
}
