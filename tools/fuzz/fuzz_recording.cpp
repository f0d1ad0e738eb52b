// libFuzzer target: the haptic server's recording reader (engine/recording/
// csv_recording_reader.h), which `mhd replay` and Python's mhd.read_recording share.
//
// Invariants (a violation traps):
//  - read_recording() returns rows or diagnostics; nothing escapes;
//  - every diagnostic names the file, and a line that exists (0 for the whole file);
//  - rows only from an input whose first line holds every recording column, and never
//    more rows than the input has complete lines after the header.
#include "recording/csv_recording_reader.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-recording: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

const std::filesystem::path& input_file() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("mhd_fuzz_recording_" + std::to_string(::getpid()) + ".csv");
  return file;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path& file = input_file();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) violated("cannot write the input file");
  }
  std::size_t lines = 0;
  for (std::size_t i = 0; i < size; ++i) lines += data[i] == '\n' ? 1u : 0u;
  try {
    const mhd::Result<std::vector<mhd::RecordingRow>> r = mhd::read_recording(file);
    if (r.ok()) {
      if (lines == 0 || r->size() > lines - 1) violated("more rows than complete lines after the header");
    } else {
      if (r.diagnostics().empty()) violated("refused without a diagnostic");
      for (const mhd::Diagnostic& d : r.diagnostics()) {
        if (d.where.file != file.string()) violated("a diagnostic names another file: " + d.where.file);
        if (d.where.line < 0 || static_cast<std::size_t>(d.where.line) > lines + 1) {
          violated("a diagnostic names line " + std::to_string(d.where.line) + " of " + std::to_string(lines));
        }
        if (d.message.empty()) violated("an empty message");
      }
    }
  } catch (const std::exception& e) {
    violated(std::string("an exception escaped: ") + e.what());
  }
  return 0;
}
