#include "dds_common/dds_entity.h"

#include "dds_common/participant_security.h"
#include "dds_common/security_refusal_log.h"

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <string>

namespace mhd::dds {

DdsError::DdsError(std::string what, dds_return_t code) : std::runtime_error(std::move(what)), code_(code) {}

dds_return_t check(dds_return_t rc, const char* what) {
  if (rc < 0) throw DdsError(std::string(what) + ": " + dds_strretcode(rc), rc);
  return rc;
}

void Entity::reset() noexcept {
  if (handle_ > 0) dds_delete(handle_);
  handle_ = 0;
}

Qos::Qos() : qos_(dds_create_qos()) {
  if (qos_ == nullptr) throw DdsError("dds_create_qos: out of memory", DDS_RETCODE_OUT_OF_RESOURCES);
}

Qos::~Qos() {
  if (qos_ != nullptr) dds_delete_qos(qos_);
}

Qos Qos::best_effort(std::int32_t depth) {
  Qos q;
  dds_qset_reliability(q.qos_, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_history(q.qos_, DDS_HISTORY_KEEP_LAST, depth);
  dds_qset_durability(q.qos_, DDS_DURABILITY_VOLATILE);
  return q;
}

Qos Qos::reliable(std::int32_t depth, bool transient_local) {
  Qos q;
  dds_qset_reliability(q.qos_, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(q.qos_, DDS_HISTORY_KEEP_LAST, depth);
  dds_qset_durability(q.qos_, transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  return q;
}

Qos Qos::partition(const std::string& name) {
  Qos q;
  dds_qset_partition1(q.qos_, name.c_str());
  return q;
}

Qos& Qos::exclusive_ownership() {
  dds_qset_ownership(qos_, DDS_OWNERSHIP_EXCLUSIVE);
  return *this;
}

Qos& Qos::ownership_strength(std::int32_t strength) {
  dds_qset_ownership_strength(qos_, strength);
  return *this;
}

Qos& Qos::automatic_liveliness(dds_duration_t lease_ns) {
  dds_qset_liveliness(qos_, DDS_LIVELINESS_AUTOMATIC, lease_ns);
  return *this;
}

namespace {

/// What Cyclone logged since `mark`, as "; Cyclone DDS said: A; B" ("" when nothing).
std::string cyclone_said(std::uint64_t mark) {
  std::string said;
  for (const std::string& line : SecurityRefusalLog::errors_since(mark)) said += (said.empty() ? "" : "; ") + line;
  return said.empty() ? said : "; Cyclone DDS said: " + said;
}

bool mentions(const std::string& text, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) { return text.find(w) != std::string::npos; });
}

/// A participant or domain Cyclone would not create, with the cause it logged and what
/// to do about it; `identity_hint` is said only when nothing points elsewhere.
[[noreturn]] void refuse(const std::string& what, dds_return_t rc, std::uint64_t mark, const std::string& identity_hint) {
  const std::string said = cyclone_said(mark);
  std::string hint;
  if (mentions(said, {"participant index"})) {
    hint = " (every participant index this configuration allows on this host is held by another DDS process in "
           "this domain, even an idle one: stop those processes, or raise Discovery/MaxAutoParticipantIndex in "
           "the Cyclone configuration, docs/networking.md)";
  } else if (mentions(said, {"ddress in use", "bind"})) {
    hint = " (another process holds the ports of this domain: use another domain id)";
  } else if (said.empty() || mentions(said, {"ertificate", "ermission", "overnance", "dentity", "CA", "sign", "xpired",
                                             "ecurity", "uthenticat"})) {
    hint = identity_hint;
  }
  throw DdsError(what + ": " + dds_strretcode(rc) + said + hint, rc);
}

}  // namespace

Participant::Participant(dds_domainid_t domain_id, const std::string& config,
                         const std::optional<std::filesystem::path>& identity_dir) {
  // Cyclone reports most failures as a bare "Error" and logs the cause: keep the log.
  const SecurityRefusalLog log;
  const std::uint64_t mark = SecurityRefusalLog::error_count();
  if (!config.empty()) {
    if (domain_id == DDS_DOMAIN_DEFAULT) {
      throw DdsError("a DDS configuration needs an explicit domain id", DDS_RETCODE_BAD_PARAMETER);
    }
    const dds_entity_t domain = dds_create_domain(domain_id, config.c_str());
    // PRECONDITION_NOT_MET: this process already has the domain; use it as it is.
    if (domain < 0 && domain != DDS_RETCODE_PRECONDITION_NOT_MET) refuse("dds_create_domain", domain, mark, "");
  }
  const std::optional<std::filesystem::path> identity = resolve_identity_dir(identity_dir);
  if (!identity) {
    const dds_entity_t participant = dds_create_participant(domain_id, nullptr, nullptr);
    if (participant < 0) {
      refuse("dds_create_participant", participant, mark,
             std::string(" (no DDS identity given: if the Cyclone configuration has a Security section, such as "
                         "config/cyclonedds-secure.xml, set ") +
                 kIdentityEnv + ")");
    }
    participant_ = Entity(participant);
    warn_unsecured_once();
    return;
  }
  // Checked here: Cyclone reports any bad identity file as a bare "Error".
  const IdentityFiles files = IdentityFiles::in_folder(*identity);
  Qos qos;
  apply_identity(qos.get_mutable(), files);
  const dds_entity_t participant = dds_create_participant(domain_id, qos.get(), nullptr);
  if (participant < 0) {
    refuse("dds_create_participant with DDS identity '" + identity->string() + "'", participant, mark,
           " (Cyclone refused the identity: a certificate or permissions not signed by the CA, or expired)");
  }
  participant_ = Entity(participant);
  identity_dir_ = *identity;
}

PartitionGroup::PartitionGroup(const Participant& participant, Side side, const std::string& partition) {
  const Qos qos = Qos::partition(partition);
  group_ = Entity(side == Side::Publish
                      ? check(dds_create_publisher(participant.handle(), qos.get(), nullptr), "dds_create_publisher")
                      : check(dds_create_subscriber(participant.handle(), qos.get(), nullptr), "dds_create_subscriber"));
}

Topic::Topic(const Participant& participant, const dds_topic_descriptor_t& descriptor, const char* name,
             const Qos& qos)
    : topic_(check(dds_create_topic(participant.handle(), &descriptor, name, qos.get(), nullptr),
                   "dds_create_topic")) {}

std::string config_file_uri(const std::string& file, const char* scene_file) {
  std::filesystem::path path(file);
  if (path.is_relative() && scene_file != nullptr && scene_file[0] != '\0') {
    path = std::filesystem::path(scene_file).parent_path() / path;
  }
  return "file://" + std::filesystem::absolute(path).lexically_normal().string();
}

}  // namespace mhd::dds
