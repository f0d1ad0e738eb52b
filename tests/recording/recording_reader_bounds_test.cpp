// read_recording within bounds: a device, a FIFO and a folder are refused without being
// read (a FIFO would block, /dev/zero never end), and a file without line ends is refused
// at its first line instead of being read whole. The dual: a good recording still reads.
#include "recording/csv_recording.h"
#include "recording/csv_recording_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path fresh_dir() {
  const fs::path dir = fs::temp_directory_path() / ("mhd_recording_bounds_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string first_error(const mhd::Result<std::vector<mhd::RecordingRow>>& r) {
  return r.ok() || r.diagnostics().empty() ? std::string() : r.diagnostics()[0].to_string();
}

TEST(RecordingReaderBounds, DevicesFifosAndFoldersAreRefusedUnread) {
  const fs::path dir = fresh_dir();
  const fs::path fifo = dir / "pipe.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const fs::path& p : {fs::path("/dev/zero"), fifo, dir}) {
    const auto r = mhd::read_recording(p);
    EXPECT_FALSE(r.ok()) << p;
    EXPECT_THAT(first_error(r), HasSubstr("not a regular file")) << p;
  }
  fs::remove_all(dir);
}

TEST(RecordingReaderBounds, AFileWithoutLineEndsIsRefusedAtItsFirstLine) {
  const fs::path dir = fresh_dir();
  const fs::path zeros = dir / "zeros.csv";
  std::ofstream(zeros, std::ios::binary) << std::string(3 << 20, '\0');
  const auto r = mhd::read_recording(zeros);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(first_error(r), zeros.string() + ":1: error: a line longer than 65536 bytes: not a recording");
  fs::remove_all(dir);
}

TEST(RecordingReaderBounds, AGoodRecordingLongerThanOneReadBlockIsReadWhole) {
  const fs::path dir = fresh_dir();
  const fs::path file = dir / "good.csv";
  constexpr int kRows = 8000;  // several MiB: more than one read block
  {
    std::ofstream out(file);
    out << mhd::recording_csv_header() << "\n";
    const std::size_t columns = static_cast<std::size_t>(std::count(
                                    mhd::recording_csv_header().begin(), mhd::recording_csv_header().end(), ',')) + 1;
    for (int i = 0; i < kRows; ++i) {
      out << i * 0.001;
      for (std::size_t c = 1; c < columns; ++c) out << ",0.123456789012345";
      out << "\n";
    }
  }
  ASSERT_GT(fs::file_size(file), 1u << 20);
  const auto r = mhd::read_recording(file);
  ASSERT_TRUE(r.ok()) << first_error(r);
  ASSERT_EQ(r->size(), static_cast<std::size_t>(kRows));
  EXPECT_DOUBLE_EQ(r->back().t_s, (kRows - 1) * 0.001);
  fs::remove_all(dir);
}

}  // namespace
