#include "calibration/rig_xml_writer.h"
#include "calibration/text_concat.h"

#include "scene_xml/scene_reader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>
#include <system_error>

namespace mhd {

namespace {

using calibration_detail::concat;
using calibration_detail::kDegPerRad;

namespace fs = std::filesystem;

constexpr double kReadBackTolerance_m = 1e-6;
constexpr double kReadBackTolerance_rad = 1e-6;

/// Fixed-point with trailing zeros removed ("203.05", "90", "-0.5").
std::string fixed(double value, int decimals) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*f", decimals, value);
  std::string s(buffer.data());
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string triple(const Eigen::Vector3d& v, int decimals) {
  return concat(fixed(v.x(), decimals), " ", fixed(v.y(), decimals), " ", fixed(v.z(), decimals));
}

/// XML comments may not hold "--".
std::string comment_safe(std::string text) {
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--")) text.replace(at, 2, "- -");
  return text;
}

const FrameDescription* find_frame(const SceneDescription& scene, std::string_view name) {
  for (const FrameDescription& f : scene.rig_frames) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

/// One element's text in the file, edited in place so the file keeps its layout.
class ElementText {
 public:
  ElementText(std::string text) : text_(std::move(text)) {}
  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] bool has(std::string_view attribute) const { return find(attribute).has_value(); }

  void set(std::string_view attribute, const std::string& value) {
    if (const auto at = find(attribute)) {
      text_.replace(at->value_begin, at->value_end - at->value_begin, value);
      return;
    }
    std::size_t close = text_.rfind("/>");
    if (close == std::string::npos) close = text_.rfind('>');
    text_.insert(close, concat(" ", attribute, "=\"", value, "\""));
  }

  void erase(std::string_view attribute) {
    if (const auto at = find(attribute)) text_.erase(at->begin, at->value_end + 1 - at->begin);
  }

 private:
  struct Span {
    std::size_t begin;        ///< the whitespace before the name
    std::size_t value_begin;  ///< after the opening quote
    std::size_t value_end;    ///< at the closing quote
  };
  [[nodiscard]] std::optional<Span> find(std::string_view attribute) const {
    for (std::size_t at = text_.find(attribute); at != std::string::npos; at = text_.find(attribute, at + 1)) {
      if (at == 0 || std::isspace(static_cast<unsigned char>(text_[at - 1])) == 0) continue;
      std::size_t i = at + attribute.size();
      while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i])) != 0) ++i;
      if (i >= text_.size() || text_[i] != '=') continue;
      ++i;
      while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i])) != 0) ++i;
      if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) continue;
      const std::size_t close = text_.find(text_[i], i + 1);
      if (close == std::string::npos) return std::nullopt;
      std::size_t begin = at;
      while (begin > 0 && std::isspace(static_cast<unsigned char>(text_[begin - 1])) != 0) --begin;
      return Span{begin, i + 1, close};
    }
    return std::nullopt;
  }
  std::string text_;
};

/// Where the <frame> element defined at `line` (1-based) starts and ends in `file_text`.
std::optional<std::pair<std::size_t, std::size_t>> locate_frame(const std::string& file_text, int line,
                                                                std::string_view name) {
  std::size_t line_start = 0;
  for (int l = 1; l < line; ++l) {
    line_start = file_text.find('\n', line_start);
    if (line_start == std::string::npos) return std::nullopt;
    ++line_start;
  }
  const std::size_t begin = file_text.find("<frame", line_start);
  if (begin == std::string::npos) return std::nullopt;
  const std::size_t end = file_text.find('>', begin);
  if (end == std::string::npos) return std::nullopt;
  const std::string_view element(file_text.data() + begin, end + 1 - begin);
  if (element.find(concat("\"", name, "\"")) == std::string_view::npos &&
      element.find(concat("'", name, "'")) == std::string_view::npos) {
    return std::nullopt;
  }
  return std::make_pair(begin, end + 1);
}

/// Sets the frame's rotation in the form it already uses (rpy_deg unless it has a
/// quaternion, or the rpy would be gimbal-locked).
void set_rotation(ElementText& frame, const Eigen::Matrix3d& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const bool gimbal_locked = std::abs(std::cos(pitch)) < 1e-6;
  if (frame.has("quaternion_wxyz") || gimbal_locked) {
    Eigen::Quaterniond q(R);
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    frame.erase("rpy_deg");
    frame.set("quaternion_wxyz",
              concat(fixed(q.w(), 10), " ", fixed(q.x(), 10), " ", fixed(q.y(), 10), " ", fixed(q.z(), 10)));
    return;
  }
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  frame.set("rpy_deg", triple(Eigen::Vector3d(roll, pitch, yaw) * kDegPerRad, 6));
}

bool close(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm() <= kReadBackTolerance_m &&
         Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() <= kReadBackTolerance_rad;
}

}  // namespace

Pose calibrated_X_robot_base(const Rig& rig, const RigOffsets& offsets) noexcept {
  const Pose X_W_robot = rig.X_W_is900() * rig.X_is900_base_sensor_nominal() * calibrated_X_base_sensor_robot(rig, offsets);
  Pose X_W_base = X_W_robot * rig.X_robot_base();
  X_W_base.translation().y() = 0.0;  // back on the floor, same rotation and ground point
  return X_W_robot.inverse(Eigen::Isometry) * X_W_base;
}

Result<WrittenRig, std::string> write_calibrated_rig(const SceneDescription& scene, const Rig& rig, const RigOffsets& offsets,
                                    const fs::path& output, const std::vector<std::string>& note_lines) {
  const FrameDescription* robot = find_frame(scene, rig_frame::kRobot);
  const FrameDescription* phantom = find_frame(scene, rig_frame::kPhantom);
  const FrameDescription* base = find_frame(scene, rig_frame::kBase);
  if (robot == nullptr || phantom == nullptr || base == nullptr) {
    return std::string(concat(scene.file.string(), ": the scene has no complete rig (robot, phantom and base frames)"));
  }
  const std::string& file = robot->where.file;
  if (phantom->where.file != file || base->where.file != file) {
    return std::string(concat(file, ": the rig frames robot, phantom and base must be defined in one file to be rewritten "
                                "(phantom is in ",
                          phantom->where.file, ", base in ", base->where.file, ")"));
  }

  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) return std::string(concat(file, ": cannot read the rig file again"));
  std::string file_text = bytes.str();

  tinyxml2::XMLDocument document;
  if (document.Parse(file_text.data(), file_text.size()) != tinyxml2::XML_SUCCESS || document.RootElement() == nullptr) {
    return std::string(concat(file, ": cannot read the rig file again: ", document.ErrorStr()));
  }
  const char* unit = document.RootElement()->Attribute("unit");
  const double unit_to_m = (unit != nullptr && std::string_view(unit) == "mm") ? 1e-3 : 1.0;
  const int decimals = unit_to_m < 1.0 ? 4 : 7;  // 0.1 micrometre either way

  const Pose X_S_robot = calibrated_X_base_sensor_robot(rig, offsets);
  const Pose X_R_phantom = calibrated_X_robot_phantom(rig, offsets);
  const Pose X_R_base = calibrated_X_robot_base(rig, offsets);

  struct Edit {
    const FrameDescription* frame;
    std::size_t begin = 0, end = 0;
  };
  std::array<Edit, 3> edits = {{{robot}, {phantom}, {base}}};
  for (Edit& e : edits) {
    const auto span = locate_frame(file_text, e.frame->where.line, e.frame->name);
    if (!span) {
      return std::string(concat(file, ":", std::to_string(e.frame->where.line), ": rig frame '", e.frame->name,
                            "' is not where the scene reader found it"));
    }
    e.begin = span->first;
    e.end = span->second;
  }
  // From the end of the file backwards, so earlier offsets stay valid.
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  for (const Edit& e : edits) {
    ElementText element(file_text.substr(e.begin, e.end - e.begin));
    std::string prefix;
    if (e.frame == robot) {
      element.set("position", triple(X_S_robot.translation() / unit_to_m, decimals));
      set_rotation(element, X_S_robot.linear());
      // The note goes above the robot frame, indented like it.
      const std::size_t newline = file_text.rfind('\n', e.begin);
      const std::size_t line_start = newline == std::string::npos ? 0 : newline + 1;
      const std::string indent = file_text.substr(line_start, e.begin - line_start);
      const bool blank_before = indent.find_first_not_of(" \t") == std::string::npos;
      std::string text = "<!-- Calibrated by mhd calibrate (docs/calibration.md):";
      for (const std::string& line : note_lines) text += concat("\n", blank_before ? indent : "", "     ", comment_safe(line));
      text += " -->";
      prefix = blank_before ? concat(text, "\n", indent) : concat(text, " ");
    } else if (e.frame == phantom) {
      element.set("position", triple(X_R_phantom.translation() / unit_to_m, decimals));
    } else {
      element.set("position", triple(X_R_base.translation() / unit_to_m, decimals));
    }
    file_text.replace(e.begin, e.end - e.begin, prefix + element.text());
  }

  const fs::path temporary = fs::path(output.string() + ".tmp");
  std::error_code ec;
  const auto discard = [&] { fs::remove(temporary, ec); };
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << file_text;
    out.close();
    if (!out) {
      discard();
      return std::string(concat(output.string(), ": cannot write"));
    }
  }

  // Read it back as any user of the rig will.
  const Result<SceneDescription> read = read_scene_file(temporary);
  if (!read.ok()) {
    discard();
    std::string message = concat(output.string(), ": the written rig does not read back:");
    for (const Diagnostic& d : read.diagnostics()) message += concat("\n  ", d.to_string());
    return std::string(message);
  }
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(*read, rig.device());
  if (!built.ok()) {
    discard();
    std::string message = concat(output.string(), ": the written rig is not a valid rig:");
    for (const RigError& e : built.error()) message += concat("\n  ", e.to_string());
    return std::string(message);
  }
  if (!close(built->X_base_sensor_robot(), X_S_robot) || !close(built->X_robot_phantom(), X_R_phantom) ||
      !close(built->X_robot_base(), X_R_base)) {
    discard();
    return std::string(concat(output.string(), ": the written rig reads back with other offsets than calibrated"));
  }
  fs::rename(temporary, output, ec);
  if (ec) {
    discard();
    return std::string(concat(output.string(), ": cannot write: ", ec.message()));
  }
  return WrittenRig{file};
}

}  // namespace mhd
