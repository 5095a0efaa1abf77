#pragma once
// The JSON of one solution piece (point, segment, ray), shared by the rate, step and N-point
// reports: a point under `point_key`, a segment as start/end with their closedness, a ray as
// start and direction. `values` turns the piece's value type into JSON.
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/rate_problem/rate/point_rate.hpp"

namespace cpkit::rate::report_detail {

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

/// A count as the reports print it: "inf" for infinitely many (count() < 0), else the number.
inline nlohmann::json count_json(long long count) {
  return count < 0 ? nlohmann::json("inf") : nlohmann::json(count);
}

}  // namespace cpkit::rate::report_detail
