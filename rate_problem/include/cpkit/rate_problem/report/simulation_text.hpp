#pragma once
/// \file simulation_text.hpp
/// The text summaries `cpkit simulate` prints without --json (docs/simulation.md, docs/
/// contact_3d.md), written once here for the program, Python and tests: a few lines with the
/// outcome, the steps, the stop message, wear, slip and energy. Numbers as an std::ostream
/// prints them by default (6 significant digits), in the units of the run.
#include <string>

#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"

namespace cpkit::rate {

/// One 2-D point: "simulate: OUTCOME after N steps", the message, the final wear depth, the
/// Archard integral and the total slip, the energy balance, the branch points, and with `heat`
/// the final and largest interface temperature.
std::string simulation_text(const SimulationResult& r, bool heat);

/// N points: "simulate (N points): OUTCOME after N steps" ("inconclusive" when the run stopped
/// without proof), the message, the wear depth and the Archard integral per point, the energy
/// balance error, the branch points and the steps not proved complete.
std::string system_simulation_text(const SystemSimulationResult& r);

/// One 3-D point under an elliptic orbit: "simulate (3-D point): OUTCOME after N steps", the
/// message, wear depth (the integral named after the wear law `law`), slip path length, the last
/// cycle's wear (by X and Y slip) and slip, branch points, steps not proved complete and those
/// solved by the local fallback.
std::string fretting_3d_text(const Fretting3dResult& r, WearLaw law);

}  // namespace cpkit::rate
