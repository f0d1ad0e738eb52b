// mhd-dds-force-latency-bench [--samples N] [--rate-hz R] [--security DIR]: tracker
// sample published -> force computed from it, across processes on loopback
// (config/cyclonedds-loopback.xml). With --security DIR (make_rig_security.sh DIR 44)
// under DDS Security too (config/cyclonedds-secure.xml): the publisher as
// DIR/identities/tracker-rig44, the haptic server as haptic-rig44.
//
// A child process (dds_server_step_publisher) publishes base-sensor samples of the
// thesis rig, the base 0.1 mm further along x in each, stamped with dds_time() just
// before the write. This process runs the haptic server (the `dds` tracker plugin,
// fault_device, predict_base_pose false so a tick uses the newest sample as it is) and
// records every tick. Measured from outside the engine: the first recorded tick whose
// base pose is sample i's computed the HIP and the force from it; its tracker_age_s is
// that tick's time minus sample i's stamp (the plugin maps the stamp onto the host clock
// exactly on one host), i.e. the latency from publish to force. Prints median and p99.
#include "dds_server_support.h"
#include "dds_test_support.h"

#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace mhd;
using namespace mhd::dds_server_test;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  long samples = 1900;
  double rate_hz = 190.0;
  std::string security_dir;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--samples") samples = std::strtol(argv[i + 1], nullptr, 10);
    else if (flag == "--rate-hz") rate_hz = std::strtod(argv[i + 1], nullptr);
    else if (flag == "--security") security_dir = fs::absolute(argv[i + 1]).string();
    else {
      std::fprintf(stderr, "usage: %s [--samples N] [--rate-hz R] [--security DIR]\n", argv[0]);
      return 2;
    }
  }
  if (samples < 10 || !(rate_hz > 0.0)) {
    std::fprintf(stderr, "mhd-dds-force-latency-bench: need --samples >= 10 and --rate-hz > 0\n");
    return 2;
  }
  try {
    const fs::path dir = fs::temp_directory_path() / fmt::format("mhd-dds-force-latency-{}", ::getpid());
    fs::create_directories(dir);
    const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(31);
    // Each process's identity through MHD_DDS_IDENTITY: the server's participants are
    // made when it opens, the publisher's environment is copied when it starts.
    const auto use_identity = [&](const char* name) {
      if (!security_dir.empty()) setenv("MHD_DDS_IDENTITY", (fs::path(security_dir) / "identities" / name).c_str(), 1);
    };
    if (!security_dir.empty()) {
      const std::string uri = std::string(std::getenv("CYCLONEDDS_URI")) + ",file://" + MHD_SOURCE_DIR +
                              "/config/cyclonedds-secure.xml";
      setenv("CYCLONEDDS_URI", uri.c_str(), 1);
    }
    use_identity("haptic-rig44");
    SceneOptions o;
    o.domain_id = domain;
    o.rig_id = 44;
    o.log_base = false;
    o.state_display = false;
    o.server_params = "\n    <param name=\"predict_base_pose\" value=\"false\"/>";
    const LoadedScene scene = load_scene(write_server_scene(dir, o));
    if (!scene.compiled) {
      for (const auto& e : scene.errors) std::fprintf(stderr, "%s\n", e.c_str());
      return 1;
    }
    ServerOptions options;
    options.plugin_path = plugin_dirs();
    options.recording = dir / "run.csv";

    const Rig rig = thesis_rig();
    constexpr double kStep_m = 1e-4;
    const double x0_m = -0.25;  // far from the wall at first; 0.19 m of travel at 1900 samples
    const Pose X0 = rig.X_is900_base_sensor_from_base(BasePose{x0_m, 0.0, 0.0});
    const Pose X1 = rig.X_is900_base_sensor_from_base(BasePose{x0_m + kStep_m, 0.0, 0.0});
    const Eigen::Quaterniond q(X0.rotation());
    const Eigen::Vector3d d = X1.translation() - X0.translation();
    std::vector<std::string> args{MHD_DDS_SERVER_STEP_PUBLISHER, std::to_string(domain), "44", std::to_string(samples),
                                  fmt::format("{}", rate_hz)};
    for (double v : {X0.translation().x(), X0.translation().y(), X0.translation().z(), q.w(), q.x(), q.y(), q.z(),
                     d.x(), d.y(), d.z()}) {
      args.push_back(fmt::format("{}", v));
    }

    ServerReport report;
    std::optional<int> rc;
    {
      ServerThread server(scene, options);
      if (!server.opened()) {
        for (const auto& e : server.errors()) std::fprintf(stderr, "%s\n", e.c_str());
        return 1;
      }
      use_identity("tracker-rig44");
      dds::test::ChildProcess publisher(args, (dir / "publisher.log").string());
      rc = publisher.wait_for(std::chrono::milliseconds(static_cast<long>(20'000 + 1000.0 * static_cast<double>(samples) / rate_hz)));
      report = server.stop();
    }
    if (rc != 0) {
      std::fprintf(stderr, "mhd-dds-force-latency-bench: the publisher failed: %s\n",
                   dds::test::read_file((dir / "publisher.log").string()).c_str());
      return 1;
    }
    if (report.error) {
      std::fprintf(stderr, "mhd-dds-force-latency-bench: %s\n", report.error->c_str());
      return 1;
    }

    // The first tick showing each sample's base pose.
    std::map<long, double> latency_by_sample;
    for (const Row& r : read_recording(options.recording)) {
      if (!std::isfinite(r.base_x_m) || r.tracker_age_s < 0.0) continue;
      const double k = (r.base_x_m - x0_m) / kStep_m;
      const long i = std::lround(k);
      if (std::abs(k - static_cast<double>(i)) > 1e-3 || i < 0 || i >= samples) continue;
      latency_by_sample.emplace(i, r.tracker_age_s);
    }
    std::vector<double> us;
    for (const auto& [i, age_s] : latency_by_sample) us.push_back(age_s * 1e6);
    if (us.empty()) {
      std::fprintf(stderr, "mhd-dds-force-latency-bench: no sample reached the haptic loop\n");
      return 1;
    }
    std::sort(us.begin(), us.end());
    const auto at = [&](double p) { return us[std::min(us.size() - 1, static_cast<std::size_t>(p * static_cast<double>(us.size())))]; };
    std::printf("tracker sample published -> force computed from it (loopback, %s, %.0f Hz, haptic and io at 1 kHz)\n",
                security_dir.empty() ? "unsecured" : "DDS Security", rate_hz);
    std::printf("samples published %ld, seen by the haptic loop %zu\n", samples, us.size());
    std::printf("median %.0f us  p99 %.0f us  min %.0f us  max %.0f us\n", at(0.5), at(0.99), us.front(), us.back());
    std::printf("haptic scheduling: %s\n", report.haptic_scheduling.c_str());
    fs::remove_all(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mhd-dds-force-latency-bench: %s\n", e.what());
    return 1;
  }
}
