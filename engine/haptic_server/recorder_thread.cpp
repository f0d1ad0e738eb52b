// The recorder thread: the haptic thread's rows, with the newest head pose, to the CSV
// recording.
#include "haptic_server/server_impl.h"

#include "haptic_server/user_motion_estimate.h"
#include "realtime/thread_name.h"

#include <chrono>
#include <exception>
#include <limits>
#include <thread>

namespace mhd {

void HapticServer::Impl::recorder_thread() {
  realtime::name_current_thread("mhd-recorder");
  RecordingRow row;
  auto drain = [&] {
    while (recording_rows.pop(row)) {
      const HeadState h = head.get();
      if (h.known) {
        row.user_x_m = h.p_W_m.x();
        row.user_z_m = h.p_W_m.z();
        row.user_heading_rad = planar_heading_rad(h.q_W);
      } else {
        row.user_x_m = row.user_z_m = row.user_heading_rad = std::numeric_limits<double>::quiet_NaN();
      }
      recording->write(row);
    }
  };
  try {
    while (!recorder_stop.load(std::memory_order_acquire)) {
      drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    drain();  // what the haptic thread queued before it stopped
    recording->flush();
  } catch (const std::exception& e) {
    fail(e.what());
  }
  recording_rows_written = recording->rows();
}

}  // namespace mhd
