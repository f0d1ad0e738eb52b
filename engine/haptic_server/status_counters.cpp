#include "haptic_server/status_counters.h"

namespace mhd {

ServerStatus StatusCounters::snapshot(double elapsed_s, std::uint64_t ticks_before, double window_s) {
  ServerStatus s;
  s.elapsed_s = elapsed_s;
  s.ticks = ticks.load();
  s.haptic_rate_hz = window_s > 0.0 ? static_cast<double>(s.ticks - ticks_before) / window_s : 0.0;
  s.overruns = overruns.load();
  s.in_contact = in_contact.load();
  s.force_N = force_N.load();
  s.safety_gain = safety_gain.load();
  s.tracker_age_s = tracker_age_s.load();
  s.tracker_samples = tracker_samples.load();
  s.tracker_rejected = tracker_rejected.load();
  s.tracker_plugin_counters = tracker_plugin_counters.latest().to_vector();
  s.early_ticks = early_ticks.load();
  s.base = base.get();
  return s;
}

}  // namespace mhd
