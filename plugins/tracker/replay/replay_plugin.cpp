// The replay tracker plugin: plays a recorded CSV (see replay_csv.h) on the host clock
// from start(). open() reads and checks the whole file, so a bad row fails the open
// with "FILE:LINE: ...". A relative path is relative to the host's working directory.

#include "replay_csv.h"
#include "replay_model.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <span>

namespace mhd::tracker_replay {

class ReplayPlugin {
 public:
  static constexpr std::array kParams{
      sdk::required_text("file", "the CSV of tracker samples to replay (docs/simulation.md)"),
  };

  ReplayPlugin(const mhd_host& host, const sdk::Params& params)
      : host_(host), model_(read_replay_csv(params.text("file"))) {}

  void start() { model_.start(sdk::host_now(host_)); }
  std::size_t tracker_read(std::span<mhd_tracker_sample> out) { return model_.read(sdk::host_now(host_), out); }

 private:
  mhd_host host_;
  ReplayModel model_;
};

}  // namespace mhd::tracker_replay

MHD_PLUGIN_ENTRY(mhd::tracker_replay::ReplayPlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Tracker replay: plays a recorded CSV of tracker samples on the host clock"})
