// The display thread: the newest state as a DisplayFrame to every display plugin.
#include "haptic_server/server_impl.h"

#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"

namespace mhd {

void HapticServer::Impl::display_thread() {
  realtime::name_current_thread("mhd-display");
  realtime::PeriodicTimer timer(1.0 / settings.display_rate_hz);
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    const HapticSnapshot snap = snapshot_for_display.latest();
    const HeadState h = head.get();
    DisplayFrame frame{};
    frame.timestamp_s = snap.t_s;
    for (int i = 0; i < 3; ++i) {
      frame.p_W_hip_m[i] = snap.p_W_hip[i];
      frame.p_W_proxy_m[i] = snap.proxy_W_m[i];
      frame.force_W_N[i] = snap.force_W_N[i];
      frame.p_W_head_m[i] = h.p_W_m[i];
    }
    frame.in_contact = snap.in_contact;
    frame.base_x_m = snap.base.x_m;
    frame.base_z_m = snap.base.z_m;
    frame.base_heading_rad = snap.base.heading_rad;
    frame.q_W_head_wxyz[0] = h.q_W.w();
    frame.q_W_head_wxyz[1] = h.q_W.x();
    frame.q_W_head_wxyz[2] = h.q_W.y();
    frame.q_W_head_wxyz[3] = h.q_W.z();
    for (OpenedPlugin* d : displays) {
      const InCall in_call(*d, "display_write", host.now_s());
      auto r = d->instance.display_write(frame);
      if (check(r, *d) || deactivated(r.value(), *d, "display_write")) return;
    }
  }
}

}  // namespace mhd
