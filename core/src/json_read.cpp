// parse_json_bounded: nlohmann's SAX parser feeding a bounded DOM builder (json_read.hpp), and
// messages that show a JSON value at bounded cost.
#include "cpkit/core/json_read.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

using nlohmann::json;

/// 1-based line of byte `position` in `text`.
int line_at(const std::string& text, std::size_t position) {
  const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(position, text.size()));
  return 1 + static_cast<int>(std::count(text.begin(), end, '\n'));
}

/// nlohmann's message without its code ("[json.exception.parse_error.101] "): the user's words.
std::string without_code(const std::string& what) {
  if (what.rfind("[json.exception.", 0) == 0) {
    const auto close = what.find("] ");
    if (close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

/// Builds the document as nlohmann's own DOM parser does, with the refusals of json_read.hpp.
class BoundedDomBuilder final : public json::json_sax_t {
 public:
  BoundedDomBuilder(json& root, const std::string& text, const std::string& origin,
                    const std::string& depth_hint)
      : root_(root), text_(text), origin_(origin), depth_hint_(depth_hint) {}

  bool null() override { return put(json(nullptr)) != nullptr; }
  bool boolean(bool b) override { return put(json(b)) != nullptr; }
  bool number_integer(number_integer_t v) override { return put(json(v)) != nullptr; }
  bool number_unsigned(number_unsigned_t v) override { return put(json(v)) != nullptr; }
  bool number_float(number_float_t v, const string_t& raw) override {
    double parsed = 0;
    if (const auto r = io_text::parse_real(raw, parsed); r == io_text::Number::kUnderflow)
      fail(io_text::describe(r, raw));
    return put(json(v)) != nullptr;
  }
  bool string(string_t& s) override { return put(json(std::move(s))) != nullptr; }
  bool binary(binary_t&) override { fail("binary values are not JSON text"); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool key(string_t& k) override {
    if (stack_.back()->contains(k)) fail("duplicate field \"" + io_text::quoted(k) + "\"");
    key_ = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& ex) override {
    position_ = position;
    if (ex.id == 406)  // out_of_range.406: a number beyond the range of double
      fail(io_text::describe(io_text::Number::kOverflow, last_token));
    fail("not valid JSON: " + io_text::valid_utf8(without_code(ex.what())));
  }
  /// Bytes the lexer has read so far (updated by CountingIterator): the position of messages.
  std::size_t position_ = 0;

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(origin_ + ":" + std::to_string(line_at(text_, position_)) + ": " + what);
  }
  /// Stores v where the parser is (root, next array element, or the current key).
  json* put(json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    json& slot = top[key_];
    slot = std::move(v);
    return &slot;
  }
  bool open(json&& container) {
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth)
      fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels" +
           (depth_hint_.empty() ? std::string() : " (" + depth_hint_ + ")"));
    stack_.push_back(put(std::move(container)));
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  json& root_;
  const std::string& text_;
  const std::string& origin_;
  const std::string& depth_hint_;
  std::vector<json*> stack_;  // open containers; a parent never grows while its child is open
  string_t key_;
};

/// A character iterator that records how far the lexer has read, so that the builder's
/// messages can name the line.
struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* at = nullptr;
  const char* begin = nullptr;
  std::size_t* consumed = nullptr;
  reference operator*() const { return *at; }
  CountingIterator& operator++() {
    ++at;
    *consumed = static_cast<std::size_t>(at - begin);
    return *this;
  }
  bool operator==(const CountingIterator& o) const { return at == o.at; }
  bool operator!=(const CountingIterator& o) const { return at != o.at; }
};

/// A scalar or a string (its first `room` bytes are enough) as the compact dump writes it.
std::string scalar_dump(const json& v, std::size_t room) {
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    return json(s.size() > room ? s.substr(0, room) : s).dump(-1, ' ', false,
                                                              json::error_handler_t::replace);
  }
  return v.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// Appends v's compact dump to `out` until `out` holds `limit` bytes. The recursion stops at
/// the limit, and at a depth no document can have once it has been through parse_json_bounded
/// (a deeper one built in code is shown as "...").
void dump_into(const json& v, std::string& out, std::size_t limit, int depth) {
  if (out.size() >= limit) return;
  if (depth > kMaxJsonDepth) {
    out += "...";
    return;
  }
  if (v.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() < limit; ++it) {
      if (!first) out += ',';
      first = false;
      out += scalar_dump(json(it.key()), limit - std::min(limit, out.size()));
      out += ':';
      dump_into(*it, out, limit, depth + 1);
    }
    out += '}';
  } else if (v.is_array()) {
    out += '[';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() < limit; ++it) {
      if (!first) out += ',';
      first = false;
      dump_into(*it, out, limit, depth + 1);
    }
    out += ']';
  } else {
    out += scalar_dump(v, limit - out.size());
  }
}

/// Length of `s` cut to at most `n` bytes, backed off to the start of a UTF-8 sequence.
std::size_t utf8_cut(const std::string& s, std::size_t n) {
  if (n >= s.size()) return s.size();
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  return n;
}

}  // namespace

json parse_json_bounded(const std::string& text, const std::string& origin,
                        const std::string& depth_hint) {
  json root;
  BoundedDomBuilder builder(root, text, origin, depth_hint);
  const char* b = text.data();
  const CountingIterator first{b, b, &builder.position_};
  const CountingIterator last{b + text.size(), b, &builder.position_};
  json::sax_parse(first, last, &builder);
  return root;
}

std::string json_dump_prefix(const json& v, std::size_t max_bytes) {
  std::string out;
  dump_into(v, out, max_bytes, 0);
  out.resize(utf8_cut(out, max_bytes));
  return out;
}

std::string json_excerpt(const json& v, std::size_t max_chars) {
  const std::size_t keep = max_chars < 3 ? 0 : max_chars - 3;
  // 4 bytes more than shown: even after backing off to a UTF-8 boundary (at most 3 bytes) a
  // prefix longer than max_chars tells that the dump is longer.
  std::string t = json_dump_prefix(v, max_chars + 4);
  if (t.size() <= max_chars) return t;
  t.resize(utf8_cut(t, keep));
  return t + "...";
}

}  // namespace cpkit
