#include "scene_xml/motion_reader.h"

#include "scene_xml/message_text.h"
#include "scene_xml/pose_reader.h"
#include "scene_xml/xml_attribute_parser.h"

#include <tinyxml2.h>

#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mhd::scene_xml {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct RepeatName {
  std::string_view name;
  MotionRepeat repeat;
};
constexpr RepeatName kRepeats[] = {
    {"hold", MotionRepeat::Hold}, {"loop", MotionRepeat::Loop}, {"pingpong", MotionRepeat::PingPong}};

std::optional<MotionRepeat> read_repeat(AttributeParser& a, const DiagnosticSink& sink) {
  const auto text = a.token("repeat", Presence::Optional);
  if (!text) return MotionRepeat::Hold;
  for (const RepeatName& r : kRepeats) {
    if (*text == r.name) return r.repeat;
  }
  sink.error(a.line_of("repeat"), concat("attribute 'repeat' on ", a.tag(), " must be hold, loop or pingpong, got '",
                                         *text, "'"));
  return std::nullopt;
}

// Refuses a motion faster than a hand can follow, naming the element's line.
bool within_limits(const ObjectMotion& m, int line, const DiagnosticSink& sink) {
  bool ok = true;
  if (m.max_speed_mps() > kMaxObjectSpeed_mps) {
    sink.error(line, concat("<motion> moves the object at up to ", format_g(m.max_speed_mps()), " m/s; at most ",
                            format_g(kMaxObjectSpeed_mps), " m/s can be rendered"));
    ok = false;
  }
  if (m.max_rate_radps() / kDeg > kMaxObjectRate_deg_s) {
    sink.error(line, concat("<motion> turns the object at up to ", format_g(m.max_rate_radps() / kDeg),
                            " deg/s; at most ", format_g(kMaxObjectRate_deg_s), " deg/s can be rendered"));
    ok = false;
  }
  return ok;
}

std::optional<ObjectMotion> read_keyframes(const tinyxml2::XMLElement& e, AttributeParser& a,
                                           const DiagnosticSink& sink, double unit_to_m) {
  const auto repeat = read_repeat(a, sink);
  std::vector<PoseKey> keys;
  std::vector<int> key_lines;
  bool ok = repeat.has_value();
  for (const tinyxml2::XMLElement* c = e.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "key") {
      sink.error(c->GetLineNum(), concat("unknown element <", c->Name(), "> in <motion> (expected <key>)"));
      ok = false;
      continue;
    }
    if (static_cast<int>(keys.size()) >= kMaxMotionKeys) {
      sink.error(c->GetLineNum(), concat("<motion> has more than ", kMaxMotionKeys, " keys"));
      return std::nullopt;
    }
    if (c->FirstChildElement() != nullptr) {
      sink.error(c->FirstChildElement()->GetLineNum(), "<key> takes attributes only");
      ok = false;
    }
    AttributeParser ka(*c, sink, {"t_s", "position", "rpy_deg", "quaternion_wxyz"});
    const std::size_t errors_before = sink.error_count();
    const auto t_s = ka.number("t_s", Presence::Required, Bound::Any);
    const Pose X_WO = read_pose_attributes(ka, sink, unit_to_m);
    if (!t_s || sink.error_count() != errors_before) {
      ok = false;
      continue;
    }
    keys.push_back({*t_s, X_WO});
    key_lines.push_back(c->GetLineNum());
  }
  if (!ok) return std::nullopt;
  try {
    return ObjectMotion::keyframes(std::move(keys), *repeat);
  } catch (const std::invalid_argument& error) {
    // ObjectMotion names the key ("motion key 3: ..."): point at its line.
    const std::string what = error.what();
    int line = e.GetLineNum();
    if (what.rfind("motion key ", 0) == 0) {
      const std::size_t k = std::stoul(what.substr(11)) - 1;
      if (k < key_lines.size()) line = key_lines[k];
    }
    sink.error(line, what);
    return std::nullopt;
  }
}

}  // namespace

std::optional<ObjectMotion> read_motion(const tinyxml2::XMLElement& e, const DiagnosticSink& sink, double unit_to_m,
                                        const Pose& X_WO, bool pose_given) {
  AttributeParser a(e, sink, {"repeat", "velocity", "angular_velocity_deg_s"});
  const bool twist = a.has("velocity") || a.has("angular_velocity_deg_s");
  const bool keyed = e.FirstChildElement() != nullptr || a.has("repeat");
  std::optional<ObjectMotion> motion;
  if (twist && keyed) {
    sink.error(e.GetLineNum(), "<motion> is keyframed (<key>, repeat) or a twist (velocity, angular_velocity_deg_s), "
                               "not both");
    return std::nullopt;
  }
  if (twist) {
    const auto v = a.vector3("velocity", Presence::Optional, Bound::Any);
    const auto w = a.vector3("angular_velocity_deg_s", Presence::Optional, Bound::Any);
    if ((a.has("velocity") && !v) || (a.has("angular_velocity_deg_s") && !w)) return std::nullopt;
    motion = ObjectMotion::twist(X_WO, v.value_or(Eigen::Vector3d::Zero()) * unit_to_m,
                                 w.value_or(Eigen::Vector3d::Zero()) * kDeg);
  } else {
    if (e.FirstChildElement() == nullptr) {
      sink.error(e.GetLineNum(), "<motion> needs <key> children or a velocity / angular_velocity_deg_s");
      return std::nullopt;
    }
    if (pose_given) {
      sink.error(e.GetLineNum(), "an object with keyframed <motion> takes its pose from its keys: remove its <pose>");
      return std::nullopt;
    }
    motion = read_keyframes(e, a, sink, unit_to_m);
  }
  if (motion && !within_limits(*motion, e.GetLineNum(), sink)) return std::nullopt;
  return motion;
}

}  // namespace mhd::scene_xml
