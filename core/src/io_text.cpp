#include "io_text.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "cpkit/core/errors.hpp"

namespace cpkit::io_text {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool in_range(unsigned char c, unsigned lo, unsigned hi) { return c >= lo && c <= hi; }

/// Length of the well-formed UTF-8 sequence starting at s[i] (Unicode 15, Table 3-7), or 0.
std::size_t utf8_sequence(std::string_view s, std::size_t i) {
  const auto at = [&](std::size_t k) -> unsigned char {
    return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0;
  };
  const unsigned char c = at(0);
  if (c < 0x80) return 1;
  auto cont = [&](std::size_t k) { return in_range(at(k), 0x80, 0xBF); };
  if (in_range(c, 0xC2, 0xDF)) return cont(1) ? 2 : 0;
  if (c == 0xE0) return in_range(at(1), 0xA0, 0xBF) && cont(2) ? 3 : 0;
  if (in_range(c, 0xE1, 0xEC) || in_range(c, 0xEE, 0xEF)) return cont(1) && cont(2) ? 3 : 0;
  if (c == 0xED) return in_range(at(1), 0x80, 0x9F) && cont(2) ? 3 : 0;  // no surrogates
  if (c == 0xF0) return in_range(at(1), 0x90, 0xBF) && cont(2) && cont(3) ? 4 : 0;
  if (in_range(c, 0xF1, 0xF3)) return cont(1) && cont(2) && cont(3) ? 4 : 0;
  if (c == 0xF4) return in_range(at(1), 0x80, 0x8F) && cont(2) && cont(3) ? 4 : 0;
  return 0;
}

}  // namespace

std::string read_text(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string shown = valid_utf8(path);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(shown + ": cannot open file (no such file)");
  if (fs::is_directory(st)) throw InputError(shown + ": is a directory, not a problem file");
  if (!fs::is_regular_file(st) && !fs::is_fifo(st))
    throw InputError(shown + ": not a regular file (devices and sockets are not read)");
  if (fs::is_regular_file(st)) {
    const auto size = fs::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
      throw InputError(shown + ": file of " + std::to_string(size) + " bytes is larger than the " +
                       std::to_string(kMaxFileBytes) + "-byte limit of the readers");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(shown + ": cannot open file");
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes)  // a FIFO has no size to check up front
      throw InputError(shown + ": more than " + std::to_string(kMaxFileBytes) +
                       " bytes (the limit of the readers)");
  }
  if (in.bad()) throw InputError(shown + ": read error");
  return text;
}

std::string valid_utf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t len = utf8_sequence(s, i);
    if (len == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
      ++i;
    } else {
      out.append(s.substr(i, len));
      i += len;
    }
  }
  return out;
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  if (token.size() <= kMax) return valid_utf8(token);
  return valid_utf8(token.substr(0, kMax)) + "...";
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  if (token.size() != t.size() && (t.empty() || t.front() == '-')) return false;
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size()) return false;
  value = v;
  return true;
}

std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    if (is_space(text[i])) {
      if (text[i] == '\n') ++line;
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    out.push_back({text.substr(start, i - start), line, start});
  }
  return out;
}

}  // namespace cpkit::io_text
