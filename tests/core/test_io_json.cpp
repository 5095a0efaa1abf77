// JSON problem files: the layout, every refusal as a clear InputError naming the field or line,
// and the limits (nesting depth, number range, unknown fields).
#include <catch2/catch.hpp>

#include <string>

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
  fails_with(R"({"M": [[1]], "q": [1)", "malformed JSON");
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
  fails_with(R"({"M": [[NaN]], "q": [1]})", "f.json:1: malformed JSON");
  fails_with(R"({"M": [[1]], "q": [Infinity]})", "malformed JSON");
  fails_with(R"({"M": [[1]], "q": [-Infinity]})", "malformed JSON");
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
  fails_with("{\"M\": [[1]], \"q\": [1], \"note\": \"\xff\"}", "malformed JSON");
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
