#pragma once
// What the host offers every plugin (mhd_host): a monotonic clock and the scene file it
// runs. (Simulated plugins share their world among themselves: libs/sim_world.)
// Plugins keep the mhd_host pointer they get in open(),
// so a HostServices must outlive every instance opened with it and cannot move.

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

struct mhd_host;  // mhd/plugin_abi.h; the engine passes it to plugins and never reads it

namespace mhd {

class HostServices {
 public:
  HostServices();
  HostServices(const HostServices&) = delete;
  HostServices& operator=(const HostServices&) = delete;
  HostServices(HostServices&&) = delete;
  HostServices& operator=(HostServices&&) = delete;
  ~HostServices();

  /// The table handed to open(); abi_version and struct_size are this host's.
  [[nodiscard]] const mhd_host& abi() const noexcept { return *host_; }

  /// Seconds on the steady clock since this object was made (the host clock plugins see).
  [[nodiscard]] double now_s() const noexcept;

  /// The root scene file plugins see as mhd_host::scene_file (kept as an absolute path);
  /// set before opening plugins. Empty: none.
  void set_scene_file(const std::filesystem::path& scene_file);
  [[nodiscard]] const std::string& scene_file() const noexcept { return scene_file_; }

 private:
  std::chrono::steady_clock::time_point epoch_;
  std::unique_ptr<mhd_host> host_;
  std::string scene_file_;
};

}  // namespace mhd
