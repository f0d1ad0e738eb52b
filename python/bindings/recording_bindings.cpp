// Haptic server recordings (engine/recording) from Python, as one NumPy structured array:
// a record per tick, one field per CSV column with the column's name (t_s, hip_x_m,
// force_x_N, contact, ...). The rows the engine's reader returns become the array's buffer
// as they are (the dtype describes RecordingRow's memory), so no row is copied or boxed.

#include "bindings.h"
#include "engine_error.h"

#include "recording/csv_recording.h"
#include "recording/csv_recording_reader.h"
#include "recording/recording_row.h"

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <utility>
#include <optional>
#include <vector>

namespace py = pybind11;

namespace mhd::python {
namespace {

struct Field {
  std::string_view name;  ///< the CSV column
  std::size_t offset;     ///< in RecordingRow
  const char* format;     ///< NumPy type code
};

constexpr std::size_t kD = sizeof(double);

// In the CSV's column order (recording_csv_header()); a test compares the two.
const std::array<Field, 31> kFields{{
    {"t_s", offsetof(RecordingRow, t_s), "f8"},
    {"dt_s", offsetof(RecordingRow, dt_s), "f8"},
    {"tool_D_x_m", offsetof(RecordingRow, p_D_tool_m), "f8"},
    {"tool_D_y_m", offsetof(RecordingRow, p_D_tool_m) + kD, "f8"},
    {"tool_D_z_m", offsetof(RecordingRow, p_D_tool_m) + 2 * kD, "f8"},
    {"hip_x_m", offsetof(RecordingRow, p_W_hip), "f8"},
    {"hip_y_m", offsetof(RecordingRow, p_W_hip) + kD, "f8"},
    {"hip_z_m", offsetof(RecordingRow, p_W_hip) + 2 * kD, "f8"},
    {"proxy_x_m", offsetof(RecordingRow, proxy_W_m), "f8"},
    {"proxy_y_m", offsetof(RecordingRow, proxy_W_m) + kD, "f8"},
    {"proxy_z_m", offsetof(RecordingRow, proxy_W_m) + 2 * kD, "f8"},
    {"force_x_N", offsetof(RecordingRow, force_W_N), "f8"},
    {"force_y_N", offsetof(RecordingRow, force_W_N) + kD, "f8"},
    {"force_z_N", offsetof(RecordingRow, force_W_N) + 2 * kD, "f8"},
    {"cmd_force_x_N", offsetof(RecordingRow, cmd_force_W_N), "f8"},
    {"cmd_force_y_N", offsetof(RecordingRow, cmd_force_W_N) + kD, "f8"},
    {"cmd_force_z_N", offsetof(RecordingRow, cmd_force_W_N) + 2 * kD, "f8"},
    {"force_D_x_N", offsetof(RecordingRow, force_D_N), "f8"},
    {"force_D_y_N", offsetof(RecordingRow, force_D_N) + kD, "f8"},
    {"force_D_z_N", offsetof(RecordingRow, force_D_N) + 2 * kD, "f8"},
    {"base_x_m", offsetof(RecordingRow, base_x_m), "f8"},
    {"base_z_m", offsetof(RecordingRow, base_z_m), "f8"},
    {"base_heading_rad", offsetof(RecordingRow, base_heading_rad), "f8"},
    {"user_x_m", offsetof(RecordingRow, user_x_m), "f8"},
    {"user_z_m", offsetof(RecordingRow, user_z_m), "f8"},
    {"user_heading_rad", offsetof(RecordingRow, user_heading_rad), "f8"},
    {"tracker_age_s", offsetof(RecordingRow, tracker_age_s), "f8"},
    {"safety_gain", offsetof(RecordingRow, safety_gain), "f8"},
    {"contact", offsetof(RecordingRow, contact), "u1"},
    {"contact_object", offsetof(RecordingRow, contact_object), "i4"},
    {"lift_m", offsetof(RecordingRow, lift_m), "f8"},
}};

py::dtype recording_dtype() {
  py::list names, formats, offsets;
  for (const Field& f : kFields) {
    names.append(py::str(f.name.data(), f.name.size()));
    formats.append(f.format);
    offsets.append(f.offset);
  }
  return py::dtype(names, formats, offsets, static_cast<py::ssize_t>(sizeof(RecordingRow)));
}

py::array read(const std::filesystem::path& file) {
  std::optional<Result<std::vector<RecordingRow>>> read;
  {
    py::gil_scoped_release unlocked;
    read.emplace(read_recording(file));
  }
  if (!read->ok()) throw EngineError(read->error());
  // The array borrows the rows' memory; the capsule frees it with the array.
  auto* rows = new std::vector<RecordingRow>(std::move(*read).value());
  const py::capsule owner(rows, [](void* p) { delete static_cast<std::vector<RecordingRow>*>(p); });
  return py::array(recording_dtype(), {static_cast<py::ssize_t>(rows->size())}, {}, rows->data(), owner);
}

}  // namespace

void bind_recording(py::module_& m) {
  m.def("read_recording", &read, py::arg("file"),
        "Reads a haptic server recording (`mhd run --record`, docs/haptic_server.md) into a NumPy structured "
        "array, one record per tick, one field per CSV column (rec['force_x_N']). Start-up rows have nan HIP "
        "and proxy and tracker_age_s -1. A bad file is an MhdError at file:line.");
  m.def("recording_dtype", &recording_dtype, "The structured dtype of read_recording's arrays.");
  m.def("recording_columns", [] { return std::string(recording_csv_header()); },
        "The recording CSV's header line, as the server writes it.");
}

}  // namespace mhd::python
