#include "sim_common/plugin_shell.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace mhd::plugin_support {

void set_error(mhd_error* err, std::string_view message) noexcept {
  if (err == nullptr) return;
  const std::size_t n = std::min(message.size(), sizeof(err->message) - 1);
  std::memcpy(err->message, message.data(), n);
  err->message[n] = '\0';
}

void check_host(const mhd_host* host) {
  if (host == nullptr) throw std::runtime_error("the host table is NULL");
  if (host->abi_version != MHD_PLUGIN_ABI_VERSION) {
    throw std::runtime_error("host ABI version " + std::to_string(host->abi_version) + " is not " +
                             std::to_string(MHD_PLUGIN_ABI_VERSION));
  }
  if (host->struct_size < sizeof(mhd_host)) {
    throw std::runtime_error("host table is " + std::to_string(host->struct_size) + " bytes, expected at least " +
                             std::to_string(sizeof(mhd_host)));
  }
  if (host->now_s == nullptr) throw std::runtime_error("the host gives no clock (now_s is NULL)");
}

void check_sim_world(const mhd_host& host) {
  const mhd_sim_world* w = host.sim_world;
  if (w == nullptr) return;
  if (w->get_base_pose == nullptr || w->set_base_pose == nullptr || w->get_hand == nullptr || w->set_hand == nullptr ||
      w->get_head == nullptr || w->set_head == nullptr) {
    throw std::runtime_error("the host's simulated world has a NULL function");
  }
}

double host_now(const mhd_host& host) {
  const double t = host.now_s(host.clock_context);
  if (!std::isfinite(t)) throw std::runtime_error("the host clock returned a non-finite time");
  return t;
}

}  // namespace mhd::plugin_support
