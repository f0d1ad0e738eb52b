// A tick that meets more constraint planes than a motion can hold (kMaxHalfSpaces) on the
// 200k-triangle open scan of the bunny (assets/generated/scan_bunny.ply, the benchmark
// scene). The five ticks are those of `mhd-proxy-bench` (200 strokes, seed 1) that ran
// out of work when the store was full: the proxy, 0.1-0.2 m from a HIP that moved round
// the scan, slid over many small faces and collected planes it had long left. Each is
// replayed from the state the bench left before it. Judged by the exact oracle.

#include "proxy/god_object.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

struct RecordedTick {
  V proxy_W, p_W_hip_previous, hip_velocity_W, p_W_hip;
  std::vector<std::pair<V, double>> planes;  ///< normal, offset: the contact the tick starts in
};

// Recorded with std::printf("%.17g"), so they are the bench's states to the bit.
const std::vector<RecordedTick>& recorded_ticks() {
  static const std::vector<RecordedTick> ticks = {
    {V(0.0066945126427382156, -0.02021496099879511, 0.091440747510692102), V(-0.066267820865784338, 0.20658365356264533, 0.16050545567151822), V(-0.058781919929169632, 0.29102070320212536, -0.40230788480406976), V(-0.066326602774305105, 0.20687467422844677, 0.16010314775547985), {{V(0.39837789323814998, -0.90168995095473636, -0.16807821550212371), 0.005525375368648301}, {V(0.17778109953245741, -0.91039135824391415, -0.37360601639137386), -0.014569129794318349}, {V(0.20371593285751743, -0.90780839283879511, -0.36658387933927955), -0.013805613808496138}}},
    {V(0.040544625230204197, -0.021029276183752312, 0.096154785895159189), V(0.081761367728521994, 0.18220691584367291, 0.17784074739661257), V(-0.0058900646879034993, 0.34984206135334045, -0.35717760181030217), V(0.081755477663766604, 0.1825567579048932, 0.1774835697946576), {{V(-0.13317321489831091, -0.93802589012100068, -0.3199567537908094), -0.01643882573435413}, {V(-0.30494495490471774, -0.82837647666382974, -0.46989465562844934), -0.040126341205798957}}},
    {V(-0.11423723606543354, 0.090897146100701695, -0.012588383853614526), V(-0.23132467397566817, 0.13426311657488313, 0.039163535297311224), V(0.021149671663289973, -0.092529175157217119, 0.49090838561568395), V(-0.23130352430286247, 0.13417058739904605, 0.039654443682816218), {{V(0.89728616212438228, -0.31823267284652162, -0.30595017436349925), -0.12757851464362899}, {V(0.85573085636685176, -0.33141596090099834, -0.39735143427666453), -0.12287908048591921}, {V(0.94278595523444619, -0.21030205019912393, -0.25870386602197915), -0.12356045433962083}}},
    {V(-0.12798264686764557, 0.084675231756583189, 0.028703268373448727), V(-0.1724015692930414, 0.20673030175975635, -0.0019558798140704645), V(0.10975573446119861, 0.058616926968771493, -0.48426994261802314), V(-0.17229180942109057, 0.20678891370005442, -0.0024401497914217736), {{V(0.33559626149639588, -0.91281436986528408, 0.23269094403755153), -0.11356427552949659}, {V(0.2410774057839338, -0.96139159395082963, 0.13269471542292752), -0.10845100849030798}}},
    {V(-0.0075585097133439305, -0.075300192510577013, 0.10385728994790533), V(-0.11870877164673836, -0.10181235424073869, 0.2200422308175248), V(-0.39837946975667227, 0.28609576146405891, -0.097152873091521874), V(-0.11910711856604717, -0.10152622730346829, 0.21994501401010219), {{V(0.65035440536121281, 0.14606995699864225, -0.74545470358008881), -0.093335711264795312}, {V(0.79701844919752607, 0.22030168043854112, -0.5623422100773916), -0.081016368599353128}, {V(0.52774235845564477, 0.21854984576169803, -0.82080690056139993), -0.10569257146438961}}},
  };
  return ticks;
}

TEST(ProxyConstraintStore, ATickThatOutgrowsItsStoreDropsPlanesItHasLeftAndGoesOn) {
  const std::string file = std::string(MHD_SOURCE_DIR) + "/scenes/benchmarks/scan_bunny.xml";
  const auto read = read_scene_file(file);
  ASSERT_TRUE(read.ok()) << file;
  const auto compiled = compile_scene(*read);
  ASSERT_TRUE(compiled.ok()) << file;
  const CompiledScene& scene = *compiled.value();
  const verify::SurfaceCrossingOracle oracle(scene.world);
  int reached = 0;
  for (std::size_t i = 0; i < recorded_ticks().size(); ++i) {
    const RecordedTick& r = recorded_ticks()[i];
    ProxyState state;
    state.initialised = true;
    state.proxy_W = r.proxy_W;
    state.p_W_hip = r.p_W_hip_previous;
    state.hip_velocity_W = r.hip_velocity_W;
    state.plane_count = static_cast<int>(r.planes.size());
    for (std::size_t k = 0; k < r.planes.size(); ++k) {
      state.planes[k] = ConstraintPlane{r.planes[k].first, r.planes[k].second, TriangleRef{0, 0}};
    }
    const V start = state.proxy_W;
    const ProxyOutput out = step_proxy(scene.world, scene.materials, scene.proxy, state, r.p_W_hip, 1e-3);
    EXPECT_FALSE(out.budget_exhausted) << "tick " << i << ": " << out.sweeps << " sweeps";
    // Safety first: every leg of the path is crossing-free.
    V at = start;
    for (int k = 1; k < state.path_points; ++k) {
      const V next = state.path_W[static_cast<std::size_t>(k)];
      EXPECT_FALSE(oracle.segment_touches_surface(at, next)) << "tick " << i << ", leg " << k;
      at = next;
    }
    // And it follows: a HIP in free view of where the proxy ended is where it ended.
    if (!oracle.segment_touches_surface(out.proxy_W, r.p_W_hip)) {
      EXPECT_EQ(out.proxy_W, r.p_W_hip) << "tick " << i;
      EXPECT_EQ(out.force_W, V::Zero()) << "tick " << i;
    }
    reached += out.proxy_W == r.p_W_hip ? 1 : 0;
  }
  std::printf("%d of %zu ticks end at the HIP\n", reached, recorded_ticks().size());
}

}  // namespace
}  // namespace mhd
