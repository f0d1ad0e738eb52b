#include "sim_common/command_log.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace mhd::plugin_support {
namespace {

// Rows are drained this often; a flush follows any write, so the file is never more
// than this (well under 50 ms) behind.
constexpr auto kDrainPeriod = std::chrono::milliseconds(10);

const char* to_text(CommandEvent e) {
  switch (e) {
    case CommandEvent::Start: return "start";
    case CommandEvent::Command: return "command";
    case CommandEvent::Timeout: return "timeout";
    case CommandEvent::Stop: return "stop";
  }
  return "unknown";
}

}  // namespace

CommandLog::CommandLog(const std::string& path, const std::array<const char*, 3>& value_names) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error("cannot write the command log '" + path + "': " + std::strerror(errno));
  }
  std::fprintf(file_, "t_s,event,%s,%s,%s\n", value_names[0], value_names[1], value_names[2]);
  std::fflush(file_);
  writer_ = std::thread([this] { writer_loop(); });
}

CommandLog::~CommandLog() {
  stop_.store(true, std::memory_order_release);
  writer_.join();
  write_queued();
  if (const std::uint64_t lost = dropped(); lost > 0) {
    std::fprintf(file_, "0,dropped,%llu,0,0\n", static_cast<unsigned long long>(lost));
  }
  std::fclose(file_);
}

void CommandLog::add(double t_s, CommandEvent event, const std::array<double, 3>& values) noexcept {
  if (!ring_.push(Row{t_s, event, values})) dropped_.fetch_add(1, std::memory_order_relaxed);
}

void CommandLog::write_queued() {
  Row row;
  bool wrote = false;
  while (ring_.pop(row)) {
    std::fprintf(file_, "%.6f,%s,%.9g,%.9g,%.9g\n", row.t_s, to_text(row.event), row.values[0], row.values[1],
                 row.values[2]);
    wrote = true;
  }
  if (wrote) std::fflush(file_);
}

void CommandLog::writer_loop() {
  while (!stop_.load(std::memory_order_acquire)) {
    std::this_thread::sleep_for(kDrainPeriod);
    write_queued();
  }
}

}  // namespace mhd::plugin_support
