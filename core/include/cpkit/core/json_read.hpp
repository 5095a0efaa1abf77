#pragma once
/// \file json_read.hpp
/// The one JSON parser of every cpkit input (LCP problem files, system files of 2-D and 3-D
/// points, the `cpkit simulate` config, map checkpoint manifests and chunk summaries), so that
/// every reader has the same limits and the same messages (docs/file_formats.md):
/// - nesting deeper than kMaxJsonDepth is refused while parsing, before the document exists
///   (nlohmann's destructor and dump() recurse: 10^6 nested brackets would overflow the stack);
/// - a number beyond the range of double (`1e400`) is refused, and so is a non-zero literal
///   below the smallest subnormal (`1e-400`, which would silently become 0);
/// - a duplicate key is refused (which of its values would be meant?);
/// - syntax errors and invalid UTF-8 are refused.
/// Every refusal is a cpkit::InputError "origin:line: what".
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace cpkit {

/// Deepest JSON nesting read ({"M": [[1]]} has depth 3); deeper input is an InputError.
inline constexpr int kMaxJsonDepth = 64;

/// `text` as a JSON document, with the limits above. `depth_hint` completes the depth message,
/// e.g. "an LCP file needs 3: {\"M\": [[...]]}".
nlohmann::json parse_json_bounded(const std::string& text, const std::string& origin,
                                  const std::string& depth_hint = {});

/// The first `max_bytes` bytes of `v`'s compact dump (all of it when shorter), invalid UTF-8
/// replaced. The cost is bounded by `max_bytes`, not by the size or depth of `v`: a message can
/// show any value (a 1 MB array, a document built in code 10^6 levels deep).
std::string json_dump_prefix(const nlohmann::json& v, std::size_t max_bytes);

/// `v` for a message: its compact dump when at most `max_chars` long, else its first
/// max_chars - 3 bytes and "..." (cost bounded as json_dump_prefix).
std::string json_excerpt(const nlohmann::json& v, std::size_t max_chars = 40);

}  // namespace cpkit
