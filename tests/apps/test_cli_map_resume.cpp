// `cpkit map ... --resume`: a grid map (N points or one point) stopped part-way (SIGTERM) and resumed equals
// the uninterrupted map byte for byte; no file that looks complete is left by the interrupted
// run; a checkpoint of another map is refused. Independent source: the uninterrupted run.
// Issue 24: chunks of another map on the same prefix are refused (item 9), the prefix is
// locked while a map runs (item 9), only regular checkpoint files of bounded size are read
// (item 10).
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "map_run_util.hpp"

namespace fs = std::filesystem;
using namespace cpkit::test;

namespace {
const std::string kSystem = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/coupled_grazing_points.json";
// About 2 s in Release on one core: long enough to interrupt after a few of its 64 chunks (128
// rows: 2 a chunk). The chunk run itself (stop after k chunks, resume, the merge) is tested
// deterministically and fast at the library level (tests/rate_problem/test_map_run.cpp); this
// test keeps what only the program does: SIGTERM, partial files, the files of a resumed run.
const std::string kMap = "map --system '" + kSystem +
                         "' --kind param-direction --param coupling --from 0 --to 1 --n 128 "
                         "--theta-n 720 --threads 1";
}  // namespace

TEST_CASE("an interrupted map resumed with --resume equals the uninterrupted map",
          "[cli][map][resume]") {
  struct Case {
    std::string name, map;
    std::vector<std::string> files;
  };
  // An N-point map, and a one-point parameter x parameter map (an exact direction map per
  // cell; about 2.5 s in Release on one core; 640 rows: 10 a chunk, 64 chunks).
  const std::vector<Case> cases = {
      {"system", kMap, {"_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"}},
      {"one_point",
       "map --preset fig5b --kind param-param --param mu --from 0.1 --to 4 --n 640 --param2 a12 "
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

namespace {
// A small N-point map (8 rows: 8 chunks) and the same map over another range: two different
// maps on one prefix.
const std::string kSmall = "map --system '" + kSystem +
                           "' --kind param-direction --param coupling --to 1 --n 8 --theta-n 12";
const std::string kMapA = kSmall + " --from 0";
const std::string kMapB = kSmall + " --from 0.5";

/// Runs `map` on prefix p so that every chunk is computed and kept in p.parts but the outputs
/// cannot be written (p_count.npy is a folder, the final rename fails): a checkpoint of the
/// whole map, made without timing or signals. Exit 2 (the output cannot be written).
void checkpoint_only(const std::string& map, const fs::path& p) {
  fs::remove_all(p.string() + ".parts");
  fs::remove_all(p.string() + "_count.npy");  // a file left by an earlier complete run
  fs::create_directories(p.string() + "_count.npy");
  const CliRun r = run_cpkit(map + " --out '" + p.string() + "'");
  INFO(r.err);
  REQUIRE(r.code == 2);
  REQUIRE(chunk_files(p.string() + ".parts") == 8);
  fs::remove_all(p.string() + "_count.npy");
}
}  // namespace

TEST_CASE("--resume refuses chunks written by another map on the same prefix (issue 24, item 9)",
          "[cli][map][resume]") {
  const fs::path dir = scratch_dir() / "resume_foreign";
  fs::create_directories(dir);
  const fs::path p = dir / "m", ref = dir / "ref";
  // the reference: map B uninterrupted
  REQUIRE(run_cpkit(kMapB + " --out '" + ref.string() + "'").code == 0);
  // chunk 3 of map A
  checkpoint_only(kMapA, p);
  const std::string a3 = file_bytes(p.string() + ".parts/chunk_3.bin");
  // map B's checkpoint resumed as it is: the uninterrupted map, byte for byte
  checkpoint_only(kMapB, p);
  CliRun r = run_cpkit(kMapB + " --out '" + p.string() + "' --resume --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["resumed_cells"] == 8 * 12);
  for (const char* f : {"_count.npy", "_pattern.npy", "_x.npy", "_theta.npy"})
    CHECK(file_bytes(ref.string() + f) == file_bytes(p.string() + f));
  // The reproducer: map A wrote its chunk 3 into map B's checkpoint (two runs on one
  // prefix); resuming B used to exit 0 with A's rows in it. Now: refused, naming the chunk.
  checkpoint_only(kMapB, p);
  {
    std::ofstream f(p.string() + ".parts/chunk_3.bin", std::ios::binary | std::ios::trunc);
    f << a3;
  }
  r = run_cpkit(kMapB + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("chunk_3.bin' was written by another map") != std::string::npos);
  CHECK(r.out.empty());
  CHECK_FALSE(fs::exists(p.string() + "_count.npy"));
  // The system's data are part of the identity: a checkpoint made with a system file that is
  // then edited (same path, same name, one compliance changed) is another map.
  const fs::path copy = dir / "copy.json";
  fs::copy_file(kSystem, copy, fs::copy_options::overwrite_existing);
  std::string mapB_copy = kMapB;
  mapB_copy.replace(mapB_copy.find(kSystem), kSystem.size(), copy.string());
  checkpoint_only(mapB_copy, p);
  std::string text = file_bytes(copy);
  const auto at = text.find("\"mu\"");
  REQUIRE(at != std::string::npos);
  text.replace(at, 4, "\"C_T\": 0.001, \"mu\"");
  {
    std::ofstream f(copy, std::ios::trunc);
    f << text;
  }
  r = run_cpkit(mapB_copy + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("system_data_fnv1a differs") != std::string::npos);
  // and another range of the same map names the field
  checkpoint_only(kMapA, p);
  r = run_cpkit(kMapB + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("(input.from differs: 0.0 there, 0.5 now)") != std::string::npos);
}

TEST_CASE("a map's --out prefix is locked while it runs (issue 24, item 9)", "[cli][map][resume]") {
  const fs::path dir = scratch_dir() / "resume_lock";
  fs::create_directories(dir);
  const fs::path p = dir / "m";
  const std::string lock = p.string() + ".lock";
  // Another process holds the lock (as a running map does): refused at once, naming the lock.
  {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
    REQUIRE(::write(fd, "4242\n", 5) == 5);
    for (const std::string& map :
         {kMapA, std::string("map --preset fig5b --kind param-direction --param mu --from 0.1 "
                             "--to 4 --n 4 --theta-n 8"),
          std::string("map --system '") + CPKIT_SOURCE_DIR +
              "/docs/examples/elliptic_point_3d.json' --kind sphere --n 2 --n2 4"}) {
      CAPTURE(map);
      const CliRun r = run_cpkit(map + " --out '" + p.string() + "'");
      CHECK(r.code == 2);
      CHECK(r.err.find("'" + lock + "' is locked by process 4242") != std::string::npos);
      CHECK_FALSE(fs::exists(p.string() + ".json"));
      CHECK_FALSE(fs::exists(p.string() + ".parts"));
    }
    ::close(fd);
  }
  // A lock file left by a run that has ended (no process holds it) does not block: the map
  // runs, and removes the lock file when it ends.
  REQUIRE(fs::exists(lock));
  const CliRun r = run_cpkit(kMapA + " --out '" + p.string() + "'");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(fs::exists(p.string() + ".json"));
  CHECK_FALSE(fs::exists(lock));
}

TEST_CASE("--resume reads only regular checkpoint files of bounded size (issue 24, item 10)",
          "[cli][map][resume]") {
  const fs::path dir = scratch_dir() / "resume_special";
  fs::create_directories(dir);
  const fs::path p = dir / "m";
  const std::string chunk = p.string() + ".parts/chunk_2.bin";
  struct Case {
    std::string name, make, message;
  };
  const std::vector<Case> cases = {
      // used to read without bound (17 GB in 30 s)
      {"/dev/zero", "ln -s /dev/zero '" + chunk + "'", "symbolic link"},
      // used to block forever
      {"fifo", "mkfifo '" + chunk + "'", "not a regular file"},
      // a sparse 17 GB file (no disk used): refused by its size, not read
      {"huge", "truncate -s 17G '" + chunk + "'", "more than the"},
      {"empty", ": > '" + chunk + "'", "not a chunk"}};
  for (const auto& c : cases) {
    CAPTURE(c.name);
    checkpoint_only(kMapA, p);
    fs::remove(chunk);
    REQUIRE(shell(c.make) == 0);
    const auto t0 = std::chrono::steady_clock::now();
    const CliRun r = run_cpkit(kMapA + " --out '" + p.string() + "' --resume");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(r.code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(seconds < 30);
    fs::remove(chunk);
  }
  // the manifest too (a FIFO there used to block the reader)
  checkpoint_only(kMapA, p);
  fs::remove(p.string() + ".parts/manifest.json");
  REQUIRE(shell("mkfifo '" + p.string() + ".parts/manifest.json'") == 0);
  CliRun r = run_cpkit(kMapA + " --out '" + p.string() + "' --resume");
  CHECK(r.code == 2);
  CHECK(r.err.find("not a regular file") != std::string::npos);
  // a manifest nested 10^6 deep (2 MB) is refused by its size; 10^5 deep by its depth, no crash
  for (const int depth : {1000000, 100000}) {
    CAPTURE(depth);
    fs::remove(p.string() + ".parts/manifest.json");
    {
      std::ofstream f(p.string() + ".parts/manifest.json");
      f << std::string(static_cast<std::size_t>(depth), '[') << std::string(static_cast<std::size_t>(depth), ']');
    }
    r = run_cpkit(kMapA + " --out '" + p.string() + "' --resume");
    CHECK(r.code == 2);
    CHECK(r.err.find(depth == 1000000 ? "more than the" : "nesting deeper than") != std::string::npos);
  }
}
