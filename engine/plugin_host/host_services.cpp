#include "plugin_host/host_services.h"

#include <mhd/plugin_abi.h>

namespace mhd {
namespace {

double now_s_callback(void* context) { return static_cast<const HostServices*>(context)->now_s(); }

}  // namespace

HostServices::HostServices()
    : epoch_(std::chrono::steady_clock::now()),
      host_(std::make_unique<mhd_host>(
          mhd_host{MHD_PLUGIN_ABI_VERSION, static_cast<uint32_t>(sizeof(mhd_host)), &now_s_callback, this, nullptr})) {}

HostServices::~HostServices() = default;

void HostServices::set_scene_file(const std::filesystem::path& scene_file) {
  scene_file_ = scene_file.empty() ? std::string() : std::filesystem::absolute(scene_file).lexically_normal().string();
  host_->scene_file = scene_file_.empty() ? nullptr : scene_file_.c_str();
}

double HostServices::now_s() const noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

}  // namespace mhd
