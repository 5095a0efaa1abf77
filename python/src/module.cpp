// The compiled part of the Python package cpkit (cpkit._cpkit). Users import `cpkit`, whose
// pure-Python layer (python/cpkit/) checks argument shapes, converts inputs and wraps these
// plain-dict results in picklable dataclasses. cpkit::InputError derives from
// std::invalid_argument, which pybind11 raises as ValueError with the C++ message.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_cpkit, m) {
  m.doc() = "cpkit: complementarity problems and the contact/friction/wear model (compiled part)";
  m.attr("__version__") = CPKIT_VERSION;
  cpkit::py::bind_lcp(m);
  cpkit::py::bind_lcp_batch(m);
  cpkit::py::bind_mcp(m);
  cpkit::py::bind_rate(m);
  cpkit::py::bind_maps(m);
  cpkit::py::bind_step(m);
  cpkit::py::bind_simulation(m);
  cpkit::py::bind_system(m);
  cpkit::py::bind_system_rate(m);
  cpkit::py::bind_rate_3d(m);
  cpkit::py::bind_maps_3d(m);
  cpkit::py::bind_step_3d(m);
  cpkit::py::bind_friction(m);
}
