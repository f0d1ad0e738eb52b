// A base for tests/dds_server: stands still at the origin and keeps every command it gets
// with the command's time stamp (the host clock, as the server's recording), written at
// close to `command_log` as lines "<timestamp_s> <vx_mps> <vz_mps> <omega_radps>". So a
// test sees when the server stopped the base, not only that it ended stopped.
#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

class LogBase {
 public:
  static constexpr std::array kParams{
      mhd::sdk::text("command_log", nullptr, "where every command is logged"),
  };

  LogBase(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), command_log_(params.optional_text("command_log").value_or("")) {
    commands_.reserve(1 << 16);  // 100 minutes of commands at 10 Hz: base_write does not allocate
  }
  LogBase(const LogBase&) = delete;
  LogBase& operator=(const LogBase&) = delete;
  ~LogBase() {
    if (command_log_.empty()) return;
    if (std::FILE* f = std::fopen(command_log_.c_str(), "w")) {
      for (const mhd_base_command& c : commands_) {
        std::fprintf(f, "%.9f %.17g %.17g %.17g\n", c.timestamp_s, c.vx_mps, c.vz_mps, c.omega_radps);
      }
      std::fclose(f);
    }
  }

  void base_read(mhd_base_state& out) {
    out = {};
    out.timestamp_s = mhd::sdk::host_now(host_);
  }
  void base_write(const mhd_base_command& c) {
    if (commands_.size() == commands_.capacity()) throw std::runtime_error("command log full");
    commands_.push_back(c);
  }

 private:
  mhd_host host_;
  std::string command_log_;
  std::vector<mhd_base_command> commands_;
};

}  // namespace

MHD_PLUGIN_ENTRY(LogBase, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                           .description = "test base that logs every command with its time"})
