#pragma once
// Text helpers shared by the problem-file readers (io_json.cpp, io_dat.cpp,
// io_matrix_market.cpp): bounded file reading, strict number parsing, tokens with line numbers,
// and UTF-8 repair for text that ends up in names, notes and messages. Internal to cpkit_core.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/core/number_text.hpp"

namespace cpkit::io_text {

/// Largest problem file read (bytes). Larger files are rejected before they are read whole.
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 31;  // 2 GiB

/// The whole file. InputError when it cannot be opened, is a directory or a device (a FIFO is
/// allowed, e.g. `<(...)`), or is larger than kMaxFileBytes.
std::string read_text(const std::string& path);

/// `s` with every byte that is not part of a well-formed UTF-8 sequence replaced by U+FFFD, so
/// that file names and free text can be printed as JSON and in messages.
std::string valid_utf8(std::string_view s);

/// A token for a message: valid UTF-8, at most 40 bytes (longer ones end with "...").
std::string quoted(std::string_view token);

/// The strict decimal numbers of number_text.hpp, under the names the readers use.
using Number = NumberText;
inline Number parse_real(std::string_view token, double& value) {
  return parse_decimal(token, value);
}
inline std::string describe(Number outcome, std::string_view token) {
  return describe_number(outcome, token);
}

/// Parses the whole token as a decimal integer (optional sign). False when it is not an integer
/// or does not fit in int64.
bool parse_integer(std::string_view token, std::int64_t& value);

/// A whitespace-separated token and its 1-based line.
struct Token {
  std::string_view text;
  int line = 0;
  std::size_t offset = 0;  ///< byte offset of the token in the text
};
/// Splits `text` at whitespace (space, tab, CR, LF, VT, FF). The views point into `text`.
std::vector<Token> tokenize(std::string_view text);

}  // namespace cpkit::io_text
