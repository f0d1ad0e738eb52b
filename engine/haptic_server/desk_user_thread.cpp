// The desktop rig's second thread: the simulated user's hand at the io rate, nothing
// else (no tracker to read, no base to command; the io thread does those on a mobile rig).
#include "haptic_server/server_impl.h"

#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"
#include "simulation/simulated_user.h"

namespace mhd {

void HapticServer::Impl::desk_user_thread() {
  realtime::name_current_thread("mhd-user");
  simulation::SimulatedUser user(*user_config);
  realtime::PeriodicTimer timer(1.0 / settings.io_rate_hz);
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    user.update(host.now_s(), world);
  }
}

}  // namespace mhd
