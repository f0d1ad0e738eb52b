// dds_test_rig_claimant --domain-id D --rig-id R: claims rig R as this process, as the
// dds_state display does, and ends as soon as the claim is refused (exit 0) or holds
// (exit 1); 2 when neither came within 5 s.

#include "dds_common/rig_claim.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

int main(int argc, char** argv) {
  std::uint32_t domain = 0;
  std::uint32_t rig = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--domain-id") == 0) domain = static_cast<std::uint32_t>(std::atoi(argv[i + 1]));
    if (std::strcmp(argv[i], "--rig-id") == 0) rig = static_cast<std::uint32_t>(std::atoi(argv[i + 1]));
  }
  const mhd::dds::Participant participant(domain);
  mhd::dds::RigClaim claim(participant, rig, 1'000'000'000);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < end) {
    switch (claim.update(mhd::dds::realtime_ns())) {
      case mhd::dds::RigClaim::Standing::Refused: std::puts(claim.refusal().c_str()); return 0;
      case mhd::dds::RigClaim::Standing::Holding: std::puts("holding"); return 1;
      case mhd::dds::RigClaim::Standing::Settling: break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return 2;
}
