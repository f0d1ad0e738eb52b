#pragma once
// A small RAII layer over Cyclone DDS's C API (ddsc): every entity is deleted with its
// owner, every failing call throws DdsError with dds_strretcode's text. Debian ships no
// C++ binding, and we need only participant, topic, reader, writer and a waitset.

#include <dds/dds.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mhd::dds {

class DdsError : public std::runtime_error {
 public:
  DdsError(std::string what, dds_return_t code);
  [[nodiscard]] dds_return_t code() const noexcept { return code_; }

 private:
  dds_return_t code_;
};

/// Returns `rc` when it is not negative; else throws DdsError "<what>: <dds_strretcode>".
dds_return_t check(dds_return_t rc, const char* what);

/// Owns one dds_entity_t (and its children: DDS deletes them with it).
class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) noexcept : handle_(handle) {}
  ~Entity() { reset(); }
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;

  [[nodiscard]] dds_entity_t handle() const noexcept { return handle_; }
  void reset() noexcept;

 private:
  dds_entity_t handle_ = 0;
};

/// A dds_qos_t, owned.
class Qos {
 public:
  Qos();
  ~Qos();
  Qos(const Qos&) = delete;
  Qos& operator=(const Qos&) = delete;
  Qos(Qos&& other) noexcept : qos_(std::exchange(other.qos_, nullptr)) {}
  Qos& operator=(Qos&&) = delete;

  /// Poses and rig state: best-effort, keep the last `depth` samples per instance.
  [[nodiscard]] static Qos best_effort(std::int32_t depth);
  /// Commands and status: reliable, keep-last `depth`; transient-local keeps the last
  /// samples for late joiners.
  [[nodiscard]] static Qos reliable(std::int32_t depth, bool transient_local = false);
  /// A publisher's or subscriber's QoS: its endpoints live in partition `name`.
  [[nodiscard]] static Qos partition(const std::string& name);

  /// Exclusive ownership: a reader takes each instance from its strongest live writer
  /// only, so a second, weaker writer of the same key cannot interleave.
  Qos& exclusive_ownership();
  /// A writer's ownership strength (meaningful with exclusive ownership).
  Qos& ownership_strength(std::int32_t strength);
  /// Automatic liveliness with `lease_ns`: a writer whose process died without a word
  /// is taken for gone (and loses ownership) after the lease, not the participant's 10 s.
  Qos& automatic_liveliness(dds_duration_t lease_ns);

  [[nodiscard]] const dds_qos_t* get() const noexcept { return qos_; }
  [[nodiscard]] dds_qos_t* get_mutable() noexcept { return qos_; }

 private:
  dds_qos_t* qos_;
};

/// A domain participant. With `config` (Cyclone's configuration: XML or "file://PATH"),
/// the domain is first created with it in this process; if the process already has
/// that domain, the existing one (and its configuration) is used. The domain then lives
/// until the process ends (deleting it would delete other plugins' participants in it).
/// Without `config` the domain takes $CYCLONEDDS_URI. `domain_id` DDS_DOMAIN_DEFAULT:
/// the configuration's.
/// Security (participant_security.h): the identity folder `identity_dir`, else
/// $MHD_DDS_IDENTITY's; with neither the participant is unsecured and the process says
/// so once on stderr. Throws DdsSecurityError naming a missing identity file, DdsError
/// when Cyclone refuses the identity (its log says why).
class Participant {
 public:
  explicit Participant(dds_domainid_t domain_id = DDS_DOMAIN_DEFAULT, const std::string& config = {},
                       const std::optional<std::filesystem::path>& identity_dir = {});
  [[nodiscard]] dds_entity_t handle() const noexcept { return participant_.handle(); }
  /// The identity folder it authenticated with; empty when unsecured.
  [[nodiscard]] const std::filesystem::path& identity_dir() const noexcept { return identity_dir_; }
  [[nodiscard]] bool secured() const noexcept { return !identity_dir_.empty(); }

 private:
  Entity participant_;
  std::filesystem::path identity_dir_;
};

/// A DDS publisher or subscriber whose endpoints all live in one partition
/// (rig_partition.h): DDS takes partitions from these, not from writers and readers.
class PartitionGroup {
 public:
  enum class Side { Publish, Subscribe };
  PartitionGroup(const Participant& participant, Side side, const std::string& partition);
  [[nodiscard]] dds_entity_t handle() const noexcept { return group_.handle(); }

 private:
  Entity group_;
};

/// The topic name, type descriptor and QoS that belong to a sample type.
template <class T>
struct TopicTraits;

class Topic {
 public:
  Topic(const Participant& participant, const dds_topic_descriptor_t& descriptor, const char* name, const Qos& qos);
  [[nodiscard]] dds_entity_t handle() const noexcept { return topic_.handle(); }

 private:
  Entity topic_;
};

template <class T>
class Writer {
 public:
  /// `parent`: a participant or a PartitionGroup (Side::Publish).
  Writer(dds_entity_t parent, const Topic& topic, const Qos& qos)
      : writer_(check(dds_create_writer(parent, topic.handle(), qos.get(), nullptr), "dds_create_writer")) {}
  /// Never blocks for a best-effort writer.
  void write(const T& sample) { check(dds_write(writer_.handle(), &sample), "dds_write"); }
  /// Matched readers seen so far (discovery is asynchronous).
  [[nodiscard]] std::uint32_t matched_readers() const {
    dds_publication_matched_status_t status{};
    check(dds_get_publication_matched_status(writer_.handle(), &status), "dds_get_publication_matched_status");
    return status.current_count;
  }
  [[nodiscard]] dds_entity_t handle() const noexcept { return writer_.handle(); }

 private:
  Entity writer_;
};

/// A reader that copies samples into memory it preallocates (the types are flat), so
/// take() does not allocate.
template <class T>
class Reader {
 public:
  /// `parent`: a participant or a PartitionGroup (Side::Subscribe).
  Reader(dds_entity_t parent, const Topic& topic, const Qos& qos, std::size_t batch = 64)
      : reader_(check(dds_create_reader(parent, topic.handle(), qos.get(), nullptr), "dds_create_reader")),
        samples_(batch),
        pointers_(batch),
        infos_(batch) {
    for (std::size_t i = 0; i < batch; ++i) pointers_[i] = &samples_[i];
  }
  Reader(Reader&&) = delete;

  /// Takes up to `batch` samples with data (never blocks); the span is valid until the
  /// next take().
  std::span<const T> take() {
    const dds_return_t n = check(dds_take(reader_.handle(), pointers_.data(), infos_.data(), pointers_.size(),
                                          static_cast<std::uint32_t>(pointers_.size())),
                                 "dds_take");
    std::size_t kept = 0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      if (!infos_[i].valid_data) continue;  // dispose/unregister notices
      if (kept != i) samples_[kept] = samples_[i];
      ++kept;
    }
    return std::span<const T>(samples_.data(), kept);
  }
  /// Blocks until data is available or `timeout_ns` passes; true when data is there.
  bool wait(dds_duration_t timeout_ns);
  /// Matched writers seen so far.
  [[nodiscard]] std::uint32_t matched_writers() const { return subscription_matched().current_count; }
  /// Matched writers now (current_count) and ever (total_count).
  [[nodiscard]] dds_subscription_matched_status_t subscription_matched() const {
    dds_subscription_matched_status_t status{};
    check(dds_get_subscription_matched_status(reader_.handle(), &status), "dds_get_subscription_matched_status");
    return status;
  }
  [[nodiscard]] dds_entity_t handle() const noexcept { return reader_.handle(); }

 private:
  Entity reader_;
  std::vector<T> samples_;
  std::vector<void*> pointers_;
  std::vector<dds_sample_info_t> infos_;
  Entity waitset_;
  Entity condition_;
};

template <class T>
bool Reader<T>::wait(dds_duration_t timeout_ns) {
  if (waitset_.handle() == 0) {
    const dds_entity_t participant = check(dds_get_participant(reader_.handle()), "dds_get_participant");
    waitset_ = Entity(check(dds_create_waitset(participant), "dds_create_waitset"));
    condition_ = Entity(check(dds_create_readcondition(reader_.handle(), DDS_NOT_READ_SAMPLE_STATE), "dds_create_readcondition"));
    check(dds_waitset_attach(waitset_.handle(), condition_.handle(), 0), "dds_waitset_attach");
  }
  return check(dds_waitset_wait(waitset_.handle(), nullptr, 0, timeout_ns), "dds_waitset_wait") > 0;
}

/// A plugin's `config_file` parameter as a Cyclone configuration URI ("file://ABSOLUTE"):
/// a relative path is relative to the scene file's folder when `scene_file` is given
/// (mhd_host::scene_file, may be NULL), else to the working directory.
[[nodiscard]] std::string config_file_uri(const std::string& file, const char* scene_file);

/// The DDS time (CLOCK_REALTIME, ns) that samples carry.
[[nodiscard]] inline std::int64_t realtime_ns() noexcept { return dds_time(); }

}  // namespace mhd::dds
