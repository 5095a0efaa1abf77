// JSON problem files: the layout, every refusal as a clear InputError naming the field or line,
// and the limits (nesting depth, number range, unknown fields).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::InputError;
using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;

void fails_with(const std::string& text, const std::string& part) {
  CAPTURE(text.substr(0, 200));
  CHECK_THROWS_AS(cpkit::parse_lcp_json(text, "f.json"), InputError);
  CHECK_THROWS_WITH(cpkit::parse_lcp_json(text, "f.json"), Contains("f.json") && Contains(part));
}

}  // namespace

TEST_CASE("JSON problems", "[io][json]") {
  const auto p = cpkit::parse_lcp_json(
      R"({"name": "t", "note": "n", "M": [[1, 2], [3, 4]], "q": [-1, 0.5], "expected": {},
          "source": "hand"})");
  CHECK(p.name == "t");
  CHECK(p.note == "n");
  CHECK(p.M == Mat{{1, 2}, {3, 4}});  // row-major in the file
  CHECK(p.q == Vec{{-1, 0.5}});
  CHECK_FALSE(p.is_sparse());
  // Integers beyond int64, -0 and subnormals are doubles like any other number.
  const auto big = cpkit::parse_lcp_json(R"({"M": [[18446744073709551616]], "q": [-0]})");
  CHECK(big.M(0, 0) == 18446744073709551616.0);
  CHECK(cpkit::parse_lcp_json(R"({"M": [[1e-320]], "q": [-1]})").M(0, 0) == 1e-320);
}

TEST_CASE("Malformed JSON problems name the field", "[io][json]") {
  fails_with(R"({"M": [[1]], "q": [1)", "not valid JSON");
  fails_with(R"([1, 2])", "top level must be an object");
  fails_with(R"({"q": [1]})", "missing field \"M\"");
  fails_with(R"({"M": [[1]]})", "missing field \"q\"");
  fails_with(R"({"M": [[1]], "q": 1})", "\"q\" must be an array");
  fails_with(R"({"M": 1, "q": [1]})", "\"M\" must be an array of rows");
  fails_with(R"({"M": [], "q": []})", "\"q\" is empty");
  fails_with(R"({"M": [[1, 2]], "q": [1, 2]})", "has 1 rows but \"q\" has 2");
  fails_with(R"({"M": [[1, 2], [3]], "q": [1, 2]})", "M row 1 must be an array of 2");
  fails_with(R"({"M": [[1, 2], ["x", 4]], "q": [1, 2]})", "M[1][0] is not a number (got \"x\")");
  fails_with(R"({"M": [[1, 2], [3, 4]], "q": [1, null]})", "q[1] is not a number");
  fails_with(R"({"M": [[1, 2], [3, 4]], "q": [1, true]})", "q[1] is not a number (got true)");
  fails_with(R"({"M_mtx": "a.mtx"})", "\"M_mtx\" and \"q_mtx\" must both be file names");
  fails_with(R"({"M": [[1]], "q": [1], "name": 3})", "field \"name\" must be a string");
  fails_with(R"({"M": [[1]], "q": [1], "M_mtx": "a.mtx", "q_mtx": "b.mtx"})",
             "give either \"M\" and \"q\" or \"M_mtx\" and \"q_mtx\", not both");
  // A long bad value is shortened in the message.
  const std::string long_string(1000, 'a');
  CHECK_THROWS_WITH(cpkit::parse_lcp_json(R"({"M": [[")" + long_string + R"("]], "q": [1]})"),
                    Contains("aaa...") && !Contains(long_string));
}

TEST_CASE("JSON: unknown fields, duplicates, NaN and Inf are errors", "[io][json]") {
  fails_with(R"({"M": [[1]], "q": [1], "Q": [2]})", "unknown field \"Q\"");
  fails_with(R"({"M": [[1]], "q": [1], "nmae": "x"})", "unknown field \"nmae\"");
  fails_with("{\"M\": [[1]],\n \"q\": [1],\n \"q\": [2]}", "f.json:3: duplicate field \"q\"");
  // JSON has no NaN or Infinity literals: nlohmann's parser refuses them.
  fails_with(R"({"M": [[NaN]], "q": [1]})", "f.json:1: not valid JSON");
  fails_with(R"({"M": [[1]], "q": [Infinity]})", "not valid JSON");
  fails_with(R"({"M": [[1]], "q": [-Infinity]})", "not valid JSON");
}

TEST_CASE("JSON: the size field \"n\" is accepted and checked against M", "[io][json]") {
  // Issue 27: many tools write the size. The 2 x 2 problem of the docs, with "n": 2.
  const auto p = cpkit::parse_lcp_json(R"({"n": 2, "M": [[2, 1], [1, 2]], "q": [-5, -6]})");
  CHECK(p.M == Mat{{2, 1}, {1, 2}});
  CHECK(p.q == Vec{{-5, -6}});
  CHECK(cpkit::parse_lcp_json(R"({"M": [[3]], "q": [1], "n": 1.0})").M(0, 0) == 3);
  // A mismatch names both sizes; a size that is not a whole number is refused.
  fails_with(R"({"n": 3, "M": [[2, 1], [1, 2]], "q": [-5, -6]})",
             "field \"n\" is 3 but M is 2 x 2");
  fails_with(R"({"n": 1, "M": [[2, 1], [1, 2]], "q": [-5, -6]})", "but M is 2 x 2");
  fails_with(R"({"n": 2.5, "M": [[2, 1], [1, 2]], "q": [-5, -6]})", "\"n\" must be");
  fails_with(R"({"n": "2", "M": [[2, 1], [1, 2]], "q": [-5, -6]})", "\"n\" must be");
  fails_with(R"({"n": -2, "M": [[2, 1], [1, 2]], "q": [-5, -6]})", "\"n\" must be");
}

TEST_CASE("JSON numbers beyond the range of double are input errors", "[io][json]") {
  // 1e400 used to escape as nlohmann's out_of_range exception (exit 4, "internal error").
  fails_with("{\"M\": [[1]],\n \"q\": [1e400]}", "f.json:2: '1e400' is outside the range of double");
  fails_with(R"({"M": [[-1e400]], "q": [1]})", "'-1e400' is outside the range of double");
  fails_with(R"({"M": [[1]], "q": [1e-400]})", "'1e-400' is below the smallest double");
  fails_with(R"({"M": [[1]], "q": [123456789012345678901234567890e400]})", "outside the range");
}

TEST_CASE("JSON nesting is bounded (no stack overflow)", "[io][json]") {
  for (const int depth : {cpkit::kMaxJsonDepth + 1, 10'000, 1'000'000}) {
    CAPTURE(depth);
    const std::string arrays = std::string(static_cast<std::size_t>(depth), '[') +
                               std::string(static_cast<std::size_t>(depth), ']');
    fails_with(arrays, "nesting deeper than 64 levels");
    fails_with(R"({"M": [[1]], "q": [1], "expected": )" + arrays + "}", "nesting deeper than 64");
    const std::string objects = [&] {
      std::string s;
      for (int k = 0; k < depth; ++k) s += "{\"a\":";
      return s + "1" + std::string(static_cast<std::size_t>(depth), '}');
    }();
    fails_with(objects, "nesting deeper than 64 levels");
  }
  // At the limit the document is read (and then judged as an LCP file).
  const std::string deep = std::string(cpkit::kMaxJsonDepth - 1, '[') +
                           std::string(cpkit::kMaxJsonDepth - 1, ']');
  CHECK_NOTHROW(cpkit::parse_lcp_json(R"({"M": [[1]], "q": [1], "expected": )" + deep + "}"));
}

TEST_CASE("JSON that is not UTF-8 is refused, messages stay UTF-8", "[io][json]") {
  fails_with("{\"M\": [[1]], \"q\": [1], \"note\": \"\xff\"}", "not valid JSON");
  // The origin (a file name) may hold any bytes; the message is valid UTF-8.
  CHECK_THROWS_WITH(cpkit::parse_lcp_json("[", "\xff.json"), Contains("\xEF\xBF\xBD.json"));
}

TEST_CASE("JSON: M is allocated only once its n rows of n numbers are in the file", "[io][json]") {
  // q with 100000 entries and 100000 empty rows: allocating M first would take 80 GB.
  const std::size_t n = 100000;
  std::string text = R"({"q": [0)";
  for (std::size_t i = 1; i < n; ++i) text += ",0";
  text += R"(], "M": [[])";
  for (std::size_t i = 1; i < n; ++i) text += ",[]";
  text += "]}";
  fails_with(text, "M row 0 must be an array of 100000 numbers");
}

namespace {

/// The outcome of one reader: the problem, or the message of its InputError.
struct Outcome {
  bool ok = false;
  cpkit::LcpProblem p;
  std::string error;
};
template <class Read>
Outcome outcome(Read&& read, const std::string& text) {
  Outcome o;
  try {
    o.p = read(text, "f.json");
    o.ok = true;
  } catch (const InputError& e) {
    o.error = e.what();
  }
  return o;
}

/// parse_lcp_json (simdjson fast path) and parse_lcp_json_reference (nlohmann) agree: the
/// same problem bit for bit, or the same message.
void same_outcome(const std::string& text) {
  const Outcome a = outcome(
      [](const std::string& t, const std::string& o) { return cpkit::parse_lcp_json(t, o); }, text);
  const Outcome b = outcome([](const std::string& t, const std::string& o) {
    return cpkit::parse_lcp_json_reference(t, o);
  }, text);
  CAPTURE(text.substr(0, 300));
  REQUIRE(a.ok == b.ok);
  if (!a.ok) {
    CHECK(a.error == b.error);
    return;
  }
  CHECK(a.p.dense_M() == b.p.dense_M());
  CHECK(a.p.q == b.p.q);
  for (Eigen::Index i = 0; i < a.p.q.size(); ++i)  // signs of zeros too
    CHECK(std::signbit(a.p.q[i]) == std::signbit(b.p.q[i]));
  CHECK(a.p.name == b.p.name);
  CHECK(a.p.note == b.p.note);
}

std::string slurp_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("JSON: the fast reader and the reference reader agree on every input", "[io][json]") {
  namespace fs = std::filesystem;
  std::vector<std::string> texts = {
      R"({"M": [[1, 2], [3, 4]], "q": [-1, 0.5], "name": "a\u00e9\n", "note": ""})",
      R"({"q": [-0, 0.0, -0.0], "M": [[0,0,0],[0,0,0],[0,0,0]]})",
      R"({"M": [[18446744073709551616]], "q": [-9223372036854775808]})",
      R"({"M": [[1e-320]], "q": [-1]})", R"({"M": [[1e-400]], "q": [-1]})",
      R"({"M": [[1E-149]], "q": [-1]})", R"({"M": [[1e-0000000000000000000400]], "q": [-1]})",
      R"({"M": [[0.)" + std::string(400, '0') + R"(1]], "q": [-1]})",
      R"({"M": [[0.)" + std::string(200, '0') + R"(1e-200]], "q": [-1]})",
      R"({"M": [[1e308]], "q": [1e309]})", R"({"M": [[1]], "q": [1], "name": "\ud800"})",
      R"({"M": [[1]], "q": [1], "name": "\udc00\ud800"})",
      R"({"M": [[1]], "q": [1], "expected": {"a": 1, "b": {"c": 2, "c": 3}}})",
      R"({"M": [[1]], "q": [1], "expected": [{"a": 1}, {"a": 2}], "source": "x"})",
      R"({"M": [[1]], "q": [1], "q": [1]})", R"({"M": [[1]], "q": [1], "M_mtx": "a"})",
      R"({"M": [[1]], "q": [1]} x)", R"({"M": [[1]], "q": [1],})", "\xef\xbb\xbf{\"M\": [[1]], \"q\": [1]}",
      R"({"M": [[1, 2], [3]], "q": [1, 2]})", R"({"M": [[1]], "q": [true]})",
      R"({"M": [[1]], "q": [1], "note": 5})", R"({"M": [[NaN]], "q": [1]})", "",
      R"({"M": [[1]], "q": [-1]})",  // validates; M = 1 > 0
      "{\"M\": [[1]], \"q\": [1]}\n\n\n",
  };
  for (int depth : {cpkit::kMaxJsonDepth - 3, cpkit::kMaxJsonDepth - 2, cpkit::kMaxJsonDepth - 1,
                    cpkit::kMaxJsonDepth, cpkit::kMaxJsonDepth + 1})
    texts.push_back(R"({"M": [[1]], "q": [1], "expected": )" + std::string(size_t(depth), '[') +
                    std::string(size_t(depth), ']') + "}");
  const fs::path root(CPKIT_SOURCE_DIR);
  for (const fs::path& dir : {root / "tests/fuzz/corpus/json_lcp", root / "tests/fuzz/regressions/json_lcp",
                             root / "tests/data/lcp"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") texts.push_back(slurp_file(e.path()));
  const std::size_t seeds = texts.size();
  // seeded mutations of every seed: byte flips, deletions, duplications
  std::mt19937 rng(14);
  for (std::size_t s = 0; s < seeds; ++s)
    for (int k = 0; k < 40; ++k) {
      std::string t = texts[s];
      if (t.empty()) break;
      std::uniform_int_distribution<std::size_t> at(0, t.size() - 1);
      const char alphabet[] = "{}[],:\"-+.eE0123456789 \\u";
      switch (k % 3) {
        case 0: t[at(rng)] = alphabet[rng() % (sizeof alphabet - 1)]; break;
        case 1: t.erase(at(rng), 1); break;
        default: { const std::size_t a = at(rng); t.insert(a, t.substr(a, 1 + rng() % 8)); }
      }
      texts.push_back(std::move(t));
    }
  for (const std::string& t : texts) same_outcome(t);
}
