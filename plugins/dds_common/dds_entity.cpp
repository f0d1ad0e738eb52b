#include "dds_common/dds_entity.h"

#include <filesystem>

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

Participant::Participant(dds_domainid_t domain_id, const std::string& config) {
  if (!config.empty()) {
    if (domain_id == DDS_DOMAIN_DEFAULT) {
      throw DdsError("a DDS configuration needs an explicit domain id", DDS_RETCODE_BAD_PARAMETER);
    }
    const dds_entity_t domain = dds_create_domain(domain_id, config.c_str());
    // PRECONDITION_NOT_MET: this process already has the domain; use it as it is.
    if (domain != DDS_RETCODE_PRECONDITION_NOT_MET) check(domain, "dds_create_domain");
  }
  participant_ = Entity(check(dds_create_participant(domain_id, nullptr, nullptr), "dds_create_participant"));
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
