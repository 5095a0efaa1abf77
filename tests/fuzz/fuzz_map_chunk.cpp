// Fuzz target: the files of a map checkpoint PREFIX.parts/ (rate_problem/maps/map_run.hpp) that
// `cpkit map --resume` reads: chunk files (parse_chunk) and the manifest
// (parse_checkpoint_json). Any input must end in success or cpkit::InputError; an accepted
// chunk must survive serialize -> parse unchanged (issue 24, items 10 and 15).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_target.hpp"
#include "cpkit/rate_problem/maps/map_run.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using cpkit::fuzz::require;
  cpkit::fuzz::run_reader(data, size, [](const std::string& bytes) {
    if (bytes.compare(0, 7, "cpkchnk") == 0) {
      const cpkit::rate::MapChunk c = cpkit::rate::parse_chunk(bytes);
      const cpkit::rate::MapChunk d = cpkit::rate::parse_chunk(cpkit::rate::serialize_chunk(c));
      require(d.map_id == c.map_id && d.index == c.index && d.row_begin == c.row_begin &&
                  d.row_end == c.row_end && d.rank == c.rank,
              "chunk header changed by a round trip");
      require(d.summary == c.summary && d.arrays == c.arrays, "chunk data changed by a round trip");
      require(c.arrays.size() <= 64, "more arrays than a chunk holds");
    } else {
      const nlohmann::json j = cpkit::rate::parse_checkpoint_json(bytes, "manifest");
      (void)j.dump();  // the depth is bounded: dump() cannot exhaust the stack
    }
  });
  return 0;
}
