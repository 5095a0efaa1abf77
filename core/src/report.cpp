#include "cpkit/core/report.hpp"

#include <cmath>
#include <sstream>

namespace cpkit {

nlohmann::json to_json(const Vec& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i])) a.push_back(v[i]);
    else a.push_back(nullptr);
  }
  return a;
}

nlohmann::json to_json(const Residuals& r) {
  return {{"natural", r.natural},         {"natural_abs", r.natural_abs},
          {"complementarity", r.complementarity}, {"min_z", r.min_z},
          {"min_w", r.min_w},             {"worst_index", r.worst_index},
          {"scale", r.scale},             {"rounding", r.rounding}};
}

nlohmann::json to_json(const SolveResult& r) {
  nlohmann::json j;
  j["status"] = std::string(to_string(r.status));
  j["solver"] = r.solver;
  j["z"] = to_json(r.z);
  j["w"] = to_json(r.w);
  j["iterations"] = r.iterations;
  j["residual"] = r.residuals.natural;
  j["residuals"] = to_json(r.residuals);
  j["function_evals"] = r.function_evals;
  j["jacobian_evals"] = r.jacobian_evals;
  j["line_search_steps"] = r.line_search_steps;
  j["gradient_steps"] = r.gradient_steps;
  j["seconds"] = r.seconds;
  j["message"] = r.message;
  if (r.certificate) {
    j["certificate"] = {{"y", to_json(r.certificate->y)},
                        {"q_dot_y", r.certificate->q_dot_y},
                        {"max_MTy", r.certificate->max_MTy},
                        {"checked", r.certificate->checked},
                        {"exact", r.certificate->exact}};
  }
  if (r.ray) j["ray"] = to_json(*r.ray);
  if (!r.basis.empty()) j["basis"] = r.basis;
  if (!r.attempts.empty()) {
    auto& a = j["attempts"] = nlohmann::json::array();
    for (const auto& t : r.attempts)
      a.push_back({{"solver", t.solver},
                   {"status", std::string(to_string(t.status))},
                   {"residual", t.residual},
                   {"seconds", t.seconds},
                   {"message", t.message}});
  }
  if (!r.trace.empty()) {
    auto& t = j["trace"] = nlohmann::json::array();
    for (const auto& e : r.trace)
      t.push_back({{"iteration", e.iteration},
                   {"residual", e.residual},
                   {"step", e.step},
                   {"kind", e.kind},
                   {"entering", e.entering},
                   {"leaving", e.leaving}});
  }
  return j;
}

std::string to_text(const SolveResult& r) {
  std::ostringstream s;
  s.precision(6);
  s << "status:     " << to_string(r.status) << '\n';
  s << "solver:     " << r.solver << '\n';
  s << "iterations: " << r.iterations << '\n';
  s << "residual:   " << r.residuals.natural << " (unit-free residual, docs/conventions.md)\n";
  s << "time:       " << r.seconds * 1e3 << " ms\n";
  auto vec = [&](const char* label, const Vec& v) {
    s << label;
    const Eigen::Index shown = std::min<Eigen::Index>(v.size(), 12);
    for (Eigen::Index i = 0; i < shown; ++i) s << (i ? " " : "") << v[i];
    if (v.size() > shown) s << " ... (" << v.size() << " entries)";
    s << '\n';
  };
  if (r.z.size()) vec("z:          ", r.z);
  if (r.w.size()) vec("w:          ", r.w);
  if (r.certificate) {
    vec("certificate y: ", r.certificate->y);
    s << "  q.y = " << r.certificate->q_dot_y << ", max(M^T y) = " << r.certificate->max_MTy
      << '\n';
  }
  for (const auto& a : r.attempts)
    s << "attempt:    " << a.solver << " -> " << to_string(a.status) << " (residual " << a.residual
      << ")" << (a.message.empty() ? "" : ": " + a.message) << '\n';
  if (!r.message.empty()) s << "message:    " << r.message << '\n';
  return s.str();
}

}  // namespace cpkit
