#include "cpkit/rate_problem/report/simulation_csv.hpp"

#include <cstddef>
#include <filesystem>
#include <system_error>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

std::string simulation_csv_header() {
  return "step,t,F_T,F_N,P_T,P_N,w_T,w_N,w_w,w_Ti,g,state,type,count,dissipation,"
         "dissipation_total,work_total,stored,temperature\n";
}

void write_simulation_csv_row(std::ostream& f, const SimulationSample& s) {
  f << s.step << ',' << s.t << ',' << s.F_T << ',' << s.F_N << ',' << s.P_T << ',' << s.P_N
    << ',' << s.w_T << ',' << s.w_N << ',' << s.w_w << ',' << s.w_Ti << ',' << s.g << ','
    << to_string(s.state) << ',' << to_string(s.type) << ',' << s.count << ','
    << s.dissipation << ',' << s.dissipation_total << ',' << s.work_total << ',' << s.stored
    << ',' << s.temperature << '\n';
}

std::string system_simulation_csv_header(int n_points) {
  std::string h = "step,t";
  for (int i = 1; i <= n_points; ++i)
    for (const char* c : {"F_T", "F_N", "P_T", "P_N", "w_T", "w_N", "w_w", "w_Ti", "g", "state",
                          "type", "temperature"})
      h += std::string(",") + c + '_' + std::to_string(i);
  return h + ",count,complete,dissipation_total,work_total,stored\n";
}

void write_system_simulation_csv_row(std::ostream& f, const SystemSimulationSample& x) {
  f << x.step << ',' << x.t;
  for (Eigen::Index i = 0; i < x.P_N.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    f << ',' << x.F[2 * i] << ',' << x.F[2 * i + 1] << ',' << x.P_T[i] << ',' << x.P_N[i] << ','
      << x.w[2 * i] << ',' << x.w[2 * i + 1] << ',' << x.w_w[i] << ',' << x.w_Ti[i] << ','
      << x.g[i] << ',' << to_string(x.state[k]) << ',' << to_string(x.type[k]) << ','
      << x.temperature[i];
  }
  f << ',' << x.count << ',' << (x.complete ? 1 : 0) << ',' << x.dissipation_total << ','
    << x.work_total << ',' << x.stored << '\n';
}

std::string fretting_3d_csv_header() {
  return "step,t,F_TX,F_TY,F_N,P_TX,P_TY,P_N,g,w_TX,w_TY,w_N,w_TiX,w_TiY,Dw_TiX,Dw_TiY,lambda,"
         "Dw_w,w_w,type,count,complete,dissipation,cycle\n";
}

void write_fretting_3d_csv_row(std::ostream& f, const Fretting3dSample& s) {
  f << s.step << ',' << s.t << ',' << s.F_T(0) << ',' << s.F_T(1) << ',' << s.F_N << ','
    << s.P_T(0) << ',' << s.P_T(1) << ',' << s.P_N << ',' << s.g << ',' << s.w_T(0) << ','
    << s.w_T(1) << ',' << s.w_N << ',' << s.w_Ti(0) << ',' << s.w_Ti(1) << ',' << s.Dw_Ti(0)
    << ',' << s.Dw_Ti(1) << ',' << s.lambda << ',' << s.Dw_w << ',' << s.w_w << ','
    << to_string(s.type) << ',' << s.count << ',' << (s.complete ? 1 : 0) << ','
    << s.dissipation << ',' << s.cycle << '\n';
}

std::ofstream open_output(const std::string& path) {
  const auto dir = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  std::ofstream f(path);
  if (!f) throw InputError("cannot write '" + path + "'");
  return f;
}

void finish_output(std::ofstream& f, const std::string& path) {
  f.flush();
  if (!f) throw InputError("error writing '" + path + "' (disk full or not writable?)");
}

}  // namespace cpkit::rate
