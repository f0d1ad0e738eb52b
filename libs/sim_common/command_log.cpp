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

CommandLog::CommandLog(const std::string& path, const char* const* value_names, std::size_t value_count)
    : value_count_(value_count) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error("cannot write the command log '" + path + "': " + std::strerror(errno));
  }
  std::fputs("t_s,event", file_);
  for (std::size_t i = 0; i < value_count_; ++i) std::fprintf(file_, ",%s", value_names[i]);
  std::fputc('\n', file_);
  std::fflush(file_);
  writer_ = std::thread([this] { writer_loop(); });
}

CommandLog::~CommandLog() {
  stop_.store(true, std::memory_order_release);
  writer_.join();
  write_queued();
  if (const std::uint64_t lost = dropped(); lost > 0) {
    std::fprintf(file_, "0,dropped,%llu", static_cast<unsigned long long>(lost));
    for (std::size_t i = 1; i < value_count_; ++i) std::fputs(",0", file_);
    std::fputc('\n', file_);
  }
  std::fclose(file_);
}

void CommandLog::push(const Row& row) noexcept {
  if (!ring_.push(row)) dropped_.fetch_add(1, std::memory_order_relaxed);
}

void CommandLog::write_queued() {
  Row row;
  bool wrote = false;
  while (ring_.pop(row)) {
    std::fprintf(file_, "%.6f,%s", row.t_s, to_text(row.event));
    for (std::size_t i = 0; i < value_count_; ++i) std::fprintf(file_, ",%.9g", row.values[i]);
    std::fputc('\n', file_);
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
