#pragma once
/// \file simulation_csv.hpp
/// The time series of a simulation as CSV (docs/simulation.md, "Time series"; docs/contact_3d.md
/// for 3-D): one header line and one line per recorded sample, written as the run produces them
/// (never held in memory). Numbers are written with the stream's precision (`cpkit simulate`
/// uses 12 digits); states and types by name; flags as 0/1. Units as the run's input.
#include <fstream>
#include <ostream>
#include <string>

#include "cpkit/rate_problem/simulation/fretting_3d.hpp"
#include "cpkit/rate_problem/simulation/simulation.hpp"
#include "cpkit/rate_problem/simulation/system_simulation.hpp"

namespace cpkit::rate {

/// One point: step,t,F_T,F_N,P_T,P_N,w_T,w_N,w_w,w_Ti,g,state,type,count,dissipation,
/// dissipation_total,work_total,stored,temperature (with the line end).
std::string simulation_csv_header();
void write_simulation_csv_row(std::ostream& out, const SimulationSample& s);

/// N points: step,t, then per point i F_T_i,F_N_i,P_T_i,P_N_i,w_T_i,w_N_i,w_w_i,w_Ti_i,g_i,
/// state_i,type_i,temperature_i, then count,complete,dissipation_total,work_total,stored.
std::string system_simulation_csv_header(int n_points);
void write_system_simulation_csv_row(std::ostream& out, const SystemSimulationSample& s);

/// One 3-D point: step,t,F_TX,F_TY,F_N,P_TX,P_TY,P_N,g,w_TX,w_TY,w_N,w_TiX,w_TiY,Dw_TiX,Dw_TiY,
/// lambda,Dw_w,w_w,type,count,complete,dissipation,cycle.
std::string fretting_3d_csv_header();
void write_fretting_3d_csv_row(std::ostream& out, const Fretting3dSample& s);

/// Opens an output file for writing, creating its folder first (configs name paths such as
/// out/fretting.csv). Throws InputError "cannot write 'PATH'" when it cannot be written.
std::ofstream open_output(const std::string& path);

/// Flushes an output file; InputError "error writing 'PATH' (disk full or not writable?)" when
/// it could not be written.
void finish_output(std::ofstream& f, const std::string& path);

}  // namespace cpkit::rate
