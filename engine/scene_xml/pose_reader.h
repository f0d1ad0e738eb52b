#pragma once
// The pose attributes shared by <pose>, <frame> and a motion's <key>: position (scene
// units), and rpy_deg or quaternion_wxyz.

#include "geometry/pose.h"
#include "scene_xml/diagnostic_sink.h"
#include "scene_xml/xml_attribute_parser.h"

namespace mhd::scene_xml {

/// The pose `a`'s element gives; every fault reported to `sink` at its line (the pose
/// then falls back to what could be read: identity rotation, zero position).
[[nodiscard]] Pose read_pose_attributes(AttributeParser& a, const DiagnosticSink& sink, double unit_to_m);

}  // namespace mhd::scene_xml
