#pragma once
// One solution piece (point, segment, ray) as the rate, step and N-point reports write it, in
// JSON and in text: a point alone, a segment as start/end with their closedness, a ray as start
// and direction.
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "cpkit/rate_problem/rate/point_rate.hpp"

namespace cpkit::rate::report_detail {

/// The piece's JSON into e: a point under `point_key`; `values` turns a value into JSON.
template <class Piece, class Values>
void add_piece(nlohmann::json& e, const Piece& p, const char* point_key, Values values) {
  e["kind"] = std::string(to_string(p.kind));
  switch (p.kind) {
    case RateSolution::Kind::kPoint:
      e[point_key] = values(p.start);
      break;
    case RateSolution::Kind::kSegment:
      e["start"] = values(p.start);
      e["start_closed"] = p.start_closed;
      e["end"] = values(p.end);
      e["end_closed"] = p.end_closed;
      break;
    case RateSolution::Kind::kRay:
      e["start"] = values(p.start);
      e["start_closed"] = p.start_closed;
      e["direction"] = values(p.direction);
      break;
  }
}

/// The piece's text: "X" for a point, "from X (closed)\n      to Y (open)" and the like;
/// `text` prints one value (one point: "dP_T=...", after `from` = "from " and `sep` = " "; N
/// points: " dP_T=[...]", after " from" and "").
template <class Piece, class Text>
void piece_text(std::ostream& o, const Piece& p, const char* from, const char* sep, Text text) {
  const auto end = [](bool closed) { return closed ? " (closed)" : " (open)"; };
  switch (p.kind) {
    case RateSolution::Kind::kPoint:
      o << text(p.start) << "\n";
      break;
    case RateSolution::Kind::kSegment:
      o << from << text(p.start) << end(p.start_closed) << "\n      to" << sep << text(p.end)
        << end(p.end_closed) << "\n";
      break;
    case RateSolution::Kind::kRay:
      o << from << text(p.start) << end(p.start_closed) << "\n      direction" << sep
        << text(p.direction) << "\n";
      break;
  }
}

/// The names of the solution types present, sorted, each once.
template <class Solutions>
std::vector<std::string> type_names(const Solutions& solutions) {
  std::set<std::string> types;
  for (const auto& p : solutions) types.insert(std::string(to_string(p.type)));
  return {types.begin(), types.end()};
}

/// A count as the reports print it: "inf" for infinitely many (count() < 0), else the number.
inline nlohmann::json count_json(long long count) {
  return count < 0 ? nlohmann::json("inf") : nlohmann::json(count);
}

/// "complete", and "count" (-1: "inf") only when the set is complete: one solver's one
/// solution is not "count 1"; else "found", the number of solutions listed.
inline void add_count(nlohmann::json& j, bool complete, long long count, std::size_t found) {
  j["complete"] = complete;
  if (complete) j["count"] = count_json(count);
  else j["found"] = found;
}

}  // namespace cpkit::rate::report_detail
