// A simulated backend (FI_WRAPPED, a plugin file built in) that dies, stalls or lies at one
// of its calls, for the fault matrix (tests/fault_injection/fault_matrix_test.cpp). Every
// call is forwarded to the wrapped plugin, whose command log stays the hardware's view;
// the first time `fault_call` is made `fault_after_s` or more after start (and, for a
// device call, while the last force commanded was not zero), `fault` strikes.
// The wrapped plugin's parameters pass through; these three are the wrapper's own:
//   fault=none|segv|bus|fpe|ill|abort|stack_overflow|pthread_exit|exit0|exit3|quick_exit|
//         _exit|throw|hang|spin|stall_0.1|stall_0.5|stall_2|nan|huge|frozen_timestamp
//   fault_call=device_read|device_write|tracker_read|base_read|base_write
//   fault_after_s (0.5)
// A write is passed on before the fault strikes (the command reached the hardware, then the
// driver failed); a read fails before it is passed on.
// nan, huge and frozen_timestamp change what a read returns, and exit0, exit3 and quick_exit
// end the process, at that call and every one after it (the last gasp's own zero command
// included); the other faults strike once.
#include <mhd/plugin_abi.h>

#include <dlfcn.h>
#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace {

constexpr const char* kFaultChoices =
    "none|segv|bus|fpe|ill|abort|stack_overflow|pthread_exit|exit0|exit3|quick_exit|_exit|throw|hang|spin|"
    "stall_0.1|stall_0.5|stall_2|nan|huge|frozen_timestamp";
constexpr const char* kCallChoices = "device_read|device_write|tracker_read|base_read|base_write";

constexpr std::array<mhd_param_decl, 3> kOwnParams{{
    {"fault", MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, kFaultChoices, "none", "how the wrapped backend fails"},
    {"fault_call", MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, kCallChoices, "device_read", "the call that fails"},
    {"fault_after_s", MHD_PARAM_NUMBER, "s", MHD_PARAM_HAS_MIN | MHD_PARAM_HAS_MAX, 0.0, 3600.0, nullptr, "0.5",
     "the first such call this long after start fails"},
}};

bool is_own(const char* name) {
  for (const mhd_param_decl& d : kOwnParams) {
    if (std::strcmp(d.name, name) == 0) return true;
  }
  return false;
}

const mhd_plugin_api* g_inner = nullptr;

struct Instance {
  mhd_plugin_instance* inner = nullptr;
  mhd_host host{};
  std::string fault = "none";
  std::string call = "device_read";
  double after_s = 0.5;
  double start_s = 0.0;
  bool struck = false;
  double frozen_t_s = 0.0;
  bool pushing = false;  ///< the last device command carried force
};

Instance* self_of(mhd_plugin_instance* p) { return reinterpret_cast<Instance*>(p); }

double host_now(const Instance& s) { return s.host.now_s(s.host.clock_context); }

volatile std::uint64_t g_depth_limit = std::numeric_limits<std::uint64_t>::max();
int* volatile g_nowhere = nullptr;

// Deep enough to overflow any thread's stack; the limit is never reached.
[[gnu::noinline]] std::uint64_t recurse(std::uint64_t depth) {
  volatile char frame[1024];
  frame[0] = static_cast<char>(depth);
  if (depth >= g_depth_limit) return frame[0];
  return recurse(depth + 1) + static_cast<std::uint64_t>(frame[0]);
}

/// Dies or stalls as `fault` says; returns for the faults that let the call go on.
void strike(const std::string& fault) {
  using namespace std::chrono_literals;
  if (fault == "segv") *g_nowhere = 1;
  if (fault == "bus") ::raise(SIGBUS);
  if (fault == "fpe") ::raise(SIGFPE);
  if (fault == "ill") __builtin_trap();
  if (fault == "abort") std::abort();
  if (fault == "stack_overflow") (void)recurse(0);
  if (fault == "pthread_exit") ::pthread_exit(nullptr);
  if (fault == "exit0") std::exit(0);
  if (fault == "exit3") std::exit(3);
  if (fault == "quick_exit") std::quick_exit(0);
  if (fault == "_exit") ::_exit(0);
  if (fault == "throw") throw std::runtime_error("fi_wrap: injected exception");
  if (fault == "hang") {
    for (;;) std::this_thread::sleep_for(1h);
  }
  if (fault == "spin") {
    std::atomic<std::uint64_t> turns{0};
    for (;;) turns.fetch_add(1, std::memory_order_relaxed);
  }
  if (fault == "stall_0.1") std::this_thread::sleep_for(100ms);
  if (fault == "stall_0.5") std::this_thread::sleep_for(500ms);
  if (fault == "stall_2") std::this_thread::sleep_for(2s);
}

/// Tells the matrix, on stderr, when the fault struck on the host's clock (the clock of the
/// command logs), so that it judges only what came after. write(2): nothing is buffered
/// when the strike ends the process.
void say_strike(const Instance& s, std::string_view call, double now_s) {
  std::array<char, 160> line{};
  const int n = std::snprintf(line.data(), line.size(), "fi_wrap: %s strikes in %.*s at host time %.9f s\n",
                              s.fault.c_str(), static_cast<int>(call.size()), call.data(), now_s);
  if (n > 0) (void)!::write(2, line.data(), std::min(static_cast<std::size_t>(n), line.size() - 1));
}

bool is_value_fault(const std::string& fault) { return fault == "nan" || fault == "huge" || fault == "frozen_timestamp"; }
bool is_exit_fault(const std::string& fault) { return fault == "exit0" || fault == "exit3" || fault == "quick_exit"; }

/// Before the call `call`: strikes the first time it is due. True when the call's result is
/// to be falsified (a value fault that has struck).
bool before(Instance& s, std::string_view call) {
  if (call != s.call || s.fault == "none") return false;
  if (!s.struck) {
    const double now_s = host_now(s);
    if (now_s - s.start_s < s.after_s || (call.substr(0, 6) == "device" && !s.pushing)) return false;
    s.struck = true;
    s.frozen_t_s = now_s;
    say_strike(s, call, now_s);
    if (!is_value_fault(s.fault)) strike(s.fault);
  } else if (is_exit_fault(s.fault)) {
    strike(s.fault);
  }
  return is_value_fault(s.fault);
}

double falsified(const Instance& s, double value) {
  return s.fault == "nan" ? std::numeric_limits<double>::quiet_NaN() : s.fault == "huge" ? 1e308 : value;
}

mhd_plugin_instance* wrap_open(const mhd_host* host, const mhd_param* params, std::size_t count, mhd_error* err) {
  auto* s = new Instance;
  s->host = *host;
  std::vector<mhd_param> passed;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string_view name = params[i].name;
    if (!is_own(params[i].name)) {
      passed.push_back(params[i]);
    } else if (name == "fault") {
      s->fault = params[i].value;
    } else if (name == "fault_call") {
      s->call = params[i].value;
    } else {
      s->after_s = std::strtod(params[i].value, nullptr);
    }
  }
  s->inner = g_inner->open(host, passed.data(), passed.size(), err);
  if (s->inner == nullptr) {
    delete s;
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(s);
}

mhd_status wrap_start(mhd_plugin_instance* p, mhd_error* err) {
  Instance& s = *self_of(p);
  s.start_s = host_now(s);
  return g_inner->start(s.inner, err);
}
mhd_status wrap_stop(mhd_plugin_instance* p, mhd_error* err) { return g_inner->stop(self_of(p)->inner, err); }
void wrap_close(mhd_plugin_instance* p) {
  g_inner->close(self_of(p)->inner);
  delete self_of(p);
}

mhd_status wrap_device_info(mhd_plugin_instance* p, mhd_device_info* out, mhd_error* err) {
  return g_inner->device_info(self_of(p)->inner, out, err);
}
mhd_status wrap_device_read(mhd_plugin_instance* p, mhd_device_state* out, mhd_error* err) {
  Instance& s = *self_of(p);
  const bool lie = before(s, "device_read");
  const mhd_status status = g_inner->device_read(s.inner, out, err);
  if (lie && status == MHD_OK) {
    out->p_D_tool_m[0] = falsified(s, out->p_D_tool_m[0]);
    if (s.fault == "frozen_timestamp") out->timestamp_s = s.frozen_t_s;
  }
  return status;
}
mhd_status wrap_device_write(mhd_plugin_instance* p, const mhd_device_command* command, mhd_error* err) {
  Instance& s = *self_of(p);
  const mhd_status status = g_inner->device_write(s.inner, command, err);
  (void)before(s, "device_write");
  s.pushing = command->force_D_N[0] != 0.0 || command->force_D_N[1] != 0.0 || command->force_D_N[2] != 0.0;
  return status;
}
mhd_status wrap_tracker_read(mhd_plugin_instance* p, mhd_tracker_sample* out, std::size_t capacity,
                             std::size_t* count, mhd_error* err) {
  Instance& s = *self_of(p);
  const bool lie = before(s, "tracker_read");
  const mhd_status status = g_inner->tracker_read(s.inner, out, capacity, count, err);
  if (lie && status == MHD_OK) {
    for (std::size_t i = 0; i < *count; ++i) {
      out[i].p_T_m[0] = falsified(s, out[i].p_T_m[0]);
      if (s.fault == "frozen_timestamp") out[i].timestamp_s = s.frozen_t_s;
    }
  }
  return status;
}
mhd_status wrap_base_read(mhd_plugin_instance* p, mhd_base_state* out, mhd_error* err) {
  Instance& s = *self_of(p);
  const bool lie = before(s, "base_read");
  const mhd_status status = g_inner->base_read(s.inner, out, err);
  if (lie && status == MHD_OK) {
    out->x_m = falsified(s, out->x_m);
    if (s.fault == "frozen_timestamp") out->timestamp_s = s.frozen_t_s;
  }
  return status;
}
mhd_status wrap_base_write(mhd_plugin_instance* p, const mhd_base_command* command, mhd_error* err) {
  Instance& s = *self_of(p);
  const mhd_status status = g_inner->base_write(s.inner, command, err);
  (void)before(s, "base_write");
  return status;
}
mhd_status wrap_simulate_until(mhd_plugin_instance* p, double t_s, mhd_error* err) {
  return g_inner->simulate_until(self_of(p)->inner, t_s, err);
}
mhd_status wrap_tracker_wait(mhd_plugin_instance* p, double timeout_s, mhd_error* err) {
  return g_inner->tracker_wait(self_of(p)->inner, timeout_s, err);
}
mhd_status wrap_counters(mhd_plugin_instance* p, mhd_counter* out, std::size_t capacity, std::size_t* count,
                         mhd_error* err) {
  return g_inner->counters(self_of(p)->inner, out, capacity, count, err);
}

/// The wrapped plugin's table with this plugin's name, its parameters plus the three
/// above, and every call it has routed through here.
const mhd_plugin_api* make_table(std::uint32_t host_abi_version) {
  void* library = ::dlopen(FI_WRAPPED, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) return nullptr;
  auto entry = reinterpret_cast<mhd_plugin_entry_fn>(::dlsym(library, "mhd_plugin_entry"));
  if (entry == nullptr) return nullptr;
  g_inner = entry(host_abi_version);
  if (g_inner == nullptr) return nullptr;
  static std::vector<mhd_param_decl> params(g_inner->params, g_inner->params + g_inner->param_count);
  params.insert(params.end(), kOwnParams.begin(), kOwnParams.end());
  static mhd_plugin_api table = *g_inner;
  table.name = MHD_PLUGIN_NAME;
  table.description = "test backend: a simulated one that fails on cue (fault matrix)";
  table.open = wrap_open;
  table.start = wrap_start;
  table.stop = wrap_stop;
  table.close = wrap_close;
  table.params = params.data();
  table.param_count = params.size();
  const auto route = [](auto& slot, auto wrapper) {
    if (slot != nullptr) slot = wrapper;
  };
  route(table.device_info, wrap_device_info);
  route(table.device_read, wrap_device_read);
  route(table.device_write, wrap_device_write);
  route(table.tracker_read, wrap_tracker_read);
  route(table.base_read, wrap_base_read);
  route(table.base_write, wrap_base_write);
  route(table.simulate_until, wrap_simulate_until);
  route(table.tracker_wait, wrap_tracker_wait);
  route(table.counters, wrap_counters);
  return &table;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(std::uint32_t host_abi_version) {
  static const mhd_plugin_api* const table = make_table(host_abi_version);
  return table;
}
