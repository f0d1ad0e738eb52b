// A tracker returning two samples per read, with tracker_wait (data is always there, or
// never with no_data) and two counters (reads so far, a fixed 7). Param
// mode=ok|no_data|too_many|bad_quat|nan|bad_counter breaks one call in one way.
#include <mhd/plugin_abi.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <new>

namespace {

enum class Mode { Ok, NoData, TooMany, BadQuat, Nan, BadCounter };

struct Tracker {
  Mode mode = Mode::Ok;
  uint64_t sequence = 0;
  uint64_t reads = 0;
};

Tracker* tracker_of(mhd_plugin_instance* self) { return reinterpret_cast<Tracker*>(self); }

mhd_plugin_instance* tracker_open(const mhd_host*, const mhd_param* params, size_t count, mhd_error* err) {
  Tracker t;
  for (size_t i = 0; i < count; ++i) {
    const char* v = params[i].value;
    if (std::strcmp(params[i].name, "mode") != 0) {
      std::snprintf(err->message, sizeof(err->message), "unknown parameter '%s'", params[i].name);
      return nullptr;
    }
    if (std::strcmp(v, "no_data") == 0) t.mode = Mode::NoData;
    else if (std::strcmp(v, "too_many") == 0) t.mode = Mode::TooMany;
    else if (std::strcmp(v, "bad_quat") == 0) t.mode = Mode::BadQuat;
    else if (std::strcmp(v, "nan") == 0) t.mode = Mode::Nan;
    else if (std::strcmp(v, "bad_counter") == 0) t.mode = Mode::BadCounter;
  }
  return reinterpret_cast<mhd_plugin_instance*>(new (std::nothrow) Tracker(t));
}

mhd_status tracker_start(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
mhd_status tracker_stop(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
void tracker_close(mhd_plugin_instance* self) { delete tracker_of(self); }

mhd_status tracker_read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                        mhd_error*) {
  Tracker* t = tracker_of(self);
  ++t->reads;
  if (t->mode == Mode::NoData) {
    *count = 0;
    return MHD_NO_DATA;
  }
  size_t n = 0;
  for (; n < 2 && n < capacity; ++n) {
    mhd_tracker_sample& s = out[n];
    s = mhd_tracker_sample{};
    s.sensor_id = static_cast<uint32_t>(n);
    s.sequence = ++t->sequence;
    s.timestamp_s = 1.0;
    s.p_T_m[0] = 0.1 * static_cast<double>(n);
    s.q_T_wxyz[0] = 1.0;
  }
  if (t->mode == Mode::BadQuat && n > 0) out[0].q_T_wxyz[0] = 2.0;
  if (t->mode == Mode::Nan && n > 1) out[1].p_T_m[2] = std::numeric_limits<double>::quiet_NaN();
  *count = t->mode == Mode::TooMany ? capacity + 1 : n;
  return MHD_OK;
}

mhd_status tracker_wait(mhd_plugin_instance* self, double /*timeout_s*/, mhd_error*) {
  return tracker_of(self)->mode == Mode::NoData ? MHD_NO_DATA : MHD_OK;
}

mhd_status counters(mhd_plugin_instance* self, mhd_counter* out, size_t capacity, size_t* count, mhd_error*) {
  const Tracker* t = tracker_of(self);
  const mhd_counter all[2] = {{"reads", t->reads}, {t->mode == Mode::BadCounter ? "has space" : "dropped_test", 7}};
  for (size_t i = 0; i < 2 && i < capacity; ++i) out[i] = all[i];
  *count = 2;
  return MHD_OK;
}

mhd_plugin_api make_api() {
  mhd_plugin_api api{};
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_PLUGIN_KIND;
  api.name = MHD_PLUGIN_NAME;
  api.version = "0.1.0";
  api.open = tracker_open;
  api.start = tracker_start;
  api.stop = tracker_stop;
  api.close = tracker_close;
  static const mhd_param_decl params[] = {
      {"mode", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "how tracker_read misbehaves"},
  };
  api.params = params;
  api.param_count = 1;
  api.tracker_read = tracker_read;
  api.tracker_wait = tracker_wait;
  api.counters = counters;
  return api;
}

}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = make_api();
  return &api;
}
