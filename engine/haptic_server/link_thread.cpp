// Shared objects (docs/shared-objects.md): the link thread carries messages between the
// haptic thread's rings and the link plugin, and the haptic thread's two steps hand them
// to and from its tick (RigSharing). Each kHz period the link thread:
//   1. sends what the haptic thread queued (link_send, in batches);
//   2. reads what the other rigs sent (link_read) and queues it for the haptic thread.
#include "haptic_server/server_impl.h"

#include "haptic_server/haptic_tick.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"

#include <array>
#include <cstddef>

namespace mhd {
namespace {

constexpr double kLinkPeriod_s = 0.001;
constexpr std::size_t kBatch = PluginInstance::kMaxLinkMessagesPerCall;

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<double, 3> arr(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

SharedObjectState state_of(const LinkMessage& m) {
  SharedObjectState s;
  s.authority_rig = m.rig_id;
  s.epoch = m.term;
  s.sequence = m.sequence;
  s.t_s = m.timestamp_s;
  const Eigen::Quaterniond q(m.q_W_wxyz[0], m.q_W_wxyz[1], m.q_W_wxyz[2], m.q_W_wxyz[3]);
  s.X_WO = Pose::Identity();
  s.X_WO.linear() = q.normalized().toRotationMatrix();
  s.X_WO.translation() = vec(m.p_W_m);
  s.twist_W.v_W_origin_mps = vec(m.v_W_mps);
  s.twist_W.omega_W_radps = vec(m.w_W_radps);
  return s;
}

SharedPush push_of(const LinkMessage& m) {
  return SharedPush{-1, m.rig_id, m.sequence, m.timestamp_s, vec(m.f_W_N), vec(m.p_O_m)};
}

LinkMessage message_of(const SharingMessage& out) {
  LinkMessage m;
  m.object_id = out.object_id;
  if (out.kind == SharingMessage::Kind::State) {
    const SharedObjectState& s = out.state;
    m.kind = LinkMessageKind::State;
    m.rig_id = s.authority_rig;
    m.term = s.epoch;
    m.sequence = s.sequence;
    m.timestamp_s = s.t_s;
    const Eigen::Quaterniond q(s.X_WO.linear());
    m.p_W_m = arr(s.X_WO.translation());
    m.q_W_wxyz = {q.w(), q.x(), q.y(), q.z()};
    m.v_W_mps = arr(s.twist_W.v_W_origin_mps);
    m.w_W_radps = arr(s.twist_W.omega_W_radps);
  } else {
    const SharedPush& p = out.push;
    m.kind = LinkMessageKind::Push;
    m.rig_id = p.from_rig;
    m.sequence = p.sequence;
    m.timestamp_s = p.t_s;
    m.f_W_N = arr(p.f_W_N);
    m.p_O_m = arr(p.p_O_m);
  }
  return m;
}

}  // namespace

void HapticServer::Impl::link_thread() {
  realtime::name_current_thread("mhd-link");
  realtime::PeriodicTimer timer(kLinkPeriod_s);
  std::array<LinkMessage, kBatch> batch{};
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    // 1. Send.
    for (std::size_t n = batch.size(); n == batch.size();) {
      n = 0;
      while (n < batch.size() && link_from_haptic.pop(batch[n])) ++n;
      if (n == 0) break;
      const InCall in_call(*link, "link_send", host.now_s());
      auto r = link->instance.link_send(std::span<const LinkMessage>(batch.data(), n));
      if (check(r, *link) || deactivated(r.value(), *link, "link_send")) return;
    }
    // 2. Receive.
    std::size_t count = 0;
    auto r = [&] {
      const InCall in_call(*link, "link_read", host.now_s());
      return link->instance.link_read(batch, count);
    }();
    if (check(r, *link) || deactivated(r.value(), *link, "link_read")) return;
    for (std::size_t i = 0; i < count; ++i) {
      if (!link_to_haptic.push(batch[i])) link_dropped.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

void HapticServer::Impl::receive_shared(HapticTick& tick, double t_s) {
  RigSharing* sharing = tick.sharing();
  LinkMessage m;
  while (link_to_haptic.pop(m)) {
    if (sharing == nullptr) continue;
    if (m.kind == LinkMessageKind::State) {
      sharing->receive_state(m.object_id, state_of(m), t_s);
    } else {
      sharing->receive_push(m.object_id, push_of(m));
    }
  }
}

void HapticServer::Impl::send_shared(const HapticTick& tick) {
  const RigSharing* sharing = tick.sharing();
  if (sharing == nullptr || link == nullptr) return;
  for (const SharingMessage& out : sharing->outbox()) {
    if (!link_from_haptic.push(message_of(out))) link_dropped.fetch_add(1, std::memory_order_relaxed);
  }
}

void HapticServer::Impl::note_shared_objects(const HapticTick& tick, double t_s) {
  const RigSharing* sharing = tick.sharing();
  if (sharing == nullptr) return;
  sharing_counters = sharing->counters();
  shared_final_count = sharing->object_count();
  for (int s = 0; s < shared_final_count; ++s) {
    const SharedObjectDeclaration& d = sharing->declaration(s);
    shared_final[static_cast<std::size_t>(s)] = {d.object,
                                                 d.id,
                                                 sharing->authority(s),
                                                 sharing->holds(d.object),
                                                 tick.world().pose(d.object).translation(),
                                                 sharing->state_age_s(s, t_s)};
  }
}

}  // namespace mhd
