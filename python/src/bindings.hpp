#pragma once
// One function per concept adds its part of the module (module.cpp calls them in order).
#include <pybind11/pybind11.h>

namespace cpkit::py {
void bind_lcp(pybind11::module_& m);
void bind_lcp_batch(pybind11::module_& m);  // solve_batch (bind_lcp_batch.cpp)
void bind_mcp(pybind11::module_& m);
void bind_rate(pybind11::module_& m);
void bind_maps(pybind11::module_& m);
void bind_step(pybind11::module_& m);
void bind_simulation(pybind11::module_& m);  // simulate, load histories (bind_simulation.cpp)
void bind_system(pybind11::module_& m);
void bind_system_rate(pybind11::module_& m);
void bind_rate_3d(pybind11::module_& m);   // the 3-D rate problem (bind_rate_3d.cpp)
void bind_maps_3d(pybind11::module_& m);   // maps of a 3-D system (bind_maps_3d.cpp)
void bind_step_3d(pybind11::module_& m);   // the 3-D step and fretting (bind_step_3d.cpp)
void bind_friction(pybind11::module_& m);  // 3-D frictional contact (bind_friction.cpp)
}  // namespace cpkit::py
