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
void bind_system(pybind11::module_& m);
void bind_system_rate(pybind11::module_& m);
void bind_three_d(pybind11::module_& m);
void bind_three_d_more(pybind11::module_& m);
void bind_friction(pybind11::module_& m);  // 3-D frictional contact (bind_friction.cpp)
}  // namespace cpkit::py
