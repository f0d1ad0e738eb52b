#include "plugin_host/plugin_instance.h"

#include "plugin_host/abi_conversion.h"
#include "plugin_host/device_info_check.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/scene_plugin_check.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

namespace mhd {
namespace {

// Statuses are handled as numbers: a plugin may return any value, and reading an
// out-of-range value through the enum type would be undefined behaviour.
using StatusCode = long;

std::string status_name(StatusCode code) {
  switch (code) {
    case MHD_OK: return "MHD_OK";
    case MHD_NO_DATA: return "MHD_NO_DATA";
    case MHD_ERROR: return "MHD_ERROR";
    case MHD_DEACTIVATE: return "MHD_DEACTIVATE";
    default: return fmt::format("status {}", code);
  }
}

std::string plugin_message(const mhd_error& err) {
  const std::size_t length = strnlen(err.message, sizeof(err.message));
  return std::string(err.message, length);
}

/// "open failed: MESSAGE" or "open failed (no message)".
std::string failed(std::string_view call, const mhd_error& err) {
  const std::string text = plugin_message(err);
  return text.empty() ? fmt::format("{} failed (no message)", call) : fmt::format("{} failed: {}", call, text);
}

/// One checked group of doubles in a struct: "timestamp_s" or "p_T_m[3]".
struct Field {
  std::string_view name;
  const double* values;
  std::size_t count;  ///< 1: a scalar, named without an index
};

/// The first non-finite value among `fields`, named "p_T_m[2]" (with `prefix` before it).
std::optional<std::string> first_non_finite(std::initializer_list<Field> fields, std::string_view prefix = {}) {
  for (const Field& field : fields) {
    for (std::size_t i = 0; i < field.count; ++i) {
      if (std::isfinite(field.values[i])) continue;
      if (field.count == 1) return fmt::format("{}{}", prefix, field.name);
      return fmt::format("{}{}[{}]", prefix, field.name, i);
    }
  }
  return std::nullopt;
}

std::optional<std::string> non_finite_in(const DeviceCommand& c) {
  return first_non_finite({{"timestamp_s", &c.timestamp_s, 1},
                           {"force_D_N", c.force_D_N.data(), 3},
                           {"torque_D_Nm", c.torque_D_Nm.data(), 3}});
}

std::optional<std::string> non_finite_in(const TrackerSample& s, std::string_view prefix) {
  return first_non_finite(
      {{"timestamp_s", &s.timestamp_s, 1}, {"p_T_m", s.p_T_m.data(), 3}, {"q_T_wxyz", s.q_T_wxyz.data(), 4}}, prefix);
}

std::optional<std::string> non_finite_in(const BaseState& s) {
  return first_non_finite({{"timestamp_s", &s.timestamp_s, 1},
                           {"x_m", &s.x_m, 1},
                           {"z_m", &s.z_m, 1},
                           {"heading_rad", &s.heading_rad, 1},
                           {"vx_mps", &s.vx_mps, 1},
                           {"vz_mps", &s.vz_mps, 1},
                           {"omega_radps", &s.omega_radps, 1},
                           {"lift_m", &s.lift_m, 1},
                           {"lift_vmps", &s.lift_vmps, 1}});
}

std::optional<std::string> non_finite_in(const BaseCommand& c) {
  return first_non_finite({{"timestamp_s", &c.timestamp_s, 1},
                           {"vx_mps", &c.vx_mps, 1},
                           {"vz_mps", &c.vz_mps, 1},
                           {"omega_radps", &c.omega_radps, 1},
                           {"lift_vmps", &c.lift_vmps, 1}});
}

std::optional<std::string> non_finite_in(const DisplayFrame& f) {
  return first_non_finite({{"timestamp_s", &f.timestamp_s, 1},
                           {"p_W_hip_m", f.p_W_hip_m.data(), 3},
                           {"p_W_proxy_m", f.p_W_proxy_m.data(), 3},
                           {"force_W_N", f.force_W_N.data(), 3},
                           {"base_x_m", &f.base_x_m, 1},
                           {"base_z_m", &f.base_z_m, 1},
                           {"base_heading_rad", &f.base_heading_rad, 1},
                           {"p_W_head_m", f.p_W_head_m.data(), 3},
                           {"q_W_head_wxyz", f.q_W_head_wxyz.data(), 4}});
}

// A tracker quaternion is a unit quaternion up to this much error in its norm.
constexpr double kUnitQuaternionTolerance = 1e-3;

// What is wrong with link message `index` (named "messages[i].field"), or nothing. Formats
// only what it reports.
std::optional<std::string> link_message_problem(const LinkMessage& m, std::size_t index) {
  if (m.kind != LinkMessageKind::State && m.kind != LinkMessageKind::Push) {
    return fmt::format("an unknown messages[{}].kind {}", index, static_cast<std::uint32_t>(m.kind));
  }
  if (auto field = first_non_finite({{"timestamp_s", &m.timestamp_s, 1},
                                     {"p_W_m", m.p_W_m.data(), 3},
                                     {"q_W_wxyz", m.q_W_wxyz.data(), 4},
                                     {"v_W_mps", m.v_W_mps.data(), 3},
                                     {"w_W_radps", m.w_W_radps.data(), 3},
                                     {"f_W_N", m.f_W_N.data(), 3},
                                     {"p_O_m", m.p_O_m.data(), 3}})) {
    return fmt::format("a non-finite messages[{}].{}", index, *field);
  }
  if (m.kind == LinkMessageKind::State) {
    const std::array<double, 4>& q = m.q_W_wxyz;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(norm - 1.0) > kUnitQuaternionTolerance) {
      return fmt::format("messages[{}].q_W_wxyz of norm {}, not a unit quaternion", index, norm);
    }
  }
  return std::nullopt;
}

}  // namespace

std::string_view to_string(PluginState state) {
  switch (state) {
    case PluginState::Loaded: return "loaded";
    case PluginState::Open: return "open";
    case PluginState::Running: return "running";
    case PluginState::Stopped: return "stopped";
    case PluginState::Closed: return "closed";
  }
  return "unknown";
}

PluginInstance::PluginInstance(std::shared_ptr<const PluginLibrary> library) : library_(std::move(library)) {}

PluginInstance::~PluginInstance() { (void)close(); }

PluginInstance::PluginInstance(PluginInstance&& other) noexcept
    : library_(std::move(other.library_)),
      handle_(std::exchange(other.handle_, nullptr)),
      state_(std::exchange(other.state_, PluginState::Closed)),
      info_(other.info_) {}

PluginInstance& PluginInstance::operator=(PluginInstance&& other) noexcept {
  if (this != &other) {
    (void)close();
    library_ = std::move(other.library_);
    handle_ = std::exchange(other.handle_, nullptr);
    state_ = std::exchange(other.state_, PluginState::Closed);
    info_ = other.info_;
  }
  return *this;
}

const std::string& PluginInstance::name() const noexcept {
  static const std::string kNone;
  return library_ ? library_->name() : kNone;
}

PluginKind PluginInstance::kind() const noexcept { return library_ ? library_->kind() : PluginKind::Device; }

bool PluginInstance::simulates() const noexcept { return library_ && library_->api().simulate_until != nullptr; }

bool PluginInstance::waits() const noexcept {
  return library_ && library_->info().kind == PluginKind::Tracker && library_->api().tracker_wait != nullptr;
}

bool PluginInstance::counts() const noexcept { return library_ && library_->api().counters != nullptr; }

PluginError PluginInstance::error(PluginErrorKind kind, std::string message) const {
  return PluginError{kind, name(), {}, std::move(message)};
}

Status<PluginError> PluginInstance::check_call(std::string_view call, PluginKind needed_kind) const {
  if (library_ && kind() != needed_kind) {
    return error(PluginErrorKind::WrongKind, fmt::format("{} called on a {} plugin", call, to_string(kind())));
  }
  return {};
}

Status<PluginError> PluginInstance::check_running(std::string_view call) const {
  if (state_ != PluginState::Running) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("{} called while the plugin is {}; it must be running", call, to_string(state_)));
  }
  return {};
}

Status<PluginError> PluginInstance::open(const std::map<std::string, std::string>& params, const mhd_host& host) {
  if (state_ != PluginState::Loaded) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("open called while the plugin is {}; it must be loaded", to_string(state_)));
  }
  std::vector<mhd_param> abi_params;
  abi_params.reserve(params.size());
  for (const auto& [key, value] : params) abi_params.push_back(mhd_param{key.c_str(), value.c_str()});

  // The plugin's declarations decide first, as `mhd validate` does: open() never sees a
  // parameter the plugin did not declare or a value its declaration refuses.
  if (auto problems = declared_param_problems(*library_, params)) {
    return error(PluginErrorKind::BadParameter, std::move(*problems));
  }

  mhd_error err{};
  handle_ = library_->api().open(&host, abi_params.data(), abi_params.size(), &err);
  if (handle_ == nullptr) return error(PluginErrorKind::OpenFailed, failed("open", err));
  state_ = PluginState::Open;

  if (kind() == PluginKind::Device) {
    Status<PluginError> info = read_device_info();
    if (!info) {
      close_handle();
      state_ = PluginState::Loaded;
      return info;
    }
  }
  return {};
}

Status<PluginError> PluginInstance::read_device_info() {
  mhd_error err{};
  mhd_device_info raw{};
  const StatusCode code = static_cast<StatusCode>(library_->api().device_info(handle_, &raw, &err));
  if (code == MHD_ERROR) return error(PluginErrorKind::CallFailed, failed("device_info", err));
  if (code != MHD_OK) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("device_info returned {}; expected MHD_OK or MHD_ERROR", status_name(code)));
  }
  const DeviceInfo info = from_abi(raw);
  if (auto problem = device_info_problem(info)) {
    return error(PluginErrorKind::InvalidData, fmt::format("device_info returned {}", *problem));
  }
  info_ = info;
  return {};
}

Status<PluginError> PluginInstance::start() {
  if (state_ != PluginState::Open && state_ != PluginState::Stopped) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("start called while the plugin is {}; it must be open or stopped", to_string(state_)));
  }
  mhd_error err{};
  const StatusCode code = static_cast<StatusCode>(library_->api().start(handle_, &err));
  if (code == MHD_ERROR) return error(PluginErrorKind::StartFailed, failed("start", err));
  if (code != MHD_OK) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("start returned {}; expected MHD_OK or MHD_ERROR", status_name(code)));
  }
  state_ = PluginState::Running;
  return {};
}

Status<PluginError> PluginInstance::stop() {
  if (state_ != PluginState::Running) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("stop called while the plugin is {}; it must be running", to_string(state_)));
  }
  state_ = PluginState::Stopped;  // the host stops driving it whatever the plugin says
  mhd_error err{};
  const StatusCode code = static_cast<StatusCode>(library_->api().stop(handle_, &err));
  if (code == MHD_ERROR) return error(PluginErrorKind::StopFailed, failed("stop", err));
  if (code != MHD_OK) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("stop returned {}; expected MHD_OK or MHD_ERROR", status_name(code)));
  }
  return {};
}

Status<PluginError> PluginInstance::close() {
  Status<PluginError> result;
  if (state_ == PluginState::Running) result = stop();
  close_handle();
  state_ = PluginState::Closed;
  return result;
}

void PluginInstance::close_handle() noexcept {
  if (handle_ != nullptr) library_->api().close(handle_);
  handle_ = nullptr;
}

Result<DeviceInfo, PluginError> PluginInstance::device_info() const {
  if (Status<PluginError> s = check_call("device_info", PluginKind::Device); !s) return s.error();
  if (state_ != PluginState::Open && state_ != PluginState::Running && state_ != PluginState::Stopped) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("device_info called while the plugin is {}; it must be open, running or stopped",
                             to_string(state_)));
  }
  return info_;
}

namespace {

/// Maps a read/write status; MHD_ERROR becomes CallFailed and unknown numbers InvalidData.
Result<PluginCallStatus, PluginError> call_outcome(const std::string& plugin, std::string_view call, StatusCode code,
                                            const mhd_error& err) {
  switch (code) {
    case MHD_OK: return PluginCallStatus::Ok;
    case MHD_NO_DATA: return PluginCallStatus::NoData;
    case MHD_DEACTIVATE: return PluginCallStatus::Deactivate;
    case MHD_ERROR: return PluginError{PluginErrorKind::CallFailed, plugin, {}, failed(call, err)};
    default:
      return PluginError{PluginErrorKind::InvalidData, plugin, {},
                         fmt::format("{} returned status {}, which is not an mhd_status", call, code)};
  }
}

}  // namespace

Result<PluginCallStatus, PluginError> PluginInstance::device_read(DeviceState& out) {
  if (Status<PluginError> s = check_call("device_read", PluginKind::Device); !s) return s.error();
  if (Status<PluginError> s = check_running("device_read"); !s) return s.error();
  mhd_error err{};
  mhd_device_state raw{};
  Result<PluginCallStatus, PluginError> outcome =
      call_outcome(name(), "device_read", static_cast<StatusCode>(library_->api().device_read(handle_, &raw, &err)), err);
  if (!outcome || outcome.value() != PluginCallStatus::Ok) return outcome;
  const DeviceState state = from_abi(raw);
  if (auto problem = device_state_problem(state)) {
    return error(PluginErrorKind::InvalidData, fmt::format("device_read returned {}", *problem));
  }
  out = state;
  return outcome;
}

Result<PluginCallStatus, PluginError> PluginInstance::device_write(const DeviceCommand& command) {
  if (Status<PluginError> s = check_call("device_write", PluginKind::Device); !s) return s.error();
  if (Status<PluginError> s = check_running("device_write"); !s) return s.error();
  if (auto field = non_finite_in(command)) {
    return error(PluginErrorKind::InvalidData, fmt::format("refused to send a non-finite {} to device_write", *field));
  }
  const mhd_device_command clamped = to_abi(clamp_to_device(info_, command));
  mhd_error err{};
  return call_outcome(name(), "device_write", static_cast<StatusCode>(library_->api().device_write(handle_, &clamped, &err)), err);
}

Result<PluginCallStatus, PluginError> PluginInstance::tracker_read(std::span<TrackerSample> out, std::size_t& count) {
  count = 0;
  if (Status<PluginError> s = check_call("tracker_read", PluginKind::Tracker); !s) return s.error();
  if (Status<PluginError> s = check_running("tracker_read"); !s) return s.error();
  mhd_error err{};
  // Read into the ABI's form on the stack (no allocation on the io thread), then convert;
  // only the part handed to the plugin is zeroed.
  std::array<mhd_tracker_sample, kMaxTrackerSamplesPerRead> raw;
  const std::size_t capacity = std::min(out.size(), raw.size());
  std::fill_n(raw.begin(), capacity, mhd_tracker_sample{});
  std::size_t returned = 0;
  Result<PluginCallStatus, PluginError> outcome = call_outcome(
      name(), "tracker_read",
      static_cast<StatusCode>(library_->api().tracker_read(handle_, raw.data(), capacity, &returned, &err)), err);
  if (!outcome || outcome.value() != PluginCallStatus::Ok) return outcome;
  if (returned > capacity) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("tracker_read returned count {} for capacity {}", returned, capacity));
  }
  for (std::size_t i = 0; i < returned; ++i) {
    const TrackerSample sample = from_abi(raw[i]);
    out[i] = sample;
    const std::string prefix = fmt::format("samples[{}].", i);
    if (auto field = non_finite_in(sample, prefix)) {
      return error(PluginErrorKind::InvalidData, fmt::format("tracker_read returned a non-finite {}", *field));
    }
    const std::array<double, 4>& q = sample.q_T_wxyz;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(norm - 1.0) > kUnitQuaternionTolerance) {
      return error(PluginErrorKind::InvalidData,
                   fmt::format("tracker_read returned samples[{}].q_T_wxyz of norm {}, not a unit quaternion", i, norm));
    }
  }
  count = returned;
  return outcome;
}

Result<PluginCallStatus, PluginError> PluginInstance::base_read(BaseState& out) {
  if (Status<PluginError> s = check_call("base_read", PluginKind::Base); !s) return s.error();
  if (Status<PluginError> s = check_running("base_read"); !s) return s.error();
  mhd_error err{};
  mhd_base_state raw{};
  Result<PluginCallStatus, PluginError> outcome =
      call_outcome(name(), "base_read", static_cast<StatusCode>(library_->api().base_read(handle_, &raw, &err)), err);
  if (!outcome || outcome.value() != PluginCallStatus::Ok) return outcome;
  const BaseState state = from_abi(raw);
  if (auto field = non_finite_in(state)) {
    return error(PluginErrorKind::InvalidData, fmt::format("base_read returned a non-finite {}", *field));
  }
  out = state;
  return outcome;
}

Result<PluginCallStatus, PluginError> PluginInstance::base_write(const BaseCommand& command) {
  if (Status<PluginError> s = check_call("base_write", PluginKind::Base); !s) return s.error();
  if (Status<PluginError> s = check_running("base_write"); !s) return s.error();
  if (auto field = non_finite_in(command)) {
    return error(PluginErrorKind::InvalidData, fmt::format("refused to send a non-finite {} to base_write", *field));
  }
  mhd_error err{};
  const mhd_base_command raw = to_abi(command);
  return call_outcome(name(), "base_write", static_cast<StatusCode>(library_->api().base_write(handle_, &raw, &err)), err);
}

Result<PluginCallStatus, PluginError> PluginInstance::display_write(const DisplayFrame& frame) {
  if (Status<PluginError> s = check_call("display_write", PluginKind::Display); !s) return s.error();
  if (Status<PluginError> s = check_running("display_write"); !s) return s.error();
  if (auto field = non_finite_in(frame)) {
    return error(PluginErrorKind::InvalidData, fmt::format("refused to send a non-finite {} to display_write", *field));
  }
  mhd_error err{};
  const mhd_display_frame raw = to_abi(frame);
  return call_outcome(name(), "display_write", static_cast<StatusCode>(library_->api().display_write(handle_, &raw, &err)),
                      err);
}

Result<PluginCallStatus, PluginError> PluginInstance::link_send(std::span<const LinkMessage> messages) {
  if (Status<PluginError> s = check_call("link_send", PluginKind::Link); !s) return s.error();
  if (Status<PluginError> s = check_running("link_send"); !s) return s.error();
  std::array<mhd_link_message, kMaxLinkMessagesPerCall> raw;
  if (messages.size() > raw.size()) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("refused to send {} messages to link_send (at most {})", messages.size(), raw.size()));
  }
  for (std::size_t i = 0; i < messages.size(); ++i) {
    if (auto problem = link_message_problem(messages[i], i)) {
      return error(PluginErrorKind::InvalidData, fmt::format("refused to send {} to link_send", *problem));
    }
    raw[i] = to_abi(messages[i]);
  }
  mhd_error err{};
  return call_outcome(
      name(), "link_send",
      static_cast<StatusCode>(library_->api().link_send(handle_, raw.data(), messages.size(), &err)), err);
}

Result<PluginCallStatus, PluginError> PluginInstance::link_read(std::span<LinkMessage> out, std::size_t& count) {
  count = 0;
  if (Status<PluginError> s = check_call("link_read", PluginKind::Link); !s) return s.error();
  if (Status<PluginError> s = check_running("link_read"); !s) return s.error();
  std::array<mhd_link_message, kMaxLinkMessagesPerCall> raw;
  const std::size_t capacity = std::min(out.size(), raw.size());
  std::fill_n(raw.begin(), capacity, mhd_link_message{});
  std::size_t returned = 0;
  mhd_error err{};
  Result<PluginCallStatus, PluginError> outcome = call_outcome(
      name(), "link_read",
      static_cast<StatusCode>(library_->api().link_read(handle_, raw.data(), capacity, &returned, &err)), err);
  if (!outcome || outcome.value() != PluginCallStatus::Ok) return outcome;
  if (returned > capacity) {
    return error(PluginErrorKind::InvalidData,
                 fmt::format("link_read returned count {} for capacity {}", returned, capacity));
  }
  for (std::size_t i = 0; i < returned; ++i) {
    out[i] = from_abi(raw[i]);
    if (auto problem = link_message_problem(out[i], i)) {
      return error(PluginErrorKind::InvalidData, fmt::format("link_read returned {}", *problem));
    }
  }
  count = returned;
  return outcome;
}

Result<PluginCallStatus, PluginError> PluginInstance::simulate_until(double t_s) {
  if (library_ && !simulates()) {
    return error(PluginErrorKind::WrongKind, "simulate_until called on a plugin that does not simulate");
  }
  if (Status<PluginError> s = check_running("simulate_until"); !s) return s.error();
  if (!std::isfinite(t_s)) {
    return error(PluginErrorKind::InvalidData, "refused to send a non-finite t_s to simulate_until");
  }
  mhd_error err{};
  return call_outcome(name(), "simulate_until", static_cast<StatusCode>(library_->api().simulate_until(handle_, t_s, &err)), err);
}

Result<PluginCallStatus, PluginError> PluginInstance::tracker_wait(double timeout_s) {
  if (library_ && !waits()) return error(PluginErrorKind::WrongKind, "tracker_wait called on a plugin that does not wait");
  if (Status<PluginError> s = check_running("tracker_wait"); !s) return s.error();
  if (!std::isfinite(timeout_s)) {
    return error(PluginErrorKind::InvalidData, "refused to send a non-finite timeout_s to tracker_wait");
  }
  mhd_error err{};
  return call_outcome(name(), "tracker_wait",
                      static_cast<StatusCode>(library_->api().tracker_wait(handle_, std::clamp(timeout_s, 0.0, 1.0), &err)),
                      err);
}

Result<std::size_t, PluginError> PluginInstance::counters(std::span<CounterReading> out) {
  if (library_ && !counts()) return error(PluginErrorKind::WrongKind, "counters called on a plugin that keeps none");
  if (state_ != PluginState::Open && state_ != PluginState::Running && state_ != PluginState::Stopped) {
    return error(PluginErrorKind::WrongState,
                 fmt::format("counters called while the plugin is {}; it must be open, running or stopped", to_string(state_)));
  }
  mhd_error err{};
  std::array<mhd_counter, kMaxCountersPerRead> raw{};
  const std::size_t capacity = std::min(out.size(), raw.size());
  std::size_t count = 0;
  Result<PluginCallStatus, PluginError> outcome = call_outcome(
      name(), "counters", static_cast<StatusCode>(library_->api().counters(handle_, raw.data(), capacity, &count, &err)), err);
  if (!outcome) return outcome.error();
  if (outcome.value() != PluginCallStatus::Ok) return std::size_t{0};
  const std::size_t written = std::min(count, capacity);
  for (std::size_t i = 0; i < written; ++i) {
    out[i] = from_abi(raw[i]);
    const char* n = out[i].name;
    constexpr std::size_t kMaxName = 64;
    const std::size_t length = n == nullptr ? 0 : strnlen(n, kMaxName + 1);
    const bool printable = std::all_of(n, n + length, [](char c) { return c > ' ' && c < 127; });
    if (length == 0 || length > kMaxName || !printable) {
      return error(PluginErrorKind::InvalidData,
                   fmt::format("counters returned counters[{}].name that is missing, empty, too long or not printable", i));
    }
  }
  return written;
}

}  // namespace mhd
