#include "plugin_host/isolated_load.h"

#include "plugin_host/plugin_name.h"
#include "plugin_host/scene_plugin_check.h"

#include <fmt/core.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

// The answer's framing: fields as "<length>:<bytes>", so any byte may be in them.
void put(std::string& out, std::string_view field) {
  out += std::to_string(field.size());
  out += ':';
  out += field;
}

std::optional<std::vector<std::string>> fields_of(std::string_view in) {
  std::vector<std::string> fields;
  while (!in.empty()) {
    const std::size_t colon = in.find(':');
    if (colon == std::string_view::npos || colon == 0 || colon > 9) return std::nullopt;
    std::size_t length = 0;
    for (const char c : in.substr(0, colon)) {
      if (c < '0' || c > '9') return std::nullopt;
      length = length * 10 + static_cast<std::size_t>(c - '0');
    }
    in.remove_prefix(colon + 1);
    if (length > in.size()) return std::nullopt;
    fields.emplace_back(in.substr(0, length));
    in.remove_prefix(length);
  }
  return fields;
}

std::string error_fields(const PluginError& e) {
  std::string out;
  put(out, "error");
  put(out, std::to_string(static_cast<int>(e.kind)));
  put(out, e.plugin);
  put(out, e.path.string());
  put(out, e.message);
  return out;
}

std::optional<PluginError> error_from(const std::vector<std::string>& f) {
  if (f.size() != 5 || f[0] != "error") return std::nullopt;
  return PluginError{static_cast<PluginErrorKind>(std::stoi(f[1])), f[2], f[3], f[4]};
}

/// Writes all of `data`; false when the reader went away.
bool write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = ::sigabbrev_np(signal);
    return fmt::format("was killed by signal {} (SIG{}, {})", signal, name != nullptr ? name : "?",
                       ::strsignal(signal));
  }
  if (WIFEXITED(status)) return fmt::format("ended the process with exit status {}", WEXITSTATUS(status));
  return "ended the process";
}

}  // namespace

Result<std::string, PluginError> run_isolated(const std::function<std::string()>& work, const std::string& plugin,
                                              const fs::path& path, double timeout_s) {
  auto failed = [&](const std::string& how) {
    return PluginError{PluginErrorKind::CrashedWhileLoading, plugin, path,
                       fmt::format("loading it {} (in a static constructor or its entry point, in a child process: "
                                   "nothing else was affected)",
                                   how)};
  };
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return failed(fmt::format("could not be tried: pipe: {}", std::strerror(errno)));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    return failed(fmt::format("could not be tried: fork: {}", std::strerror(errno)));
  }
  if (child == 0) {
    ::close(pipe_fds[0]);
    // What the library prints while it loads (or a sanitizer's report of a library that
    // exits) is not the caller's output; its error comes back through the pipe.
    if (const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC); null_fd >= 0) {
      ::dup2(null_fd, STDOUT_FILENO);
      ::dup2(null_fd, STDERR_FILENO);
    }
    std::string answer;
    try {
      answer = work();
    } catch (...) {
      ::_exit(3);
    }
    // A reply, then _exit: no atexit handler or static destructor of the plugin's runs.
    ::_exit(write_all(pipe_fds[1], answer) ? 0 : 4);
  }
  ::close(pipe_fds[1]);
  std::string answer;
  bool complete = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
    pollfd p{pipe_fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) break;
    char buffer[4096];
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      complete = true;  // the child closed its end: ended, one way or another
      break;
    }
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  if (!complete) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!complete) return failed(fmt::format("did not finish within {} s", timeout_s));
  // Every answer is a field or more: a child that ends without one, even with status 0,
  // was ended by the library.
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty()) return failed(how_it_ended(status));
  return answer;
}

Status<PluginError> check_scene_plugin_isolated(const PluginSearchPath& search, const PluginDescription& description,
                                                double timeout_s) {
  const Result<fs::path, PluginError> path = search.find(description.name);
  if (!path) return path.error();
  const Result<std::string, PluginError> answer = run_isolated(
      [&] {
        const Status<PluginError> checked = check_scene_plugin(search, description);
        std::string out;
        if (checked) {
          put(out, "ok");
        } else {
          out = error_fields(checked.error());
        }
        return out;
      },
      plugin_name_from_file(path.value()), path.value(), timeout_s);
  if (!answer) return answer.error();
  const std::optional<std::vector<std::string>> f = fields_of(answer.value());
  if (f && f->size() == 1 && f->front() == "ok") return {};
  if (f) {
    if (std::optional<PluginError> e = error_from(*f)) return *e;
  }
  return PluginError{PluginErrorKind::CrashedWhileLoading, description.name, path.value(),
                     "loading it in a child process gave no readable answer"};
}

Result<PluginInfo, PluginError> probe_plugin_isolated(const fs::path& path, double timeout_s) {
  const std::string name = plugin_name_from_file(path);
  const Result<std::string, PluginError> answer = run_isolated(
      [&] {
        const Result<std::shared_ptr<const PluginLibrary>, PluginError> library = PluginLibrary::load(path);
        if (!library) return error_fields(library.error());
        const PluginInfo& info = library.value()->info();
        std::string out;
        put(out, "info");
        put(out, std::to_string(static_cast<int>(info.kind)));
        put(out, info.name);
        put(out, info.version);
        put(out, info.description);
        return out;
      },
      name.empty() ? path.filename().string() : name, path, timeout_s);
  if (!answer) return answer.error();
  const std::optional<std::vector<std::string>> f = fields_of(answer.value());
  if (f && f->size() == 5 && f->front() == "info") {
    return PluginInfo{static_cast<PluginKind>(std::stoi((*f)[1])), (*f)[2], (*f)[3], (*f)[4]};
  }
  if (f) {
    if (std::optional<PluginError> e = error_from(*f)) return *e;
  }
  return PluginError{PluginErrorKind::CrashedWhileLoading, name, path,
                     "loading it in a child process gave no readable answer"};
}

}  // namespace mhd
