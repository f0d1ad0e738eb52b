// The replay tracker plugin: plays a recorded CSV (see replay_csv.h) on the host clock
// from start(). open() reads and checks the whole file, so a bad row fails the open
// with "FILE:LINE: ...". A relative path is relative to the host's working directory.

#include "replay_csv.h"
#include "replay_model.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <atomic>
#include <stdexcept>
#include <utility>

namespace mhd::tracker_replay {
namespace {

using plugin_support::guarded_open;

struct Instance {
  Instance(const mhd_host& h, std::vector<mhd_tracker_sample> samples) : host(h), model(std::move(samples)) {}

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  ReplayModel model;
  bool started = false;
};

constexpr std::array kParams{
    sdk::required_text("file", "the CSV of tracker samples to replay (docs/simulation.md)"),
};

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    plugin_support::ParamReader reader(kParams, params, param_count);
    const std::string file = reader.required_text("file");
    reader.reject_unknown();
    return reinterpret_cast<mhd_plugin_instance*>(new Instance(*host, read_replay_csv(file)));
  });
}

// Every instance call: find, lock and (for Need::Running) check the instance.
template <class F>
mhd_status call(mhd_plugin_instance* self, plugin_support::Need need, mhd_error* err, F&& f) {
  return plugin_support::with_instance<Instance>(MHD_PLUGIN_NAME, self, need, err, std::forward<F>(f));
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.model.start(plugin_support::host_now(s.host));
    s.started = true;
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status tracker_read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                        mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("tracker_read: NULL output");
    *count = s.model.read(plugin_support::host_now(s.host), std::span(out, capacity));
    return *count > 0 ? MHD_OK : MHD_NO_DATA;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Tracker replay: plays a recorded CSV of tracker samples on the host clock",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = tracker_read,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = nullptr,
    .simulate_until = nullptr,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::tracker_replay

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::tracker_replay::kApi : nullptr;
}
