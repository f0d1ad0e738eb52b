// A tracker for the haptic server's fault tests: each read returns one base-sensor sample
// (sensor 0) at the fixed pose given by param pose="px py pz qw qx qy qz" (tracker
// frame, metres), stamped now, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Tracker {
  fault_injection::Instance base;  // first: fault_injection's calls see this
  double pose[7] = {0, 0, 0, 1, 0, 0, 0};
  uint64_t sequence = 0;
};
static_assert(offsetof(Tracker, base) == 0);

Tracker* of(mhd_plugin_instance* self) { return reinterpret_cast<Tracker*>(self); }

mhd_plugin_instance* tracker_open(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  auto* t = new (std::nothrow) Tracker;
  if (t == nullptr) return nullptr;
  t->base.host = host;
  std::vector<mhd_param> rest;
  for (size_t i = 0; i < count; ++i) {
    if (std::string(params[i].name) != "pose") {
      rest.push_back(params[i]);
      continue;
    }
    double* p = t->pose;
    if (std::sscanf(params[i].value, "%lf %lf %lf %lf %lf %lf %lf", &p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6]) != 7) {
      fault_injection::fail(err, "pose needs 7 numbers");
      delete t;
      return nullptr;
    }
  }
  if (!fault_injection::parse(t->base.config, rest.data(), rest.size(), err)) {
    delete t;
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(t);
}

void tracker_close(mhd_plugin_instance* self) { delete of(self); }

mhd_status read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count, mhd_error* err) {
  Tracker& t = *of(self);
  *count = 0;
  bool nan = false;
  const mhd_status s = fault_injection::next_read(t.base.config, nan, err);
  if (s != MHD_OK) return s;
  if (capacity == 0) return MHD_NO_DATA;
  mhd_tracker_sample& sample = out[0];
  sample = {};
  sample.sensor_id = 0;
  sample.sequence = ++t.sequence;
  sample.timestamp_s = t.base.host->now_s(t.base.host->clock_context);
  for (int i = 0; i < 3; ++i) sample.p_T_m[i] = t.pose[i];
  for (int i = 0; i < 4; ++i) sample.q_T_wxyz[i] = t.pose[3 + i];
  *count = 1;
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = fault_injection::base_table(MHD_KIND_TRACKER, "fault_tracker");
    a.open = tracker_open;
    a.close = tracker_close;
    a.tracker_read = read;
    static const mhd_param_decl params[] = {
        fault_injection::kParams[0], fault_injection::kParams[1], fault_injection::kParams[2],
        fault_injection::kParams[3],
        {"pose", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "px py pz qw qx qy qz, tracker frame"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    return a;
  }();
  return &api;
}
