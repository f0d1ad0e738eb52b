// null_display: the smallest useful MHD plugin, written as a third party would. A
// display that draws nothing and counts the frames it is given; with verbose=true it
// prints the count to stderr on stop. It includes only the installed SDK headers
// (<mhd/plugin_sdk.hpp> over <mhd/plugin_abi.h>) and builds either with mhd_add_plugin
// (CMakeLists.txt) or with plain g++ -std=c++20 (docs/plugins.md).

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdio>

namespace null_display {

class NullDisplay {
 public:
  // The host checks a scene's parameters against this before open() (mhd validate too).
  static constexpr std::array kParams{
      mhd::sdk::boolean("verbose", "false", "print the frame count to stderr on stop")};

  explicit NullDisplay(const mhd::sdk::Params& params) : verbose_(params.boolean("verbose")) {}

  void stop() {
    if (verbose_) std::fprintf(stderr, "null_display: %llu frames\n", frames_);
  }
  void display_write(const mhd_display_frame& /*frame*/) { ++frames_; }

 private:
  bool verbose_;
  unsigned long long frames_ = 0;
};

}  // namespace null_display

// The name must match the file name: libmhd_null_display.so.
MHD_PLUGIN_ENTRY(null_display::NullDisplay,
                 {.kind = MHD_KIND_DISPLAY, .name = "null_display", .version = "1.0.0",
                  .description = "Draws nothing; counts frames (verbose=true prints the count on stop)"})
