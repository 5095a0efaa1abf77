// JSON problem files: {"M": [[...], ...], "q": [...]} or {"M_mtx": ..., "q_mtx": ...}.
// Two readers with one meaning: the fast one (simdjson, for the dense files of every size that
// users time) answers every well-formed dense file it can fully vouch for; anything else - an
// error, Matrix Market fields, a number that might underflow - goes to the reference reader
// (parse_json_bounded, json_read.hpp, with the checks below), which gives every message.
#include <simdjson.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/json_read.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A JSON value for a message: its dump, shortened (at bounded cost, whatever its size).
std::string shown(const json& v) { return io_text::quoted(json_dump_prefix(v, 41)); }

/// v as a double; `where()` names it in the message (made only on failure: loops stay cheap).
template <class Where>
double json_number(const json& v, const std::string& origin, const Where& where) {
  if (!v.is_number())
    throw InputError(origin + ": " + where() + " is not a number (got " + shown(v) + ")");
  return v.get<double>();  // finite: the builder refused overflow; JSON has no nan/inf
}

const std::array<const char*, 9> kKnownFields = {"M", "q", "M_mtx", "q_mtx", "name",
                                                 "note", "source", "expected", "n"};

void check_fields(const json& j, const std::string& origin) {
  for (const auto& item : j.items()) {
    const bool known = std::any_of(kKnownFields.begin(), kKnownFields.end(),
                                   [&](const char* k) { return item.key() == k; });
    if (!known)
      throw InputError(origin + ": unknown field \"" + io_text::quoted(item.key()) +
                       "\" (an LCP file has \"M\" and \"q\", or \"M_mtx\" and \"q_mtx\"; optional "
                       "\"n\", \"name\", \"note\", \"source\", \"expected\")");
  }
  for (const char* k : {"name", "note"})
    if (j.contains(k) && !j[k].is_string())
      throw InputError(origin + ": field \"" + k + "\" must be a string (got " + shown(j[k]) + ")");
  const bool dense = j.contains("M") || j.contains("q");
  const bool files = j.contains("M_mtx") || j.contains("q_mtx");
  if (dense && files)
    throw InputError(origin + ": give either \"M\" and \"q\" or \"M_mtx\" and \"q_mtx\", not both");
}

/// The optional "n" (the size, as many tools write it): a whole number equal to the size of M.
void check_size_field(const json& jn, Eigen::Index size, const std::string& origin) {
  const bool whole = jn.is_number_integer() || jn.is_number_unsigned() ||
                     (jn.is_number_float() && jn.get<double>() == std::floor(jn.get<double>()));
  if (!whole || jn.get<double>() < 0)
    throw InputError(origin + ": field \"n\" must be the problem's size, a whole number (got " +
                     shown(jn) + ")");
  if (jn.get<double>() != static_cast<double>(size))
    throw InputError(origin + ": field \"n\" is " + shown(jn) + " but M is " +
                     std::to_string(size) + " x " + std::to_string(size));
}

LcpProblem from_matrix_market_fields(const json& j, const std::string& origin) {
  if (!j.contains("M_mtx") || !j.contains("q_mtx") || !j["M_mtx"].is_string() ||
      !j["q_mtx"].is_string())
    throw InputError(origin + ": \"M_mtx\" and \"q_mtx\" must both be file names");
  const auto base = fs::path(origin).parent_path();
  return read_lcp_matrix_market((base / j["M_mtx"].get<std::string>()).string(),
                                (base / j["q_mtx"].get<std::string>()).string());
}

LcpProblem from_dense_fields(const json& j, const std::string& origin) {
  if (!j.contains("M")) throw InputError(origin + ": missing field \"M\"");
  if (!j.contains("q")) throw InputError(origin + ": missing field \"q\"");
  const json& jm = j["M"];
  const json& jq = j["q"];
  if (!jq.is_array()) throw InputError(origin + ": field \"q\" must be an array of numbers");
  if (!jm.is_array()) throw InputError(origin + ": field \"M\" must be an array of rows");
  const std::size_t n = jq.size();
  if (n == 0) throw InputError(origin + ": field \"q\" is empty");
  if (jm.size() != n)
    throw InputError(origin + ": field \"M\" has " + std::to_string(jm.size()) +
                     " rows but \"q\" has " + std::to_string(n) + " entries");
  // Every row is checked before M is allocated: the n x n entries must be in the file.
  for (std::size_t i = 0; i < n; ++i)
    if (!jm[i].is_array() || jm[i].size() != n)
      throw InputError(origin + ": M row " + std::to_string(i) + " must be an array of " +
                       std::to_string(n) + " numbers");
  LcpProblem p;
  const auto ni = static_cast<Eigen::Index>(n);
  p.M.resize(ni, ni);
  p.q.resize(ni);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k)
      p.M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = json_number(
          jm[i][k], origin, [&] { return "M[" + std::to_string(i) + "][" + std::to_string(k) + "]"; });
    p.q[static_cast<Eigen::Index>(i)] =
        json_number(jq[i], origin, [&] { return "q[" + std::to_string(i) + "]"; });
  }
  return p;
}

/// True when some number in `text` might be non-zero yet round to 0 in double: an exponent of
/// -150 or below, or a run of 150 zeros (a non-zero decimal below 2^-1074 ~ 4.9e-324 needs
/// leading zeros plus exponent digits of at least 323). simdjson would round it to 0 silently;
/// the reference reader refuses it with a message. Conservative: a string holding such text
/// also sends the file to the reference reader.
bool may_underflow(const std::string& text) {
  constexpr int kLimit = 150;
  const std::string zeros(kLimit, '0');
  if (memmem(text.data(), text.size(), zeros.data(), zeros.size()) != nullptr) return true;
  // every '-' preceded by an exponent mark (memchr: the scan runs at memory speed)
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  for (const char* at = begin;
       (at = static_cast<const char*>(std::memchr(at, '-', size_t(end - at)))) != nullptr; ++at) {
    if (at == begin || (at[-1] != 'e' && at[-1] != 'E')) continue;
    int exponent = 0;
    for (const char* d = at + 1; d < end && *d >= '0' && *d <= '9'; ++d) {
      exponent = exponent * 10 + (*d - '0');
      if (exponent >= kLimit) return true;
    }
  }
  return false;
}

/// No object anywhere in `e` has two equal keys (the reference reader refuses those).
bool distinct_keys(const simdjson::dom::element& e) {
  simdjson::dom::object obj;
  simdjson::dom::array arr;
  if (!e.get(obj)) {
    std::vector<std::string_view> keys;
    for (const auto field : obj) {
      if (std::find(keys.begin(), keys.end(), field.key) != keys.end()) return false;
      keys.push_back(field.key);
      if (!distinct_keys(field.value)) return false;
    }
  } else if (!e.get(arr)) {
    for (const auto item : arr)
      if (!distinct_keys(item)) return false;
  }
  return true;
}

/// The fast reader: true with `p` filled for a well-formed dense file that passes every check
/// of the reference reader; false (p untouched) for anything else, which the reference reader
/// then reads or refuses with its message. Nesting is limited to kMaxJsonDepth - 1 here, so
/// that the boundary is always the reference reader's.
bool parse_dense_fast(const std::string& text, LcpProblem& p) {
  if (may_underflow(text)) return false;
  simdjson::dom::parser parser;
  if (parser.allocate(text.size(), kMaxJsonDepth - 1) != simdjson::SUCCESS) return false;
  simdjson::dom::element root;
  if (parser.parse(text.data(), text.size()).get(root) != simdjson::SUCCESS) return false;
  simdjson::dom::object top;
  if (root.get(top) != simdjson::SUCCESS) return false;
  simdjson::dom::array jm, jq;
  bool has_m = false, has_q = false;
  std::string_view name, note;
  std::vector<std::string_view> keys;
  for (const auto field : top) {
    const std::string_view k = field.key;
    if (std::find(keys.begin(), keys.end(), k) != keys.end()) return false;  // duplicate
    keys.push_back(k);
    if (k == "M") {
      if (field.value.get(jm) != simdjson::SUCCESS) return false;
      has_m = true;
    } else if (k == "q") {
      if (field.value.get(jq) != simdjson::SUCCESS) return false;
      has_q = true;
    } else if (k == "name") {
      if (field.value.get(name) != simdjson::SUCCESS) return false;
    } else if (k == "note") {
      if (field.value.get(note) != simdjson::SUCCESS) return false;
    } else if (k == "source" || k == "expected") {
      if (!distinct_keys(field.value)) return false;
    } else {
      return false;  // "n" (checked by the reference reader), unknown, or Matrix Market
    }
  }
  if (!has_m || !has_q) return false;
  const std::size_t n = jq.size();  // simdjson saturates at 2^24 - 1: then never equal below
  if (n == 0 || n >= 0xFFFFFF || jm.size() != n) return false;
  for (const auto row : jm) {  // every row checked before M is allocated
    simdjson::dom::array r;
    if (row.get(r) != simdjson::SUCCESS || r.size() != n) return false;
  }
  const auto ni = static_cast<Eigen::Index>(n);
  Mat M(ni, ni);
  Vec q(ni);
  Eigen::Index i = 0;
  for (const auto row : jm) {
    simdjson::dom::array r;
    if (row.get(r) != simdjson::SUCCESS) return false;
    Eigen::Index k = 0;
    for (const auto v : r) {
      double x = 0;
      if (v.get(x) != simdjson::SUCCESS) return false;  // not a number (int64/uint64/double)
      M(i, k++) = x;
    }
    ++i;
  }
  i = 0;
  for (const auto v : jq) {
    double x = 0;
    if (v.get(x) != simdjson::SUCCESS) return false;
    q[i++] = x;
  }
  p.M = std::move(M);
  p.q = std::move(q);
  p.name = std::string(name);
  p.note = std::string(note);
  return true;
}

}  // namespace

LcpProblem parse_lcp_json(const std::string& text, const std::string& origin_in) {
  LcpProblem p;
  if (parse_dense_fast(text, p)) {
    throw_if_invalid(p.validate(), io_text::valid_utf8(origin_in));
    return p;
  }
  return parse_lcp_json_reference(text, origin_in);
}

LcpProblem parse_lcp_json_reference(const std::string& text, const std::string& origin_in) {
  const std::string origin = io_text::valid_utf8(origin_in);
  const json j = parse_json_bounded(text, origin, "an LCP file needs 3: {\"M\": [[...]]}");
  if (!j.is_object()) throw InputError(origin + ": top level must be an object with \"M\" and \"q\"");
  check_fields(j, origin);
  LcpProblem p = (j.contains("M_mtx") || j.contains("q_mtx")) ? from_matrix_market_fields(j, origin)
                                                              : from_dense_fields(j, origin);
  p.name = j.contains("name") ? j["name"].get<std::string>() : std::string();
  p.note = j.contains("note") ? j["note"].get<std::string>() : std::string();
  if (j.contains("n")) check_size_field(j["n"], p.q.size(), origin);
  throw_if_invalid(p.validate(), origin);
  return p;
}

LcpProblem read_lcp_json(const std::string& path) {
  return parse_lcp_json(io_text::read_text(path), path);
}

void write_lcp_json(const LcpProblem& p, const std::string& path) {
  json j;
  if (!p.name.empty()) j["name"] = p.name;
  if (!p.note.empty()) j["note"] = p.note;
  const Mat m = p.dense_M();
  j["M"] = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    j["M"].push_back(row);
  }
  j["q"] = std::vector<double>(p.q.data(), p.q.data() + p.q.size());
  std::ofstream out(path);
  if (!out) throw InputError(io_text::valid_utf8(path) + ": cannot write file");
  // Names and notes set in code may hold any bytes: write them as valid UTF-8.
  out << j.dump(1, ' ', false, json::error_handler_t::replace) << '\n';
}

}  // namespace cpkit
