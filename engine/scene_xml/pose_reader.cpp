#include "scene_xml/pose_reader.h"

#include "scene/plausible_bounds.h"
#include "scene_xml/message_text.h"
#include "scene_xml/number_parser.h"

#include <numbers>

namespace mhd::scene_xml {

Pose read_pose_attributes(AttributeParser& a, const DiagnosticSink& sink, double unit_to_m) {
  const Eigen::Vector3d p_m =
      a.vector3("position", Presence::Optional, Bound::Any).value_or(Eigen::Vector3d::Zero()) *
      unit_to_m;
  if (p_m.norm() > kMaxPosition_m) {
    sink.error(a.line_of("position"),
                   concat("attribute 'position' on ", a.tag(), " must lie within ", format_g(kMaxPosition_m),
                          " m of its frame's origin, got ", format_g(p_m.norm()), " m"));
  }
  if (a.has("rpy_deg") && a.has("quaternion_wxyz")) {
    sink.error(a.line(), concat(a.tag(), " takes rpy_deg or quaternion_wxyz, not both"));
  }
  if (a.has("quaternion_wxyz")) {
    const auto q = a.numbers("quaternion_wxyz", Presence::Optional, 4, Bound::Any);
    if (!q) return pose_from_xyz_rpy(p_m, Eigen::Vector3d::Zero());
    const Eigen::Quaterniond quaternion((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    if (quaternion.coeffs().cwiseAbs().maxCoeff() == 0.0) {  // squaredNorm() is 0 for 1e-170 too
      sink.error(a.line_of("quaternion_wxyz"),
                     concat("attribute 'quaternion_wxyz' on ", a.tag(), " must not be all zeros"));
      return pose_from_xyz_rpy(p_m, Eigen::Vector3d::Zero());
    }
    return pose_from_xyz_quaternion(p_m, quaternion);
  }
  const Eigen::Vector3d rpy_deg =
      a.vector3("rpy_deg", Presence::Optional, Bound::Any).value_or(Eigen::Vector3d::Zero());
  return pose_from_xyz_rpy(p_m, rpy_deg * (std::numbers::pi / 180.0));
}

}  // namespace mhd::scene_xml
