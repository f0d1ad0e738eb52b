#include "dds_common/security_refusal_log.h"

#include <dds/dds.h>
#include <dds/ddsrt/log.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <string_view>

namespace mhd::dds {
namespace {

std::atomic<std::uint64_t> g_refusals{0};
std::mutex g_install_mutex;  // instances come and go on plugin open/close, never in a tick
int g_instances = 0;

void sink(void* /*unused*/, const dds_log_data_t* data) {
  // As Cyclone's default log sink: the header (time, thread) then the message.
  std::fwrite(data->message - data->hdrsize, 1, data->hdrsize + data->size, stderr);
  std::fflush(stderr);
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

std::uint64_t SecurityRefusalLog::refusals() { return g_refusals.load(std::memory_order_relaxed); }

}  // namespace mhd::dds
