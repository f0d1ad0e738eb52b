// dds_security_rig_writer: a second writer of one rig's tracker samples, as an intruder
// or a stray tracker would be (tests/dds_security).
//
//   dds_security_rig_writer --domain-id D --rig-id R --identity DIR|none
//                           [--strength S] [--seconds T] [--x-m X]
//
// Writes sensor 0 of rig R in R's partition at 200 Hz for T seconds, every sample at
// p_T = (X, 1, 0) with sequence numbers from 1e9 up (higher than any real tracker's:
// a rig takeover). "none": no identity (unsecured). Prints one line,
//   refused: WHAT                       exit 3: the identity may not write (DDS Security)
//   wrote N samples, matched readers: M exit 0: M the most readers matched at once

#include "dds_common/dds_topics.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

int main(int argc, char** argv) {
  std::uint32_t domain_id = 0;
  std::uint32_t rig_id = 0;
  std::optional<std::filesystem::path> identity;
  bool identity_given = false;
  std::int32_t strength = mhd::dds::kDefaultOwnershipStrength;
  double seconds = 2.0;
  double x_m = 3.21;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const std::string value = argv[i + 1];
    if (flag == "--domain-id") domain_id = static_cast<std::uint32_t>(std::stoul(value));
    else if (flag == "--rig-id") rig_id = static_cast<std::uint32_t>(std::stoul(value));
    else if (flag == "--strength") strength = std::stoi(value);
    else if (flag == "--seconds") seconds = std::stod(value);
    else if (flag == "--x-m") x_m = std::stod(value);
    else if (flag == "--identity") {
      identity_given = true;
      if (value != "none") identity = value;
    } else {
      std::fprintf(stderr, "dds_security_rig_writer: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  if (!identity_given) {
    std::fprintf(stderr, "dds_security_rig_writer: --identity DIR|none is required\n");
    return 2;
  }
  try {
    const mhd::dds::Participant participant(static_cast<dds_domainid_t>(domain_id), {}, identity);
    std::optional<mhd::dds::Publisher<mhd_dds_TrackerSample>> publisher;
    try {
      publisher.emplace(participant, mhd::dds::rig_partition(rig_id), strength);
    } catch (const mhd::dds::DdsError& e) {
      if (e.code() != DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) throw;
      std::printf("refused: %s\n", e.what());
      return 3;
    }
    std::uint32_t matched_max = 0;
    std::uint64_t written = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    auto next = std::chrono::steady_clock::now();
    for (std::uint64_t i = 0; std::chrono::steady_clock::now() < end; ++i) {
      mhd_dds_TrackerSample s{};
      s.rig_id = rig_id;
      s.sensor_id = 0;
      s.sequence_number = 1'000'000'000ull + i;
      s.timestamp_ns = mhd::dds::realtime_ns();
      s.p_T_m[0] = x_m;
      s.p_T_m[1] = 1.0;
      s.q_T_wxyz[0] = 1.0;
      publisher->write(s);
      ++written;
      matched_max = std::max(matched_max, publisher->writer().matched_readers());
      next += std::chrono::milliseconds(5);
      std::this_thread::sleep_until(next);
    }
    std::printf("wrote %llu samples, matched readers: %u\n", static_cast<unsigned long long>(written),
                static_cast<unsigned>(matched_max));
    return 0;
  } catch (const std::exception& e) {
    std::printf("error: %s\n", e.what());
    return 1;
  }
}
