#include "support/mhd_run_process.h"

#include "sim_backends/command_log_file.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace mhd::test {

using Clock = std::chrono::steady_clock;

std::string fill_scene_template(const std::filesystem::path& source,
                                const std::vector<std::pair<std::string, std::string>>& fills) {
  std::ifstream in(source);
  if (!in) throw std::runtime_error("cannot read " + source.string());
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string rig = "../../../scenes/rigs/pomhi.xml";
  if (const auto at = xml.find(rig); at != std::string::npos) {
    xml.replace(at, rig.size(), (std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml").string());
  }
  for (const auto& [from, to] : fills) {
    const auto at = xml.find(from);
    if (at == std::string::npos) throw std::runtime_error(source.string() + " has no '" + from + "'");
    xml.replace(at, from.size(), to);
  }
  return xml;
}

MhdRunProcess::MhdRunProcess(const Options& options) : dir_(options.dir) {
  int pipe_fds[2] = {-1, -1};
  if (options.stdout_to_closed_pipe && ::pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    const int fd = ::open((dir_ / "output.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    ::dup2(options.stdout_to_closed_pipe ? pipe_fds[1] : fd, 1);
    if (options.stdout_to_closed_pipe) {
      ::close(pipe_fds[0]);
      ::close(pipe_fds[1]);
    }
    ::close(fd);
    if (::chdir(dir_.c_str()) != 0) ::_exit(126);
    for (const auto& [name, value] : options.env) ::setenv(name.c_str(), value.c_str(), 1);
    ::signal(SIGPIPE, SIG_DFL);  // as a shell leaves it
    std::vector<char*> args;
    for (const std::string& a : options.argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  if (options.stdout_to_closed_pipe) {
    ::close(pipe_fds[0]);  // nobody reads: every write to stdout is EPIPE / SIGPIPE
    ::close(pipe_fds[1]);
  }
}

MhdRunProcess::~MhdRunProcess() {
  if (!status_) {
    ::kill(pid_, SIGKILL);
    (void)wait_for(std::chrono::seconds(5));
  }
}

bool MhdRunProcess::wait_until_logged(const std::string& log, std::size_t rows, const std::string& event) {
  const auto give_up = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < give_up && !wait_for(std::chrono::milliseconds(10))) {
    try {
      if (!std::filesystem::exists(dir_ / log)) continue;
      const auto logged = read_command_log(dir_ / log);
      const auto n = event.empty() ? logged.size()
                                   : static_cast<std::size_t>(std::count_if(
                                         logged.begin(), logged.end(),
                                         [&](const CommandLogRow& r) { return r.event == event; }));
      if (n >= rows) return true;
    } catch (const std::exception&) {
      // a row being written
    }
  }
  return false;
}

void MhdRunProcess::signal(int s) const { ::kill(pid_, s); }

std::optional<int> MhdRunProcess::wait_for(std::chrono::milliseconds timeout) {
  const auto give_up = Clock::now() + timeout;
  while (!status_) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      status_ = status;
      break;
    }
    if (Clock::now() >= give_up) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status_;
}

std::string MhdRunProcess::output() const {
  std::ifstream in(dir_ / "output.txt");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace mhd::test
