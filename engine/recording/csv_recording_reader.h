#pragma once
// Reads a recording written by CsvRecording (csv_recording.h) back into rows. Columns are
// found by name, so extra columns are ignored; a missing column, a short row or a number
// that does not parse is an error naming the file and line.

#include "recording/recording_row.h"
#include "diagnostics/result.h"

#include <filesystem>
#include <vector>

namespace mhd {

/// Every row, or the first problem found (no rows then). A last line without its newline (a recording cut short by a crash) is skipped, not an
/// error: everything up to the last complete line is read.
[[nodiscard]] Result<std::vector<RecordingRow>> read_recording(const std::filesystem::path& file);

}  // namespace mhd
