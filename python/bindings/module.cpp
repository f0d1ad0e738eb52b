// The `mhd._mhd` extension module: the engine's C++ API for Python. The `mhd` package
// (python/mhd/__init__.py) re-exports it with the pure-Python helpers.

#include "bindings.h"

PYBIND11_MODULE(_mhd, m) {
  m.doc() = "MHD's engine from Python: scenes, the god-object proxy, the planner simulator, recordings and "
            "the haptic server (docs/python.md).";
  mhd::python::bind_errors(m);
  mhd::python::bind_scene(m);
  mhd::python::bind_proxy(m);
  mhd::python::bind_plan_sim(m);
  mhd::python::bind_recording(m);
  mhd::python::bind_server(m);
}
