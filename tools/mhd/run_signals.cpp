#include "run_signals.h"

#include "realtime/alternate_signal_stack.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <string>

namespace mhd::cli {
namespace {

std::atomic<HapticServer*> g_server{nullptr};
std::atomic<int> g_stop_signal{0};
std::atomic<bool> g_gasping{false};

// A message built without allocation, for signal handlers.
class Message {
 public:
  Message& add(const char* text) noexcept {
    for (; text != nullptr && *text != '\0' && size_ + 1 < sizeof(text_); ++text) text_[size_++] = *text;
    return *this;
  }
  void write_to_stderr() const noexcept {
    std::size_t done = 0;
    while (done < size_) {
      const ssize_t n = ::write(STDERR_FILENO, text_ + done, size_ - done);
      if (n <= 0) return;
      done += static_cast<std::size_t>(n);
    }
  }

 private:
  char text_[1024] = {};
  std::size_t size_ = 0;
};

const char* signal_cause(int signal) noexcept {
  switch (signal) {
    case SIGSEGV: return "segmentation fault (SIGSEGV)";
    case SIGBUS: return "bus error (SIGBUS)";
    case SIGFPE: return "arithmetic exception (SIGFPE)";
    case SIGILL: return "illegal instruction (SIGILL)";
    case SIGABRT: return "abort (SIGABRT)";
    default: return "fatal signal";
  }
}

extern "C" void on_last_gasp_timeout(int /*signal*/) {
  Message().add("mhd run: the last gasp did not finish within 2 s; exiting\n").write_to_stderr();
  ::_exit(kRunLastGasp);
}

/// The plugins' own threads (a driver's I/O, a simulated backend's log) pass the zeros on.
void let_plugin_threads_pass_the_zeros_on() noexcept {
  const timespec grace{0, 30000000};
  nanosleep(&grace, nullptr);
}

/// Zero torque and a base stop through the plugins, the message, the exit: from the
/// dying thread, async-signal-safe as far as the plugins' write calls are.
[[noreturn]] void last_gasp_and_exit(const char* cause) noexcept {
  if (g_gasping.exchange(true)) {
    for (;;) ::pause();  // another thread is already at it; it ends the process
  }
  // A plugin call that never returns must not keep a dying process alive.
  std::signal(SIGALRM, on_last_gasp_timeout);
  ::alarm(2);
  const auto [plugin, call] = HapticServer::call_in_progress();
  Message first;
  first.add("mhd run: error: ");
  if (plugin != nullptr) {
    first.add(plugin).add(" in ").add(call).add(": ");
  } else {
    first.add("outside any plugin call of the server's threads: ");
  }
  first.add(cause).add("\n").write_to_stderr();
  Message last;
  HapticServer* server = g_server.load();
  const HapticServer::LastGasp gasp = server != nullptr ? server->last_gasp() : HapticServer::LastGasp{};
  if (gasp.sent) {
    last.add("mhd run: last gasp: ").add(gasp.zero_torque_sent ? "zero torque sent" : "ZERO TORQUE NOT CONFIRMED");
    if (!gasp.desktop) last.add(", ").add(gasp.base_stop_sent ? "base stop sent" : "BASE STOP NOT CONFIRMED");
    last.add("\n");
  } else {
    last.add("mhd run: last gasp: the server was not running; nothing sent\n");
  }
  last.write_to_stderr();
  let_plugin_threads_pass_the_zeros_on();
  ::_exit(kRunLastGasp);
}

extern "C" void on_stop_signal(int signal) {
  int none = 0;
  (void)g_stop_signal.compare_exchange_strong(none, signal);
  if (HapticServer* s = g_server.load()) s->request_stop();
}

extern "C" void on_fatal_signal(int signal) {
  if (g_server.load() == nullptr && !g_gasping.load()) {
    // Not running: the default action (a core dump where enabled).
    std::signal(signal, SIG_DFL);
    ::raise(signal);
    return;
  }
  last_gasp_and_exit(signal_cause(signal));
}

extern "C" void on_exit_while_running() {
  if (g_server.load() == nullptr) return;  // the normal end of mhd
  last_gasp_and_exit("exit() called while the server runs");
}

/// Registered before on_exit_while_running, so it runs after it: only when a plugin called
/// exit() again during the last gasp, which then ends with that call's status. The run
/// did not end cleanly, so the status says so.
extern "C" void on_exit_during_last_gasp() {
  if (!g_gasping.load()) return;
  Message().add("mhd run: last gasp: a plugin called exit() again while the zeros were sent\n").write_to_stderr();
  let_plugin_threads_pass_the_zeros_on();
  ::_exit(kRunLastGasp);
}

[[noreturn]] void on_terminate() noexcept {
  static std::string cause;  // not a signal handler: allocating is fine here
  cause = "uncaught exception";
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      cause += ": ";
      cause += x.what();
    } catch (...) {
      cause += " (not a std::exception)";
    }
  } else {
    cause = "std::terminate called";
  }
  last_gasp_and_exit(cause.c_str());
}

void install(int signal, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  // SA_ONSTACK: on the thread's alternate stack, where it has one, so that a stack
  // overflow still ends in the last gasp.
  action.sa_flags = SA_RESTART | SA_ONSTACK;
  sigaction(signal, &action, nullptr);
}

}  // namespace

void install_run_signal_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) install(s, on_stop_signal);
  for (const int s : {SIGPIPE, SIGUSR1, SIGUSR2}) install(s, SIG_IGN);
  for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) install(s, on_fatal_signal);
  std::set_terminate(on_terminate);
  // atexit handlers run last-registered first.
  std::atexit(on_exit_during_last_gasp);
  std::atexit(on_exit_while_running);
  std::at_quick_exit(on_exit_during_last_gasp);
  std::at_quick_exit(on_exit_while_running);
  // The main thread calls plugins too (start, stop); its stack lives as long as the process.
  static const auto* const main_thread_signal_stack = new realtime::AlternateSignalStack();
  (void)main_thread_signal_stack;
}

void guard_server(HapticServer* server) noexcept {
  g_server.store(server);
  if (server != nullptr && g_stop_signal.load() != 0) server->request_stop();
}

int stop_signal() noexcept { return g_stop_signal.load(); }

}  // namespace mhd::cli
