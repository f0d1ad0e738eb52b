#include "plugin_host/host_services.h"

namespace mhd {
namespace {

double now_s_callback(void* context) { return static_cast<const HostServices*>(context)->now_s(); }

}  // namespace

HostServices::HostServices(const mhd_sim_world* sim_world) noexcept
    : epoch_(std::chrono::steady_clock::now()),
      host_{MHD_PLUGIN_ABI_VERSION, static_cast<uint32_t>(sizeof(mhd_host)), &now_s_callback,
            this, sim_world} {}

double HostServices::now_s() const noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

}  // namespace mhd
