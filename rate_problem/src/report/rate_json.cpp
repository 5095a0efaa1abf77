#include "cpkit/rate_problem/report/json.hpp"

#include <string>
#include <vector>

#include "cpkit/rate_problem/report/rate_outcome.hpp"
#include "cpkit/rate_problem/report/json_3d.hpp"
#include "piece_report.hpp"

namespace cpkit::rate {

namespace {

std::vector<double> as_list(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

}  // namespace

nlohmann::json rates_json(const Rates& r) {
  return {{"dP_T", r.dP_T}, {"dP_N", r.dP_N}, {"dw_T", r.dw_T},
          {"dw_N", r.dw_N}, {"dw_Ti", r.dw_Ti}, {"dw_w", r.dw_w}};
}

nlohmann::json rates_json(const SystemRates& r) {
  return {{"dP_T", as_list(r.dP_T)}, {"dP_N", as_list(r.dP_N)}, {"dw_T", as_list(r.dw_T)},
          {"dw_N", as_list(r.dw_N)}, {"dw_Ti", as_list(r.dw_Ti)}, {"dw_w", as_list(r.dw_w)}};
}

nlohmann::json rate_set_json(const RateSolutionSet& s, const RateSolutionSet* reference) {
  using report_detail::count_json;
  nlohmann::json j;
  report_detail::add_count(j, s.complete, s.count(), s.solutions.size());
  if (reference && reference->complete) j["enumerated_count"] = count_json(reference->count());
  j["types"] = report_detail::type_names(s.solutions);
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& p : s.solutions) {
    nlohmann::json e;
    e["type"] = std::string(to_string(p.type));
    report_detail::add_piece(e, p, "rates", [](const Rates& r) { return rates_json(r); });
    sols.push_back(e);
  }
  j["solutions"] = sols;
  j["Lambda"] = s.Lambda;
  j["D_plus"] = s.D_plus;  // D_s = a11 - s mu a12 (docs/model.md Sec. 2.2), as the text prints
  j["D_minus"] = s.D_minus;
  j["unique_for_all_directions"] = s.unique_for_all_directions;
  return j;
}

nlohmann::json system_rate_set_json(const SystemRateSolutionSet& s) {
  nlohmann::json j;
  report_detail::add_count(j, s.complete, s.count(), s.solutions.size());
  if (!s.message.empty()) j["message"] = s.message;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& p : s.solutions) {
    nlohmann::json e;
    nlohmann::json types = nlohmann::json::array();
    for (auto t : p.types) types.push_back(std::string(to_string(t)));
    e["types"] = types;
    report_detail::add_piece(e, p, "values", [](const SystemRates& r) { return rates_json(r); });
    sols.push_back(e);
  }
  j["solutions"] = sols;
  return j;
}

nlohmann::json rate_outcome_json(const RateOutcome& out, const std::string& version) {
  if (out.route == RateOutcome::Route::kOnePoint) {
    const CheckedRateSolution& c = *out.one_point;
    return rate_set_json(c.set, c.reference ? &*c.reference : nullptr);
  }
  const bool three_d = out.route == RateOutcome::Route::kSystem3d;
  nlohmann::json j = three_d ? system_rate_3d_json(*out.system_3d) : system_rate_set_json(*out.system);
  j["cpkit_version"] = version;
  j["input"] = {{"system", out.path},
                {"name", out.name},
                {"dF", std::vector<double>(out.dF.data(), out.dF.data() + out.dF.size())},
                {"method", out.method}};
  if (three_d) {
    j["input"]["facets"] = out.facets;
    j["dim"] = 3;
  }
  j["n_points"] = out.n_points;
  return j;
}

}  // namespace cpkit::rate
