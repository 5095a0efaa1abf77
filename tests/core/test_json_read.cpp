// The one bounded JSON parser of every reader (core/json_read.hpp) and the bounded rendering of
// values in messages (issue 24, item 15: 10^6 nested brackets crashed the system-file readers
// and the Python interpreter; messages rendered values recursively).
#include <catch2/catch.hpp>

#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"
#include "cpkit/core/number_text.hpp"

namespace {

using cpkit::InputError;
using cpkit::json_excerpt;
using cpkit::kMaxJsonDepth;
using cpkit::parse_json_bounded;
using Catch::Contains;
using nlohmann::json;

std::string nested(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

}  // namespace

TEST_CASE("parse_json_bounded: nesting is refused beyond 64 levels, at any depth", "[io][json]") {
  // The documented limit (docs/file_formats.md): 64 levels are read, 65 are refused.
  CHECK(parse_json_bounded(nested(kMaxJsonDepth), "f.json").is_array());
  CHECK_THROWS_WITH(parse_json_bounded(nested(kMaxJsonDepth + 1), "f.json"),
                    Contains("f.json:1: nesting deeper than 64 levels"));
  // The issue's reproducer: 10^6 nested brackets (2 MB), bare and under a key; objects too.
  for (const std::string& text :
       {nested(1'000'000), "{\"A\": " + nested(1'000'000) + "}",
        std::string(1'000'000, '[') + "{\"k\": 1}" + std::string(1'000'000, ']')}) {
    CHECK_THROWS_AS(parse_json_bounded(text, "f.json", "a file needs 3"), InputError);
    CHECK_THROWS_WITH(parse_json_bounded(text, "f.json", "a file needs 3"),
                      Contains("nesting deeper than 64 levels (a file needs 3)"));
  }
}

TEST_CASE("parse_json_bounded: numbers that do not fit a double and duplicate keys", "[io][json]") {
  CHECK_THROWS_WITH(parse_json_bounded("{\"a\":\n 1e-400}", "f.json"),
                    Contains("f.json:2: '1e-400' is below the smallest double"));
  CHECK_THROWS_WITH(parse_json_bounded("[-1e-400]", "f.json"), Contains("'-1e-400' is below"));
  CHECK_THROWS_WITH(parse_json_bounded("[1e400]", "f.json"),
                    Contains("'1e400' is outside the range of double"));
  CHECK_THROWS_WITH(parse_json_bounded(R"({"a": 1, "a": 2})", "f.json"),
                    Contains("duplicate field \"a\""));
  CHECK_THROWS_WITH(parse_json_bounded(R"({"a": )", "f.json"), Contains("not valid JSON"));
  // Subnormal literals are doubles (4.9e-324 is the smallest), zero is zero.
  CHECK(parse_json_bounded("[4.9e-324]", "f")[0].get<double>() == 4.9e-324);
  CHECK(parse_json_bounded("[0e-400]", "f")[0].get<double>() == 0.0);
}

TEST_CASE("json_excerpt: short values whole, long and deep ones cut at bounded cost", "[io][json]") {
  CHECK(json_excerpt(json::parse(R"([1, 2, 3])")) == "[1,2,3]");
  CHECK(json_excerpt(json::parse(R"({"b": [true, null], "a": "x"})")) ==
        R"({"a":"x","b":[true,null]})");  // nlohmann keeps keys sorted
  // 100 characters: the first 37 bytes of the dump (a quote and 36 letters) and "...".
  CHECK(json_excerpt(json(std::string(100, 'a'))) == "\"" + std::string(36, 'a') + "...");
  // A 10^6-element array: 40 characters whatever its size.
  json big = json::array();
  for (int i = 0; i < 1'000'000; ++i) big.push_back(i % 10);
  CHECK(json_excerpt(big) == "[0,1,2,3,4,5,6,7,8,9,0,1,2,3,4,5,6,7,...");
  // A value built in code 10^6 levels deep (no parser limit applies): no recursion into it.
  json deep = 1;
  for (int i = 0; i < 1'000'000; ++i) {
    json outer = json::array();
    outer.push_back(std::move(deep));
    deep = std::move(outer);
  }
  CHECK(json_excerpt(deep) == std::string(37, '[') + "...");
  CHECK(cpkit::json_dump_prefix(deep, 5) == "[[[[[");
  // Multi-byte UTF-8 is never cut in the middle of a character.
  const std::string e_acute = "\xc3\xa9";
  std::string accents;
  for (int i = 0; i < 30; ++i) accents += e_acute;
  // the dump is '"x' and 2-byte characters: byte 37 is the middle of one, so the cut is at 36
  CHECK(json_excerpt(json("x" + accents)) == "\"x" + accents.substr(0, 34) + "...");
}

TEST_CASE("parse_decimal: strict decimal numbers (load CSVs, problem files)", "[io][number]") {
  using cpkit::NumberText;
  double v = 0;
  CHECK(cpkit::parse_decimal("-1.5e-3", v) == NumberText::kOk);
  CHECK(v == -1.5e-3);
  CHECK(cpkit::parse_decimal("+2", v) == NumberText::kOk);
  CHECK(v == 2);
  // hexadecimal (strtod and std::stod accept these) and partial tokens are not numbers
  for (const char* t : {"0x10", "0x1p3", "1.5x", "", " 1", "1 ", "--1", "+-1", "1e"})
    CHECK(cpkit::parse_decimal(t, v) == NumberText::kNotANumber);
  for (const char* t : {"nan", "inf", "-inf", "infinity"})
    CHECK(cpkit::parse_decimal(t, v) == NumberText::kNotFinite);
  CHECK(cpkit::parse_decimal("1e400", v) == NumberText::kOverflow);
  CHECK(cpkit::parse_decimal("-1e400", v) == NumberText::kOverflow);
  CHECK(cpkit::parse_decimal("1e-400", v) == NumberText::kUnderflow);
  CHECK(cpkit::parse_decimal("1e-320", v) == NumberText::kOk);
  CHECK(v == 1e-320);
  CHECK(cpkit::describe_number(NumberText::kNotANumber, "0x10") == "expected a number, got '0x10'");
}
