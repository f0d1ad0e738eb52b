#include "dds_common/security_refusal_log.h"

#include <dds/dds.h>
#include <dds/ddsrt/log.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace mhd::dds {
namespace {

std::atomic<std::uint64_t> g_refusals{0};
std::mutex g_install_mutex;  // instances come and go on plugin open/close, never in a tick
int g_instances = 0;

// The latest error messages, for errors_since(). Cyclone logs errors rarely and from its
// own threads, never from a tick, so a lock is fine here.
constexpr std::size_t kKeptErrors = 8;
std::mutex g_errors_mutex;
std::deque<std::string> g_errors;
std::uint64_t g_error_count = 0;

void keep_error(const char* message, std::size_t size) {
  std::string_view text(message, size);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
  const std::lock_guard lock(g_errors_mutex);
  g_errors.emplace_back(text);
  if (g_errors.size() > kKeptErrors) g_errors.pop_front();
  ++g_error_count;
}

void sink(void* /*unused*/, const dds_log_data_t* data) {
  // As Cyclone's default log sink: the header (time, thread) then the message.
  std::fwrite(data->message - data->hdrsize, 1, data->hdrsize + data->size, stderr);
  if (data->size == 0 || data->message[data->size - 1] != '\n') std::fputc('\n', stderr);  // some lack one
  std::fflush(stderr);
  if ((data->priority & (DDS_LC_ERROR | DDS_LC_FATAL)) != 0) keep_error(data->message, data->size);
  if ((data->priority & (DDS_LC_ERROR | DDS_LC_WARNING)) != 0 &&
      SecurityRefusalLog::is_refusal(data->message, data->size)) {
    g_refusals.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace

bool SecurityRefusalLog::is_refusal(const char* message, std::uint64_t size) {
  const std::string_view m(message, size);
  // Cyclone 0.10's messages for a peer it drops (ddsi security core and handshake):
  // "Could not get remote participant … permissions from plugin", "Could not
  // authenticate_peer_credential_token … remote participant …", "… handshake … failed" (matched as written there).
  constexpr std::array<std::string_view, 3> kRemote = {"permissions", "authenticat", "not allowed"};
  if (m.find("remote participant") != std::string_view::npos) {
    for (const std::string_view k : kRemote) {
      if (m.find(k) != std::string_view::npos) return true;
    }
  }
  const bool handshake = m.find("handshake") != std::string_view::npos || m.find("Handshake") != std::string_view::npos;
  return handshake && (m.find("failed") != std::string_view::npos || m.find("Failed") != std::string_view::npos);
}

SecurityRefusalLog::SecurityRefusalLog() {
  const std::lock_guard lock(g_install_mutex);
  if (g_instances++ == 0) dds_set_log_sink(&sink, nullptr);
}

SecurityRefusalLog::~SecurityRefusalLog() {
  const std::lock_guard lock(g_install_mutex);
  if (--g_instances == 0) dds_set_log_sink(nullptr, nullptr);
}

std::uint64_t SecurityRefusalLog::error_count() {
  const std::lock_guard lock(g_errors_mutex);
  return g_error_count;
}

std::vector<std::string> SecurityRefusalLog::errors_since(std::uint64_t mark) {
  const std::lock_guard lock(g_errors_mutex);
  const std::uint64_t newer = g_error_count - std::min<std::uint64_t>(mark, g_error_count);
  const std::size_t keep = static_cast<std::size_t>(std::min<std::uint64_t>(newer, g_errors.size()));
  return {g_errors.end() - static_cast<std::ptrdiff_t>(keep), g_errors.end()};
}

std::uint64_t SecurityRefusalLog::refusals() { return g_refusals.load(std::memory_order_relaxed); }

}  // namespace mhd::dds
