// Parameter x direction maps of N-point systems (docs/maps.md, "N points").
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/rate_problem/maps/system_direction_map.hpp"
#include "run_items.hpp"

namespace cpkit::rate {

namespace {
using Kind = SystemMapParameter::Kind;

struct KindName {
  Kind kind;
  const char* name;
};
constexpr KindName kKindNames[] = {{Kind::kMu, "mu"},   {Kind::kCT, "C_T"},
                                   {Kind::kKa, "k_a"},  {Kind::kPN, "P_N"},
                                   {Kind::kCoupling, "coupling"}};

std::string accepted_names(int n_points) {
  return "mu, C_T, k_a, P_N, coupling, or one point's mu@i, C_T@i, k_a@i, P_N@i with i = 1.." +
         std::to_string(n_points);
}

/// A cell's point-type pattern: its sorted type tuples (what the pattern table numbers).
std::vector<TypeTuple> tuples_of(const SystemRateSummary& s) {
  const int k = std::min(s.n_tuples, SystemRateSummary::kCap);
  return {s.tuples.begin(), s.tuples.begin() + k};
}
}  // namespace

std::string SystemMapParameter::name() const {
  std::string s = "?";
  for (const auto& k : kKindNames)
    if (k.kind == kind) s = k.name;
  return point > 0 ? s + "@" + std::to_string(point) : s;
}

SystemMapParameter parse_system_map_parameter(std::string_view s, int n_points) {
  const std::string text(s);
  const auto at = s.find('@');
  const std::string_view base = s.substr(0, at);
  SystemMapParameter p;
  bool known = false;
  for (const auto& k : kKindNames)
    if (base == k.name) {
      p.kind = k.kind;
      known = true;
    }
  if (!known)
    throw InputError("unknown map parameter '" + text + "' for a system (accepted: " +
                     accepted_names(n_points) + ")");
  if (at != std::string_view::npos) {
    if (p.kind == Kind::kCoupling)
      throw InputError("map parameter '" + text + "': coupling applies to the whole system, not "
                       "to one point");
    const std::string digits(s.substr(at + 1));
    const bool numeric = !digits.empty() && digits.size() <= 9 &&
                         std::all_of(digits.begin(), digits.end(),
                                     [](char c) { return c >= '0' && c <= '9'; });
    const long i = numeric ? std::stol(digits) : 0;
    if (i < 1 || i > n_points)
      throw InputError("map parameter '" + text + "': the point number must be 1.." +
                       std::to_string(n_points) + " (the system has " +
                       std::to_string(n_points) + " points)");
    p.point = static_cast<int>(i);
  }
  return p;
}

ContactSystem apply_system_map_parameter(const ContactSystem& base, const SystemMapParameter& p,
                                         double value) {
  ContactSystem sys = base;
  const int N = sys.n_points();
  auto where = [&] {
    std::ostringstream s;
    s << "map parameter " << p.name() << " = " << value;
    return s.str();
  };
  if (!std::isfinite(value)) throw InputError(where() + ": not a finite number");
  if (p.kind == Kind::kCoupling) {
    // A(c) = D + c (A - D): the points' own 2x2 blocks stay, the coupling between them scales.
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (i != j) sys.A.block(2 * i, 2 * j, 2, 2) *= value;
  } else {
    for (int i = 0; i < N; ++i) {
      if (p.point > 0 && i != p.point - 1) continue;
      SystemPoint& pt = sys.points[static_cast<std::size_t>(i)];
      switch (p.kind) {
        case Kind::kMu: pt.mu = value; break;
        case Kind::kCT: pt.C_T = value; break;
        case Kind::kKa: pt.k_a = value; break;
        case Kind::kPN:
          if (pt.state.label != StateLabel::kC && pt.state.label != StateLabel::kD) {
            if (p.point > 0)
              throw InputError(where() + ": point " + std::to_string(i + 1) + " is in state " +
                               std::string(to_string(pt.state.label)) + " (P_N applies to "
                               "points in state c or d)");
            continue;
          }
          pt.state.P_N = value;
          pt.P_N = value;
          break;
        case Kind::kCoupling: break;
      }
      // A sliding point stays on its friction limit: |P_T| = mu P_N (criterion (38)) or
      // mu P_N - k P_N^2 (35), with its sign.
      if (pt.state.label == StateLabel::kD) {
        const double k = pt.k_a / (3.0 * pt.P_s);
        double limit = pt.mu * pt.P_N;
        if (sys.criterion == Criterion::kSoftening) limit -= k * pt.P_N * pt.P_N;
        pt.P_T = pt.state.sgn_PT * limit;
      }
    }
    if (p.kind == Kind::kPN && p.point == 0) {
      bool any = false;
      for (const auto& pt : sys.points)
        any = any || pt.state.label == StateLabel::kC || pt.state.label == StateLabel::kD;
      if (!any)
        throw InputError("map parameter P_N: no point of the system is in state c or d");
    }
  }
  if (std::string e = sys.validate(); !e.empty()) throw InputError(where() + ": " + e);
  return sys;
}

SystemParamDirectionMap compute_system_param_direction_map(const ContactSystem& system,
                                                           const SystemMapParameter& param,
                                                           double from, double to, int n,
                                                           int theta_n, int threads,
                                                           const MapProgress& progress) {
  throw_if_invalid(system.validate(), "system");
  MapAxis axis;
  axis.from = from;
  axis.to = to;
  axis.n = n;
  throw_if_invalid(axis.validate(), "map axis " + param.name());
  if (theta_n < 1 || theta_n > 1000000)
    throw InputError("theta-n must be in [1, 1000000], got " + std::to_string(theta_n));
  if (static_cast<int64_t>(n) * theta_n > kMaxSystemMapCells)
    throw InputError("the map has " + std::to_string(static_cast<int64_t>(n) * theta_n) +
                     " cells; an N-point map keeps its cells in memory and accepts at most " +
                     std::to_string(kMaxSystemMapCells) + " (lower --n or --theta-n)");
  if (threads < 0 || threads > 1024)
    throw InputError("threads must be in [0, 1024], got " + std::to_string(threads));
  const Stopwatch clock;
  SystemParamDirectionMap map;
  map.param = param;
  map.from = from;
  map.to = to;
  map.n = n;
  map.theta_n = theta_n;
  map.theta = map_theta_values(theta_n);

  // Every row's system, validated before any cell is computed (the message names the value).
  Eigen::VectorXd e1, e2;
  system_map_patterns(system, e1, e2);
  std::vector<SystemRatePrecomputed> rows;
  rows.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    rows.push_back(precompute_system_rate(apply_system_map_parameter(system, param, map.value(i))));
    map.m_max = std::max(map.m_max, rows.back().m);
  }
  if (map.m_max > kMaxSystemMapLcp)
    throw InputError("system: the rate LCP has size " + std::to_string(map.m_max) +
                     " (3 per point in state b, 1 per point in state d); a map cell enumerates "
                     "its 2^m bases and the maps accept at most " +
                     std::to_string(kMaxSystemMapLcp));

  const std::size_t cells = static_cast<std::size_t>(map.cells());
  map.count.assign(cells, 0);
  map.pattern.assign(cells, 0);
  // Per row: the row's own pattern table (ids in order of first appearance in the row), merged
  // into the global table in row order afterwards, so ids do not depend on the thread count.
  std::vector<std::vector<std::vector<TypeTuple>>> row_patterns(static_cast<std::size_t>(n));
  std::vector<int64_t> row_unreliable(static_cast<std::size_t>(n), 0);
  auto row = [&](int i) {
    const SystemRatePrecomputed& pre = rows[static_cast<std::size_t>(i)];
    Eigen::VectorXd dF(e1.size());
    auto& table = row_patterns[static_cast<std::size_t>(i)];
    const std::size_t base = static_cast<std::size_t>(i) * static_cast<std::size_t>(theta_n);
    for (int j = 0; j < theta_n; ++j) {
      dF = std::cos(map.theta[j]) * e1 + std::sin(map.theta[j]) * e2;
      const SystemRateSummary s = summarize_rate_problem(pre, dF);
      std::vector<TypeTuple> t = tuples_of(s);
      auto it = std::find(table.begin(), table.end(), t);
      if (it == table.end()) it = table.insert(table.end(), std::move(t));
      map.count[base + j] = static_cast<int8_t>(s.count);
      map.pattern[base + j] = static_cast<uint16_t>(it - table.begin());
      row_unreliable[static_cast<std::size_t>(i)] += !s.reliable;
    }
  };
  map.threads = resolve_threads(threads, n);
  run_items(0, n, map.threads, row, [&](int done) {
    if (progress) progress("cells", static_cast<double>(done) / n);
  });
  if (progress) progress("cells", 1.0);

  std::map<std::vector<TypeTuple>, int> global;
  std::array<GridClassBox, 128> boxes{};
  for (int i = 0; i < n; ++i) {
    const auto& table = row_patterns[static_cast<std::size_t>(i)];
    std::vector<uint16_t> to_global(table.size());
    for (std::size_t k = 0; k < table.size(); ++k) {
      auto [it, added] = global.emplace(table[k], static_cast<int>(map.patterns.size()));
      if (added) {
        if (map.patterns.size() >= 65535)
          throw InputError("the map has more than 65535 distinct point-type patterns");
        map.patterns.push_back(table[k]);
        map.pattern_cells.push_back(0);
      }
      to_global[k] = static_cast<uint16_t>(it->second);
    }
    const std::size_t base = static_cast<std::size_t>(i) * static_cast<std::size_t>(theta_n);
    for (int j = 0; j < theta_n; ++j) {
      uint16_t& id = map.pattern[base + j];
      id = to_global[id];
      ++map.pattern_cells[id];
      boxes[static_cast<std::size_t>((map.count[base + j] + 1) & 127)].add(map.value(i),
                                                                           map.theta[j]);
    }
    map.unreliable += row_unreliable[static_cast<std::size_t>(i)];
  }
  for (std::size_t c = 0; c < boxes.size(); ++c)
    if (boxes[c].cells > 0) {
      boxes[c].code = static_cast<int>(c) - 1;
      map.classes.push_back(boxes[c]);
    }
  map.seconds = clock.seconds();
  return map;
}

}  // namespace cpkit::rate
