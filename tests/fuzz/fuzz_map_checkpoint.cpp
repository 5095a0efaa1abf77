// Fuzz target: the map checkpoint readers of `cpkit map --resume` (apps/map_chunks.hpp): the
// manifest PREFIX.parts/manifest.json (parse_checkpoint_manifest) and a chunk file
// (parse_chunk, whose summary is JSON too). The corpus holds manifests and chunks written by
// cpkit map; an input is given to both readers. Any input must end in success or
// cpkit::InputError: every other exception, crash or failed invariant below is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_target.hpp"
#include "map_chunks.hpp"

using cpkit::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cpkit::fuzz::run_reader(data, size, [](const std::string& text) {
    const nlohmann::json m = cpkit::cli::parse_checkpoint_manifest(text, "manifest.json");
    require(m.is_object(), "a manifest is a JSON object");
  });
  cpkit::fuzz::run_reader(data, size, [size](const std::string& bytes) {
    const cpkit::cli::MapChunk c = cpkit::cli::parse_chunk(bytes);
    std::size_t held = 0;
    for (const auto& a : c.arrays) held += a.size();
    require(held <= size, "a chunk holds no more array bytes than the file");
    require(c.arrays.size() <= 64, "at most 64 arrays");
  });
  return 0;
}
