#include "cpkit/rate_problem/report/simulation_text.hpp"

#include <sstream>

namespace cpkit::rate {

std::string simulation_text(const SimulationResult& r, bool heat) {
  std::ostringstream o;
  o << "simulate: " << to_string(r.outcome) << " after " << r.steps << " steps\n  " << r.message
    << "\n"
    << "  final wear depth " << r.wear_depth << " (Archard integral " << r.wear_integral
    << "), total slip " << r.total_slip << "\n"
    << "  energy: work " << r.external_work << " = stored " << r.stored_energy
    << " + dissipation " << r.dissipation << " (relative error " << r.energy_error
    << ")\n  branch points: " << r.branch_steps << "\n";
  if (heat)
    o << "  temperature: final " << r.final_state.temperature << ", max " << r.max_temperature
      << "\n";
  return o.str();
}

std::string system_simulation_text(const SystemSimulationResult& r) {
  std::ostringstream o;
  const Eigen::Index N = r.final_state.w_w.size();
  o << "simulate (" << N << " points): "
    << (r.inconclusive ? std::string_view("inconclusive") : to_string(r.outcome)) << " after "
    << r.steps << " steps\n  " << r.message << "\n  wear depth per point:";
  for (Eigen::Index i = 0; i < N; ++i) o << ' ' << r.final_state.w_w[i];
  o << "\n  Archard integral per point:";
  for (Eigen::Index i = 0; i < N; ++i) o << ' ' << r.wear_integral[i];
  o << "\n  energy balance relative error " << r.energy_error << ", branch points "
    << r.branch_steps << ", steps not proved complete " << r.incomplete_steps << "\n";
  return o.str();
}

std::string fretting_3d_text(const Fretting3dResult& r, WearLaw law) {
  std::ostringstream o;
  o << "simulate (3-D point): " << to_string(r.outcome) << " after " << r.steps << " steps\n  "
    << r.message << "\n  wear depth " << r.wear_depth << " ("
    << (law == WearLaw::kMrozStupkiewicz ? "Mroz" : "Archard") << " integral "
    << r.wear_integral << "), slip path length " << r.total_slip << "\n";
  if (!r.wear_per_cycle.empty())
    o << "  last cycle: wear " << r.wear_per_cycle.back() << " (by X slip "
      << r.wear_X_per_cycle.back() << ", by Y slip " << r.wear_Y_per_cycle.back() << "), slip "
      << r.slip_per_cycle.back() << "\n";
  o << "  branch points " << r.branch_steps << ", steps not proved complete "
    << r.incomplete_steps << "\n";
  if (r.local_steps > 0)
    o << "  steps solved by the local fallback " << r.local_steps
      << " (the enumeration had claimed none for " << r.enumeration_missed << ")\n";
  return o.str();
}

}  // namespace cpkit::rate
