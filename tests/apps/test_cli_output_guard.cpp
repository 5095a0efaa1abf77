// Issue 24, item 8: no command overwrites its input. `cpkit map --system sys.json --out sys`
// used to replace sys.json with the map's summary; `cpkit simulate` could write its series or
// summary over its config or system file. Every output that is an input (the same file by
// device and inode: another spelling, a hard link; or the same path not yet written) is refused
// with exit 2 before anything is written, and the input is unchanged byte for byte.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace cpkit::test;

namespace {
const std::string kExamples = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/";

/// A copy of an example file in the scratch folder `dir`, under `name`.
fs::path copy_example(const std::string& example, const fs::path& dir, const std::string& name) {
  fs::create_directories(dir);
  const fs::path p = dir / name;
  fs::copy_file(kExamples + example, p, fs::copy_options::overwrite_existing);
  return p;
}

/// Runs `args`; requires exit 2 with `message` on stderr, nothing on stdout, and `input`
/// unchanged.
void require_refused(const std::string& args, const fs::path& input, const std::string& message) {
  const std::string before = slurp(input);
  const CliRun r = run_cpkit(args);
  CAPTURE(args, r.err);
  CHECK(r.code == 2);
  CHECK(r.err.find(message) != std::string::npos);
  CHECK(r.out.empty());
  CHECK(slurp(input) == before);
}
}  // namespace

TEST_CASE("map refuses an --out prefix whose files are its --system input", "[cli][map]") {
  const fs::path dir = scratch_dir() / "guard_map";
  const fs::path sys = copy_example("coupled_grazing_points.json", dir, "sys.json");
  const std::string in = " --system '" + sys.string() + "'";
  // The reproducer (direction map: PREFIX.json is the summary), and the grid maps.
  for (const std::string& kind :
       {std::string(" --kind direction"),
        std::string(" --kind param-direction --param coupling --from 0 --to 1 --n 4 --theta-n 8"),
        std::string(" --kind param-param --param mu@1 --from 1 --to 8 --n 3 --param2 mu@2 "
                    "--from2 1 --to2 4 --n2 3")})
    require_refused("map" + in + kind + " --out '" + (dir / "sys").string() + "'", sys,
                    "is the input file");
  // Another spelling of the same path, and a hard link to it (same device and inode).
  require_refused("map" + in + " --out '" + (dir / "." / ".." / dir.filename() / "sys").string() + "'",
                  sys, "is the input file");
  fs::create_hard_link(sys, dir / "link.json");
  require_refused("map" + in + " --out '" + (dir / "link").string() + "'", sys,
                  "is the input file");
  // An input inside the checkpoint folder PREFIX.parts (replaced by a map).
  fs::create_directories(dir / "m.parts");
  const fs::path inner = copy_example("coupled_grazing_points.json", dir / "m.parts", "sys.json");
  require_refused("map --system '" + inner.string() +
                      "' --kind param-direction --param coupling --from 0 --to 1 --n 4 --theta-n 8"
                      " --out '" + (dir / "m").string() + "'",
                  inner, "lies in the checkpoint folder");
  // 3-D sphere map (PREFIX.json is the summary).
  const fs::path sys3 = copy_example("elliptic_point_3d.json", dir, "e.json");
  require_refused("map --system '" + sys3.string() + "' --kind sphere --n 2 --n2 4 --out '" +
                      (dir / "e").string() + "'",
                  sys3, "is the input file");
  // A different prefix in the same folder is fine (the check is not over-broad).
  const CliRun ok = run_cpkit("map" + in + " --kind direction --out '" + (dir / "sys_map").string() + "'");
  CHECK(ok.code == 0);
  CHECK(fs::exists(dir / "sys_map.json"));
}

TEST_CASE("simulate refuses outputs that are its inputs or each other", "[cli][simulate]") {
  const fs::path dir = scratch_dir() / "guard_simulate";
  const fs::path cfg = copy_example("fretting.json", dir, "cfg.json");
  const std::string run = "simulate --config '" + cfg.string() + "' --cycles 1 --steps-per-cycle 10";
  require_refused(run + " --summary '" + cfg.string() + "'", cfg, "is the input file");
  require_refused(run + " --csv '" + cfg.string() + "'", cfg, "is the input file");
  require_refused(run + " --plot '" + (dir / "cfg").string() + "'", cfg, "is the input file");
  require_refused(run + " --csv '" + (dir / "x").string() + "' --summary '" +
                      (dir / "." / "x").string() + "'",
                  cfg, "two outputs are the same file");
  CHECK_FALSE(fs::exists(dir / "x"));
  // The config's own output paths are checked too: a config whose "csv" is itself.
  {
    std::string text = slurp(cfg);
    const auto at = text.find("out/fretting.csv");
    REQUIRE(at != std::string::npos);
    text.replace(at, std::string("out/fretting.csv").size(), "self.json");
    std::ofstream(dir / "self.json") << text;
  }
  require_refused("simulate --config '" + (dir / "self.json").string() + "'", dir / "self.json",
                  "is the input file");
  // 3-D (dim 3 system) and N-point systems.
  const fs::path p3 = copy_example("fretting_point_3d.json", dir, "p3.json");
  require_refused("simulate --system '" + p3.string() + "' --orbit 1 0.5 --summary '" +
                      p3.string() + "'",
                  p3, "is the input file");
  const fs::path sys = copy_example("two_point_system.json", dir, "two.json");
  require_refused("simulate --system '" + sys.string() + "' --csv '" + sys.string() + "'", sys,
                  "is the input file");
}

// Issue 34, F4-08: `cpkit fc bench FILE... --out PREFIX` wrote PREFIX.csv (and PREFIX.png) over
// a problem file named like an output. The commands of the finding's README, on a Siconos file
// copied under those names (readers choose the format by content): each refused, exit 2, naming
// the input and the output, and every input intact.
TEST_CASE("fc bench refuses an --out prefix whose files are its problem files", "[cli][fc]") {
  const fs::path dir = scratch_dir() / "guard_fc_bench";
  fs::create_directories(dir);
  const fs::path problem = fs::path(CPKIT_TEST_DATA_DIR) / "fclib/local/FC3D_Example1.dat";
  const auto copy = [&](const std::string& name) {
    fs::copy_file(problem, dir / name, fs::copy_options::overwrite_existing);
    return dir / name;
  };
  const auto refused = [&](const fs::path& input, const std::string& out, const std::string& args,
                           const std::string& output) {
    require_refused("fc bench '" + input.string() + "' --out '" + out + "' --solvers nsgs" + args,
                    input, "is the input file '" + input.string() + "'");
    const CliRun r = run_cpkit("fc bench '" + input.string() + "' --out '" + out +
                               "' --solvers nsgs" + args);
    CHECK(r.err.find("the output '" + output + "'") != std::string::npos);  // both named
    CHECK_FALSE(fs::exists(out + ".lock"));  // nothing written
  };
  // PREFIX.csv is the input.
  const fs::path in = copy("in.csv");
  refused(in, (dir / "in").string(), " --no-plot", (dir / "in").string() + ".csv");
  // PREFIX.csv is a symbolic link to the input.
  const fs::path a = copy("a.dat");
  fs::create_symlink(a, dir / "link.csv");
  refused(a, (dir / "link").string(), " --no-plot", (dir / "link").string() + ".csv");
  // PREFIX.png is the input (with the plot).
  const fs::path b = copy("b.png");
  refused(b, (dir / "b").string(), "", (dir / "b").string() + ".png");
  // The table's temporary name too.
  const fs::path t = copy("t.csv.partial");
  refused(t, (dir / "t").string(), " --no-plot", (dir / "t").string() + ".csv.partial");
  // A different prefix beside them is fine (the check is not over-broad).
  const CliRun ok = run_cpkit("fc bench '" + in.string() + "' '" + a.string() + "' --out '" +
                              (dir / "bench").string() + "' --solvers nsgs --no-plot");
  INFO(ok.err);
  CHECK(ok.code == 0);
  CHECK(fs::exists(dir / "bench.csv"));
}
