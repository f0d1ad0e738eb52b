// MhdError and Diagnostic in Python, and the translation of EngineError into MhdError.

#include "bindings.h"
#include "engine_error.h"

#include <pybind11/stl.h>

#include <exception>
#include <utility>

namespace py = pybind11;

namespace mhd::python {

EngineError::EngineError(Diagnostics diagnostics)
    : std::runtime_error(diagnostics_text(diagnostics)), diagnostics_(std::move(diagnostics)) {}

EngineError::EngineError(const std::string& message, Diagnostics diagnostics, std::optional<ServerReport> report)
    : std::runtime_error(message), diagnostics_(std::move(diagnostics)), report_(std::move(report)) {}

std::string diagnostics_text(const Diagnostics& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (!text.empty()) text += '\n';
    text += d.to_string();
  }
  return text;
}

void bind_errors(py::module_& m) {
  py::class_<Diagnostic>(m, "Diagnostic", "A problem in user input, at the file and line where it stands.")
      .def(py::init([](std::string file, int line, std::string message) {
             return Diagnostic{SourceLocation{std::move(file), line}, std::move(message)};
           }),
           py::arg("file"), py::arg("line"), py::arg("message"))
      .def_property_readonly("file", [](const Diagnostic& d) { return d.where.file; })
      .def_property_readonly("line", [](const Diagnostic& d) { return d.where.line; }, "1-based; 0: the whole file")
      .def_readonly("message", &Diagnostic::message)
      .def("__str__", &Diagnostic::to_string)
      .def("__repr__", [](const Diagnostic& d) { return "<mhd.Diagnostic " + d.to_string() + ">"; });

  // A plain Python exception class: `except mhd.MhdError as e: e.diagnostics`.
  // Never destroyed: Python may be gone when static destructors run.
  static auto* const error_type = new py::exception<EngineError>(m, "MhdError", PyExc_Exception);
  error_type->doc() =
      "A problem the engine found in user input, or a haptic server run that ended on a fault.\n"
      "str(e) is the engine's message (file:line: error: ...); e.diagnostics lists each problem;\n"
      "e.report is the server's report when a fault ended a run, else None.";
  error_type->attr("diagnostics") = py::list();
  error_type->attr("report") = py::none();
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const EngineError& e) {
      py::object error = py::handle(error_type->ptr())(py::str(e.what()));
      error.attr("diagnostics") = py::cast(e.diagnostics());
      if (e.report()) error.attr("report") = py::cast(*e.report());
      PyErr_SetObject(error_type->ptr(), error.ptr());
    }
  });
}

}  // namespace mhd::python
