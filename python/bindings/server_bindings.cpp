// The haptic server from Python: run_server() opens a compiled scene's plugins (simulated
// ones, or whatever the scene names), runs every thread for duration_s and returns the
// report, as `mhd run --duration` does. The run holds no GIL; Ctrl-C (SIGINT, seen by
// Python's handler) ends it safely and raises KeyboardInterrupt after. A run a fault ended
// raises MhdError naming the plugin and its scene line, with the report attached.

#include "bindings.h"
#include "engine_error.h"
#include "scene_handles.h"

#include "haptic_server/haptic_server.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mhd::python {
namespace {

/// How often the run looks at Python's signal flags.
constexpr double kSignalPoll_s = 0.1;

const char* ended_by_name(RunEnd end) {
  switch (end) {
    case RunEnd::Duration: return "duration";
    case RunEnd::StopRequested: return "stop_requested";
    case RunEnd::Fault: return "fault";
  }
  return "unknown";
}

py::tuple base_pose(const BasePose& b) { return py::make_tuple(b.x_m, b.z_m, b.heading_rad); }

ServerReport run_server(const CompiledSceneHandle& scene, double duration_s,
                        const std::optional<std::filesystem::path>& recording,
                        const std::vector<std::filesystem::path>& plugin_path) {
  if (!(std::isfinite(duration_s) && duration_s > 0.0)) throw py::value_error("duration_s must be finite and > 0");
  ServerOptions options;
  options.duration_s = duration_s;
  if (recording) options.recording = *recording;
  options.plugin_path = plugin_path;
  HapticServer* running = nullptr;
  py::object signal_type, signal_value, signal_traceback;  // what a signal handler raised
  // Called on this (the calling) thread while run() runs: the moment to let Python see a signal.
  options.on_status = [&](const ServerStatus&) {
    const py::gil_scoped_acquire locked;
    if (PyErr_CheckSignals() != 0) {
      // Raised again once the server is safely stopped.
      PyObject *type = nullptr, *value = nullptr, *traceback = nullptr;
      PyErr_Fetch(&type, &value, &traceback);
      signal_type = py::reinterpret_steal<py::object>(type);
      signal_value = py::reinterpret_steal<py::object>(value);
      signal_traceback = py::reinterpret_steal<py::object>(traceback);
      if (running != nullptr) running->request_stop();
    }
  };
  options.status_interval_s = kSignalPoll_s;

  Diagnostics errors;
  ServerReport report;
  {
    py::gil_scoped_release unlocked;
    Result<OpenedServer> build = HapticServer::open(*scene.description, *scene.compiled, std::move(options));
    if (build.ok()) {
      running = build->server.get();
      report = build->server->run();
      running = nullptr;
      build->server.reset();  // closes the plugins before Python sees the report
    } else {
      errors = build.error();
    }
  }
  if (!errors.empty()) throw EngineError(std::move(errors));
  if (signal_type) {
    PyErr_Restore(signal_type.release().ptr(), signal_value.release().ptr(), signal_traceback.release().ptr());
    throw py::error_already_set();
  }
  if (report.error) throw EngineError(*report.error, {}, report);
  return report;
}

}  // namespace

void bind_server(py::module_& m) {
  py::class_<ServerStatus>(m, "ServerStatus", "The server's state at the end of a run.")
      .def_readonly("elapsed_s", &ServerStatus::elapsed_s)
      .def_readonly("ticks", &ServerStatus::ticks)
      .def_readonly("haptic_rate_hz", &ServerStatus::haptic_rate_hz)
      .def_readonly("overruns", &ServerStatus::overruns)
      .def_readonly("in_contact", &ServerStatus::in_contact)
      .def_readonly("force_N", &ServerStatus::force_N)
      .def_readonly("safety_gain", &ServerStatus::safety_gain)
      .def_readonly("tracker_age_s", &ServerStatus::tracker_age_s)
      .def_readonly("tracker_samples", &ServerStatus::tracker_samples)
      .def_readonly("tracker_rejected", &ServerStatus::tracker_rejected)
      .def_readonly("early_ticks", &ServerStatus::early_ticks)
      .def_property_readonly("base", [](const ServerStatus& s) { return base_pose(s.base); },
                             "(x_m, z_m, heading_rad) of the base");

  py::class_<ServerReport>(m, "ServerReport", "What a haptic server run did (the summary `mhd run` prints).")
      .def_readonly("status", &ServerReport::status)
      .def_property_readonly("ended_by", [](const ServerReport& r) { return ended_by_name(r.ended_by); },
                             "'duration', 'stop_requested' or 'fault'")
      .def_readonly("missed_deadlines", &ServerReport::missed_deadlines)
      .def_readonly("tick_median_us", &ServerReport::tick_median_us)
      .def_readonly("tick_p99_us", &ServerReport::tick_p99_us)
      .def_readonly("tick_p999_us", &ServerReport::tick_p999_us)
      .def_readonly("tick_max_us", &ServerReport::tick_max_us)
      .def_readonly("contact_ticks", &ServerReport::contact_ticks)
      .def_readonly("proxy_budget_exhausted_ticks", &ServerReport::proxy_budget_exhausted_ticks)
      .def_readonly("startup_ticks", &ServerReport::startup_ticks)
      .def_readonly("stale_ticks", &ServerReport::stale_ticks)
      .def_readonly("fault_ticks", &ServerReport::fault_ticks)
      .def_readonly("hip_jumps", &ServerReport::hip_jumps)
      .def_readonly("clamped_ticks", &ServerReport::clamped_ticks)
      .def_readonly("base_commands", &ServerReport::base_commands)
      .def_readonly("base_stops", &ServerReport::base_stops)
      .def_readonly("recording_rows", &ServerReport::recording_rows)
      .def_readonly("recording_dropped", &ServerReport::recording_dropped)
      .def_readonly("zero_force_sent", &ServerReport::zero_force_sent)
      .def_readonly("base_stop_sent", &ServerReport::base_stop_sent)
      .def_readonly("haptic_scheduling", &ServerReport::haptic_scheduling)
      .def_readonly("error", &ServerReport::error);

  m.def("run_server", &run_server, py::arg("scene"), py::arg("duration_s"), py::arg("recording") = py::none(),
        py::arg("plugin_path") = std::vector<std::filesystem::path>{},
        "Runs the haptic server on the compiled scene's plugins for duration_s seconds (docs/haptic_server.md), "
        "recording every tick to `recording` if given, and returns the ServerReport. Plugins are found as "
        "`mhd run` finds them (plugin_path first, then $MHD_PLUGIN_PATH, then the build tree). A scene the "
        "server cannot open, or a run a fault ended, raises MhdError (file:line, the plugin named).");
}

}  // namespace mhd::python
