#include "dds_test_support.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace mhd::dds::test {

std::uint32_t use_loopback_and_unique_domain(std::uint32_t salt) {
  const std::string uri = std::string("file://") + MHD_SOURCE_DIR + "/config/cyclonedds-loopback.xml";
  setenv("CYCLONEDDS_URI", uri.c_str(), 1);
  return reserve_test_domain(1u + (static_cast<std::uint32_t>(getpid()) * 7u + salt) % 200u);
}

std::uint32_t reserve_test_domain(std::uint32_t first_choice) {
  constexpr std::uint32_t kDomains = 200;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mhd-test-dds-domains";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::filesystem::permissions(dir, std::filesystem::perms::all, ec);  // shared by every user's tests
  for (std::uint32_t k = 0; k < kDomains; ++k) {
    const std::uint32_t domain = 1u + (first_choice - 1u + k) % kDomains;
    const std::string file = (dir / (std::to_string(domain) + ".lock")).string();
    const int fd = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) continue;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) return domain;  // fd stays open: held until exit
    close(fd);
  }
  throw std::runtime_error("no free DDS test domain in [1, 200] under " + dir.string());
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::string& output_file) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!output_file.empty()) {
    posix_spawn_file_actions_addopen(&actions, 1, output_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int rc = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("posix_spawn " + argv[0] + " failed: " + std::to_string(rc));
}

ChildProcess::~ChildProcess() { kill_now(); }

std::optional<int> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      reaped_ = true;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    if (std::chrono::steady_clock::now() >= end) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void ChildProcess::kill_now() {
  if (reaped_ || pid_ <= 0) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  reaped_ = true;
}

void ChildProcess::terminate() {
  if (!reaped_ && pid_ > 0) ::kill(pid_, SIGTERM);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CsvTable read_csv_table(const std::string& path) {
  CsvTable t;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return t;
  std::istringstream header(line);
  std::size_t i = 0;
  for (std::string name; std::getline(header, name, ',');) t.column[name] = i++;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::strtod(cell.c_str(), nullptr));
    t.rows.push_back(std::move(v));
  }
  return t;
}

std::optional<std::int64_t> recording_clock_zero_unix_ns(const std::string& csv) {
  std::ifstream meta(csv + ".meta");
  const std::string key = "host_clock_zero_unix_ns=";
  for (std::string line; std::getline(meta, line);) {
    if (line.rfind(key, 0) != 0) continue;
    try {
      std::size_t used = 0;
      const long long ns = std::stoll(line.substr(key.size()), &used);
      if (used == line.size() - key.size()) return ns;
    } catch (const std::exception&) {
    }
    return std::nullopt;
  }
  return std::nullopt;
}

OutputFile::OutputFile(const std::string& folder, const char* name)
    : path_((std::filesystem::path(folder) / ("mhd_dds_test_" + std::to_string(::getpid()) + "_" + name + ".log"))
                .string()) {}

OutputFile::~OutputFile() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

Repeating::Repeating(std::chrono::milliseconds period, std::function<void()> step)
    : thread_([this, period, step = std::move(step)] {
        while (!stop_.load()) {
          step();
          std::this_thread::sleep_for(period);
        }
      }) {}

Repeating::~Repeating() {
  stop_.store(true);
  thread_.join();
}

}  // namespace mhd::dds::test
