// One process per rig id, with real `mhd run` processes (docs/networking.md, "One process
// per rig"): a second process with a rig id already held is refused, exits non-zero
// naming the holder, and never publishes as the rig (one writer of the rig's state is
// ever seen while both run); the holder counts the refusal and runs on to a clean end.
// The dual: once the holder has ended, the rig can be claimed again.
#include "dds_common/dds_topics.h"
#include "dds_test_support.h"
#include "support/scratch_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

namespace mhd::dds::rig_claim_process_test {

namespace fs = std::filesystem;
using test::ChildProcess;
using namespace std::chrono_literals;

// scenes/desktop_bunny.xml with a dds_state display for rig 5 in `domain`.
fs::path write_scene(const fs::path& dir, std::uint32_t domain) {
  std::ifstream in(fs::path(MHD_SOURCE_DIR) / "scenes/desktop_bunny.xml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string include = "<include file=\"common/materials.xml\"/>";
  text.replace(text.find(include), include.size(),
               "<include file=\"" + std::string(MHD_SOURCE_DIR) + "/scenes/common/materials.xml\"/>");
  const std::string end = "  </plugins>";
  text.replace(text.find(end), end.size(),
               "    <plugin kind=\"display\" name=\"dds_state\"><param name=\"rig_id\" value=\"5\"/>"
               "<param name=\"domain_id\" value=\"" + std::to_string(domain) + "\"/></plugin>\n" + end);
  const fs::path scene = dir / "rig5.xml";
  std::ofstream(scene) << text;
  return scene;
}

// The writers (publication handles) of rig 5's state heard so far.
class RigStateWriters {
 public:
  explicit RigStateWriters(const Participant& p) : sub_(p, rig_partition(5)) {}
  void take() {
    std::array<mhd_dds_RigState, 32> samples{};
    std::array<void*, 32> pointers{};
    std::array<dds_sample_info_t, 32> infos{};
    for (std::size_t i = 0; i < samples.size(); ++i) pointers[i] = &samples[i];
    const dds_return_t n = dds_take(sub_.reader().handle(), pointers.data(), infos.data(), 32, 32);
    for (dds_return_t i = 0; i < n; ++i) {
      if (infos[static_cast<std::size_t>(i)].valid_data) writers_.insert(infos[static_cast<std::size_t>(i)].publication_handle);
    }
  }
  [[nodiscard]] std::size_t count() const { return writers_.size(); }

 private:
  Subscriber<mhd_dds_RigState> sub_;
  std::set<dds_instance_handle_t> writers_;
};

TEST(RigClaimProcess, ASecondProcessWithTheRigIdIsRefusedAndTheHolderRunsOn) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(97);
  const fs::path dir = mhd::test::scratch_dir("rig_claim", "run");
  const fs::path scene = write_scene(dir, domain);
  const Participant viewer(static_cast<dds_domainid_t>(domain));
  RigStateWriters writers(viewer);

  ChildProcess holder({MHD_BIN, "run", scene.string(), "--duration", "7", "-q"}, (dir / "holder.log").string());
  // The holder publishes once its claim has settled (1 s).
  const auto give_up = std::chrono::steady_clock::now() + 10s;
  while (writers.count() == 0 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(50ms);
    writers.take();
  }
  ASSERT_EQ(writers.count(), 1u) << test::read_file((dir / "holder.log").string());

  ChildProcess second({MHD_BIN, "run", scene.string(), "--duration", "4", "-q"}, (dir / "second.log").string());
  std::optional<int> second_rc;
  while (!second_rc && std::chrono::steady_clock::now() < give_up + 5s) {
    second_rc = second.wait_for(50ms);
    writers.take();
  }
  ASSERT_TRUE(second_rc.has_value());
  const std::string second_log = test::read_file((dir / "second.log").string());
  EXPECT_NE(*second_rc, 0) << second_log;
  EXPECT_NE(second_log.find("display_write failed: rig 5 is already claimed by "), std::string::npos) << second_log;
  EXPECT_NE(second_log.find("may not run as rig 5"), std::string::npos) << second_log;
  EXPECT_NE(second_log.find("safe state: zero force sent"), std::string::npos) << second_log;

  const std::optional<int> holder_rc = holder.wait_for(15s);
  writers.take();
  EXPECT_EQ(writers.count(), 1u);  // the second process never published as rig 5
  ASSERT_TRUE(holder_rc.has_value());
  const std::string holder_log = test::read_file((dir / "holder.log").string());
  EXPECT_EQ(*holder_rc, 0) << holder_log;
  EXPECT_NE(holder_log.find("dds_state: rig 5: refused another process's claim of this rig (1 so far)"),
            std::string::npos)
      << holder_log;

  // The holder gone, the rig can be claimed again.
  ChildProcess again({MHD_BIN, "run", scene.string(), "--duration", "2", "-q"}, (dir / "again.log").string());
  const std::optional<int> again_rc = again.wait_for(15s);
  ASSERT_TRUE(again_rc.has_value());
  EXPECT_EQ(*again_rc, 0) << test::read_file((dir / "again.log").string());
  writers.take();
  EXPECT_EQ(writers.count(), 2u);
}

}  // namespace mhd::dds::rig_claim_process_test
