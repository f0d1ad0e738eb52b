#pragma once
// The parts of the `mhd._mhd` extension module, one concept per file; module.cpp calls
// each bind_* once, in this order (later parts use the classes earlier ones register).

#include <pybind11/pybind11.h>

namespace mhd::python {

void bind_errors(pybind11::module_& m);     // errors.cpp: MhdError, Diagnostic
void bind_scene(pybind11::module_& m);      // scene_bindings.cpp: read, validate, compile
void bind_proxy(pybind11::module_& m);      // proxy_bindings.cpp: the god-object proxy over arrays
void bind_plan_sim(pybind11::module_& m);   // plan_sim_bindings.cpp: planner simulator cases and maps
void bind_recording(pybind11::module_& m);  // recording_bindings.cpp: recordings as structured arrays
void bind_server(pybind11::module_& m);     // server_bindings.cpp: the haptic server for N seconds

}  // namespace mhd::python
