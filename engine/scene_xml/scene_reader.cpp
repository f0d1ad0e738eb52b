#include "scene_xml/sharing_reader.h"
#include "scene_xml/scene_reader.h"

#include "geometry/pose.h"
#include "scene/plausible_bounds.h"
#include "scene/rig_kind_check.h"
#include "scene_xml/diagnostic_sink.h"
#include "scene_xml/frame_graph.h"
#include "scene_xml/message_text.h"
#include "scene_xml/number_parser.h"
#include "scene_xml/dynamics_reader.h"
#include "scene_xml/motion_reader.h"
#include "scene_xml/pose_reader.h"
#include "scene_xml/readable_file.h"
#include "scene_xml/texture_reader.h"
#include "scene_xml/xml_attribute_parser.h"
#include "scene_xml/xml_parse_error.h"

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;
using scene_xml::AttributeParser;
using scene_xml::Bound;
using scene_xml::concat;
using scene_xml::DiagnosticSink;
using scene_xml::Emptiness;
using scene_xml::Presence;
using scene_xml::read_dynamics;
using scene_xml::read_motion;
using scene_xml::read_pose_attributes;

constexpr std::string_view kVersion = "1";
constexpr double kMinScaleToM = 1e-6;
/// Highest max_triangles accepted: 1e9 triangles need about 100 GB with their BVH.
constexpr int kMaxMaxTriangles = 1'000'000'000;
/// Includes below the root file, at most (docs/scene-format.md).
constexpr std::size_t kMaxIncludeDepth = 64;
constexpr double kMaxScaleToM = 1e6;
constexpr std::array<std::string_view, 6> kShapes = {"mesh", "plane", "sphere", "box", "cylinder", "capsule"};

bool is_shape(std::string_view name) {
  for (const std::string_view s : kShapes) {
    if (s == name) return true;
  }
  return false;
}

std::string tag(const tinyxml2::XMLElement& e) { return concat("<", e.Name(), ">"); }

std::string where_text(const SourceLocation& where) {
  return where.line > 0 ? concat(where.file, ":", where.line) : where.file;
}

/// A path's identity for include-cycle checks: absolute, with links resolved as far
/// as they exist.
fs::path identity_of(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  fs::path canonical = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : canonical;
}

/// A path named in a file, resolved against that file's folder (the display path
/// of the file, so relative display paths stay relative to the working directory).
fs::path resolve_against(const std::string& including_file, const std::string& named) {
  const fs::path p(named);
  if (p.is_absolute()) return p.lexically_normal();
  return (fs::path(including_file).parent_path() / p).lexically_normal();
}

/// Per-file reading state: where messages go and the file's length unit.
struct FileContext {
  DiagnosticSink sink;
  double unit_to_m = 1.0;
};

/// XML forbids "--" inside a comment (and a comment ending in "-"); tinyxml2 reads such a
/// comment anyway, so a file that other XML tools (and the schema check) refuse would pass.
void check_comment(const tinyxml2::XMLNode& n, const DiagnosticSink& sink) {
  const tinyxml2::XMLComment* c = n.ToComment();
  if (c == nullptr || c->Value() == nullptr) return;
  const std::string_view text = c->Value();
  const std::size_t at = text.find("--");
  if (at == std::string_view::npos && (text.empty() || text.back() != '-')) return;
  const std::size_t where = at == std::string_view::npos ? text.size() - 1 : at;
  const auto newlines = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(where), '\n');
  sink.error(c->GetLineNum() + static_cast<int>(newlines),
             "malformed XML: '--' inside a comment (XML forbids it; write '-' or reword)");
}

/// Calls `visit` for each child element; reports non-blank text inside `parent`.
void for_each_child(const tinyxml2::XMLElement& parent, const DiagnosticSink& sink,
                    const std::function<void(const tinyxml2::XMLElement&)>& visit) {
  for (const tinyxml2::XMLNode* n = parent.FirstChild(); n != nullptr; n = n->NextSibling()) {
    if (const tinyxml2::XMLElement* e = n->ToElement()) {
      visit(*e);
    } else if (const tinyxml2::XMLText* t = n->ToText()) {
      if (!scene_xml::trim_xml_space(t->Value()).empty()) {
        sink.error(t->GetLineNum(), concat("unexpected text in ", tag(parent)));
      }
    }
    check_comment(*n, sink);
    // Comments, declarations and other markup carry nothing and are skipped.
  }
}

/// "attribute 'x' on <tag> must not exceed max (why), got v" when value > max.
void report_above(const AttributeParser& a, const FileContext& ctx, std::string_view name, double value, double max,
                  std::string_view why) {
  if (value <= max) return;
  ctx.sink.error(a.line_of(name), concat("attribute '", name, "' on ", a.tag(), " must not exceed ",
                                         scene_xml::format_g(max), " (", why, "), got ", scene_xml::format_g(value)));
}

void report_unknown_element(const tinyxml2::XMLElement& e, const tinyxml2::XMLElement& parent,
                            const DiagnosticSink& sink) {
  sink.error(e.GetLineNum(), concat("unknown element ", tag(e), " in ", tag(parent)));
}

/// For elements that take attributes only.
void expect_no_children(const tinyxml2::XMLElement& e, const DiagnosticSink& sink) {
  for_each_child(e, sink, [&](const tinyxml2::XMLElement& child) {
    report_unknown_element(child, e, sink);
  });
}

/// XML 1.0 section 2.11: a lone CR ends a line, like LF and CR LF. tinyxml2 turns it into LF
/// in text but counts only LF in line numbers, so a file with CR line ends (classic Mac)
/// would report every problem on line 1. Normalising lone CRs first keeps the lines right;
/// `storage` holds the copy when one is needed.
std::string_view normalize_lone_cr(std::string_view xml, std::string& storage) {
  const auto lone_cr = [](std::string_view text, std::size_t i) {
    return text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n');
  };
  std::size_t i = 0;
  while (i < xml.size() && !lone_cr(xml, i)) ++i;
  if (i == xml.size()) return xml;
  storage.assign(xml);
  for (; i < storage.size(); ++i) {
    if (lone_cr(storage, i)) storage[i] = '\n';
  }
  return storage;
}

class SceneReader {
 public:
  SceneReader() = default;

  void read_root(std::string_view xml, const fs::path& file) {
    const std::string display = file.string();
    scene_.file = file;
    scene_.name = file.stem().string();
    read_document(xml, display, identity_of(file), /*is_root=*/true);
  }

  void read_root_file(const fs::path& file) {
    scene_xml::FileProblem problem{};
    const std::optional<std::string> bytes = scene_xml::read_whole_file(file, problem);
    if (!bytes) {
      DiagnosticSink(file.string(), diagnostics_)
          .error(0, concat("scene file ", scene_xml::describe(problem)));
      return;
    }
    read_root(*bytes, file);
  }

  Result<SceneDescription> finish() {
    resolve_material_references();
    check_stiffness_against_rate();
    scene_xml::check_frame_graph(scene_.rig_frames, diagnostics_);
    const Diagnostics rig = check_rig_kind(scene_);
    diagnostics_.insert(diagnostics_.end(), rig.begin(), rig.end());
    const Diagnostics sharing = scene_xml::check_sharing(scene_);
    diagnostics_.insert(diagnostics_.end(), sharing.begin(), sharing.end());
    if (!diagnostics_.empty()) return std::move(diagnostics_);
    return std::move(scene_);
  }

 private:
  struct OpenFile {
    fs::path identity;
    std::string display;
  };
  struct MaterialReference {
    std::size_t object_index;
    std::string name;
    SourceLocation where;
  };

  void read_document(std::string_view xml, const std::string& display, fs::path identity,
                     bool is_root) {
    FileContext ctx{DiagnosticSink(display, diagnostics_), 1.0};
    std::string normalized;
    xml = normalize_lone_cr(xml, normalized);
    tinyxml2::XMLDocument document;
    if (document.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
      ctx.sink.error(document.ErrorLineNum(), scene_xml::describe_xml_error(document));
      return;
    }
    const tinyxml2::XMLElement* root = nullptr;
    for (const tinyxml2::XMLNode* n = document.FirstChild(); n != nullptr; n = n->NextSibling()) {
      if (const tinyxml2::XMLElement* e = n->ToElement()) {
        if (root == nullptr) {
          root = e;
        } else {
          ctx.sink.error(e->GetLineNum(),
                         concat("unexpected element ", tag(*e), " after the root element"));
        }
      } else if (const tinyxml2::XMLText* t = n->ToText()) {
        if (!scene_xml::trim_xml_space(t->Value()).empty()) {
          ctx.sink.error(t->GetLineNum(), "unexpected text outside the root element");
        }
      }
      check_comment(*n, ctx.sink);
    }
    if (root == nullptr) {
      ctx.sink.error(0, "malformed XML: no root element");
      return;
    }
    if (std::string_view(root->Name()) != "scene") {
      ctx.sink.error(root->GetLineNum(), concat("root element must be <scene>, found ", tag(*root)));
      return;
    }
    read_files_.insert(identity);
    open_files_.push_back({std::move(identity), display});
    read_scene_element(*root, ctx, is_root);
    open_files_.pop_back();
  }

  void read_scene_element(const tinyxml2::XMLElement& root, FileContext& ctx, bool is_root) {
    AttributeParser a(root, ctx.sink,
                      {"version", "name", "unit", "max_triangles", "xmlns:xsi", "xsi:noNamespaceSchemaLocation"});
    if (const auto version = a.token("version", Presence::Required); version && *version != kVersion) {
      ctx.sink.error(a.line_of("version"),
                     concat("unsupported scene version '", *version, "' (this reader reads version ",
                            kVersion, ")"));
      return;  // another version's content would only produce noise
    }
    if (const auto name = a.text("name", Presence::Optional, Emptiness::Forbidden); name && is_root) {
      scene_.name = *name;
    }
    if (const auto max_triangles = a.integer("max_triangles", Presence::Optional, 1, kMaxMaxTriangles);
        max_triangles && is_root) {
      scene_.max_triangles = static_cast<std::uint64_t>(*max_triangles);
    }
    if (const auto unit = a.token("unit", Presence::Optional)) {
      if (*unit == "m") {
        ctx.unit_to_m = 1.0;
      } else if (*unit == "mm") {
        ctx.unit_to_m = 0.001;
      } else {
        ctx.sink.error(a.line_of("unit"),
                       concat("invalid unit '", *unit, "' on <scene> (expected m or mm)"));
      }
    }
    for_each_child(root, ctx.sink, [&](const tinyxml2::XMLElement& e) {
      const std::string_view name = e.Name();
      if (name == "include") {
        read_include(e, ctx);
      } else if (name == "haptics") {
        read_haptics(e, ctx);
      } else if (name == "material") {
        read_named_material(e, ctx);
      } else if (name == "object") {
        read_object(e, ctx);
      } else if (name == "rig") {
        read_rig(e, ctx);
      } else if (name == "plugins") {
        read_plugins(e, ctx);
      } else if (name == "simulated_user") {
        read_param_block(e, ctx, scene_.simulated_user, /*has_kind=*/false);
      } else if (name == "planner") {
        read_param_block(e, ctx, scene_.planner, /*has_kind=*/true);
      } else if (name == "server") {
        read_param_block(e, ctx, scene_.server, /*has_kind=*/false);
      } else if (name == "sharing") {
        read_sharing_once(e, ctx);
      } else {
        report_unknown_element(e, root, ctx.sink);
      }
    });
  }

  /// "a.xml -> b.xml -> <next>": the open files from `first` on, then `next`.
  std::string include_chain(std::size_t first, const std::string& next) const {
    std::string chain;
    for (std::size_t j = first; j < open_files_.size(); ++j) chain += open_files_[j].display + " -> ";
    return chain + next;
  }

  void read_include(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"file"});
    expect_no_children(e, ctx.sink);
    const auto named = a.text("file", Presence::Required, Emptiness::Forbidden);
    if (!named) return;
    const int line = a.line_of("file");
    const fs::path path = resolve_against(ctx.sink.file(), *named);
    const std::string display = path.string();
    fs::path identity = identity_of(path);
    for (std::size_t i = 0; i < open_files_.size(); ++i) {
      if (open_files_[i].identity != identity) continue;
      ctx.sink.error(line, concat("include cycle: ", include_chain(i, display)));
      return;
    }
    // A file is read once per scene: a second include of it (two parts sharing the
    // materials, or a diamond of includes) adds nothing, so the cost stays linear.
    if (read_files_.count(identity) != 0) return;
    // Each level costs stack (a parsed document per file): refuse before recursing.
    if (open_files_.size() > kMaxIncludeDepth) {
      ctx.sink.error(line, concat("includes nested deeper than ", kMaxIncludeDepth, ": ", include_chain(0, display)));
      return;
    }
    scene_xml::FileProblem problem{};
    const std::optional<std::string> bytes = scene_xml::read_whole_file(path, problem);
    if (!bytes) {
      ctx.sink.error(line, concat("included file '", *named, "' ", scene_xml::describe(problem),
                                  " (resolved to '", display, "')"));
      return;
    }
    read_document(*bytes, display, std::move(identity), /*is_root=*/false);
  }

  void read_haptics(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"max_force_N", "update_rate_Hz"});
    expect_no_children(e, ctx.sink);
    if (haptics_where_) {
      ctx.sink.error(e.GetLineNum(),
                     concat("duplicate <haptics> (first defined at ", where_text(*haptics_where_), ")"));
      return;
    }
    haptics_where_ = ctx.sink.at(e.GetLineNum());
    HapticsSettings& h = scene_.haptics;
    h.max_force_N = a.number("max_force_N", Presence::Optional, Bound::Positive);
    h.update_rate_Hz =
        a.number("update_rate_Hz", Presence::Optional, Bound::Positive).value_or(h.update_rate_Hz);
    if (h.update_rate_Hz < kMinHapticRate_Hz || h.update_rate_Hz > kMaxHapticRate_Hz) {
      ctx.sink.error(a.line_of("update_rate_Hz"),
                     concat("attribute 'update_rate_Hz' on <haptics> must be within [",
                            scene_xml::format_g(kMinHapticRate_Hz), ", ", scene_xml::format_g(kMaxHapticRate_Hz),
                            "] Hz, got ", scene_xml::format_g(h.update_rate_Hz)));
    }
    // No ceiling here: the device reports its own force limit, and max_force_N can only
    // lower it (the haptic server warns at open when it asks for more).
  }

  /// The material attributes shared by named and inline materials.
  HapticMaterial read_material_properties(AttributeParser& a, const FileContext& ctx) {
    HapticMaterial m;
    m.stiffness_N_per_m =
        a.number("stiffness_N_per_m", Presence::Required, Bound::Positive).value_or(m.stiffness_N_per_m);
    m.damping_Ns_per_m =
        a.number("damping_Ns_per_m", Presence::Optional, Bound::NonNegative).value_or(m.damping_Ns_per_m);
    const auto static_mu = a.number("static_friction", Presence::Optional, Bound::NonNegative);
    const auto dynamic_mu = a.number("dynamic_friction", Presence::Optional, Bound::NonNegative);
    m.static_friction = static_mu.value_or(m.static_friction);
    m.dynamic_friction = dynamic_mu.value_or(m.dynamic_friction);
    const bool both_valid = (static_mu || !a.has("static_friction")) &&
                            (dynamic_mu || !a.has("dynamic_friction"));
    if (both_valid && m.dynamic_friction > m.static_friction) {
      ctx.sink.error(a.line_of("dynamic_friction"),
                     concat("dynamic_friction (", scene_xml::format_g(m.dynamic_friction),
                            ") must not exceed static_friction (",
                            scene_xml::format_g(m.static_friction), ") on <material>"));
    }
    m.force_shading = a.boolean("force_shading", Presence::Optional).value_or(m.force_shading);
    const auto crease_deg = a.number("shading_crease_deg", Presence::Optional, Bound::NonNegative);
    if (crease_deg) {
      report_above(a, ctx, "shading_crease_deg", *crease_deg, kMaxCreaseAngle_deg, "the widest angle two normals make");
      m.force_shading_crease_rad = std::min(*crease_deg, kMaxCreaseAngle_deg) * std::numbers::pi / 180.0;
    }
    report_above(a, ctx, "damping_Ns_per_m", m.damping_Ns_per_m, kMaxDamping_Ns_per_m, "MHD's bound");
    report_above(a, ctx, "static_friction", m.static_friction, kMaxFriction, "MHD's bound");
    report_above(a, ctx, "dynamic_friction", m.dynamic_friction, kMaxFriction, "MHD's bound");
    if (a.has("stiffness_N_per_m")) {
      stiffness_uses_.push_back({m.stiffness_N_per_m, ctx.sink.at(a.line_of("stiffness_N_per_m"))});
    }
    return m;
  }

  /// A material's children: at most one <texture>.
  static void read_material_children(const tinyxml2::XMLElement& e, const FileContext& ctx, HapticMaterial& m) {
    const tinyxml2::XMLElement* texture = nullptr;
    for_each_child(e, ctx.sink, [&](const tinyxml2::XMLElement& child) {
      if (std::string_view(child.Name()) != "texture") {
        report_unknown_element(child, e, ctx.sink);
      } else if (texture != nullptr) {
        ctx.sink.error(child.GetLineNum(),
                       concat("<material> has more than one <texture> (the first is at line ", texture->GetLineNum(), ")"));
      } else {
        texture = &child;
        m.texture_spec = scene_xml::read_texture(child, ctx.sink);
      }
    });
  }

  void read_named_material(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink,
                      {"name", "stiffness_N_per_m", "damping_Ns_per_m", "static_friction",
                       "dynamic_friction", "force_shading", "shading_crease_deg"});
    const auto name = a.text("name", Presence::Required, Emptiness::Forbidden);
    HapticMaterial m = read_material_properties(a, ctx);
    read_material_children(e, ctx, m);
    if (!name) return;
    if (!claim_name(material_where_, "material", *name, ctx.sink.at(e.GetLineNum()), ctx)) return;
    scene_.materials.emplace(*name, m);
  }

  /// Records `name` as defined at `where`; reports and returns false when it already was.
  static bool claim_name(std::map<std::string, SourceLocation, std::less<>>& defined,
                         std::string_view what, const std::string& name,
                         const SourceLocation& where, const FileContext& ctx) {
    const auto [it, inserted] = defined.emplace(name, where);
    if (!inserted) {
      ctx.sink.error(where.line, concat("duplicate ", what, " name '", name, "' (first defined at ",
                                        where_text(it->second), ")"));
    }
    return inserted;
  }

  void read_object(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"name", "material", "touchable"});
    const auto name = a.text("name", Presence::Required, Emptiness::Forbidden);
    const auto material_ref = a.text("material", Presence::Optional, Emptiness::Forbidden);
    const std::string label = name ? concat("object '", *name, "'") : std::string("<object>");

    ObjectDescription object;
    object.name = name.value_or("");
    if (const auto touchable = a.text("touchable", Presence::Optional, Emptiness::Forbidden)) {
      if (const auto faces = parse_touchable_faces(*touchable)) {
        object.touchable = *faces;
      } else {
        ctx.sink.error(a.line_of("touchable"), concat("attribute 'touchable' on ", label,
                                                      " must be front, back or both (is '", *touchable, "')"));
      }
    }
    object.where = ctx.sink.at(e.GetLineNum());
    const tinyxml2::XMLElement* shape = nullptr;
    const tinyxml2::XMLElement* pose = nullptr;
    const tinyxml2::XMLElement* scale = nullptr;
    const tinyxml2::XMLElement* inline_material = nullptr;
    const tinyxml2::XMLElement* motion = nullptr;
    const tinyxml2::XMLElement* dynamics = nullptr;
    Eigen::Vector3d scale_factors = Eigen::Vector3d::Ones();

    // Only the first of each child counts; a repeat is reported against it.
    const auto first_of = [&](const tinyxml2::XMLElement*& slot, const tinyxml2::XMLElement& child) {
      if (slot == nullptr) {
        slot = &child;
        return true;
      }
      ctx.sink.error(child.GetLineNum(), concat(label, " has more than one ", tag(child),
                                                " (the first is at line ", slot->GetLineNum(), ")"));
      return false;
    };

    for_each_child(e, ctx.sink, [&](const tinyxml2::XMLElement& child) {
      const std::string_view child_name = child.Name();
      if (is_shape(child_name)) {
        if (shape != nullptr) {
          ctx.sink.error(child.GetLineNum(),
                         concat(label, " has more than one shape: ", tag(child), " after ",
                                tag(*shape), " at line ", shape->GetLineNum()));
          return;
        }
        shape = &child;
        object.shape = read_shape(child, ctx);
      } else if (child_name == "pose") {
        if (!first_of(pose, child)) return;
        AttributeParser pa(child, ctx.sink, {"position", "rpy_deg", "quaternion_wxyz"});
        expect_no_children(child, ctx.sink);
        object.X_WO = read_pose_attributes(pa, ctx.sink, ctx.unit_to_m);
      } else if (child_name == "motion") {
        (void)first_of(motion, child);  // read below, once the <pose> is known
      } else if (child_name == "dynamics") {
        if (!first_of(dynamics, child)) return;
        object.dynamics = read_dynamics(child, ctx.sink);
      } else if (child_name == "scale") {
        if (!first_of(scale, child)) return;
        scale_factors = read_scale(child, ctx);
      } else if (child_name == "material") {
        if (!first_of(inline_material, child)) return;
        AttributeParser ma(child, ctx.sink,
                           {"name", "stiffness_N_per_m", "damping_Ns_per_m", "static_friction",
                            "dynamic_friction", "force_shading", "shading_crease_deg"});
        if (ma.has("name")) {
          ctx.sink.error(ma.line_of("name"),
                         "an inline <material> takes no name (define named materials in <scene>)");
        }
        object.material = read_material_properties(ma, ctx);
        read_material_children(child, ctx, object.material);
      } else {
        report_unknown_element(child, e, ctx.sink);
      }
    });

    if (shape == nullptr) {
      ctx.sink.error(e.GetLineNum(),
                     concat(label, " has no shape (expected <mesh>, <plane>, <sphere>, <box>, "
                                   "<cylinder> or <capsule>)"));
    }
    const bool exact_primitive = std::visit(
        [](const auto& source) {
          if constexpr (requires { source.exact; }) {
            return source.exact;
          } else {
            return false;
          }
        },
        object.shape);
    if (object.touchable != TouchableFaces::Both && shape != nullptr && exact_primitive) {
      ctx.sink.error(a.line_of("touchable"),
                     concat(label, " is an exact ", tag(*shape), ", a solid touched from outside; touchable=\"",
                            touchable_faces_name(object.touchable), "\" applies to triangles (set exact=\"false\")"));
    }
    if (motion != nullptr) {
      object.motion = read_motion(*motion, ctx.sink, ctx.unit_to_m, object.X_WO, pose != nullptr);
      if (object.motion) object.X_WO = object.motion->X_WO_at(0.0);
    }
    if (motion != nullptr && dynamics != nullptr) {
      ctx.sink.error(dynamics->GetLineNum(), concat(label, " has both <motion> (line ", motion->GetLineNum(),
                                                     ") and <dynamics>: it is scripted or pushed, not both"));
      object.dynamics.reset();
    }
    if (scale != nullptr) {
      if (shape != nullptr && !std::holds_alternative<MeshSource>(object.shape)) {
        ctx.sink.error(scale->GetLineNum(), concat("<scale> applies to mesh objects only; ", label,
                                                   " is a ", tag(*shape)));
      } else if (auto* mesh = std::get_if<MeshSource>(&object.shape); mesh != nullptr) {
        mesh->scale_to_m = scale_factors * ctx.unit_to_m;
        if (mesh->scale_to_m.minCoeff() < kMinScaleToM || mesh->scale_to_m.maxCoeff() > kMaxScaleToM) {
          ctx.sink.error(scale->GetLineNum(),
                         concat("absurd scale: unit times scale is (",
                                scene_xml::format_g(mesh->scale_to_m.x()), " ",
                                scene_xml::format_g(mesh->scale_to_m.y()), " ",
                                scene_xml::format_g(mesh->scale_to_m.z()),
                                ") metres per mesh unit, outside [1e-06, 1e+06]"));
        }
      }
    }
    if (material_ref && inline_material != nullptr) {
      ctx.sink.error(inline_material->GetLineNum(),
                     concat(label, " has both material=\"", *material_ref,
                            "\" and an inline <material>"));
    } else if (!material_ref && inline_material == nullptr && !a.has("material")) {
      ctx.sink.error(e.GetLineNum(), concat(label, " has no material (set material=\"NAME\" or add "
                                                   "an inline <material>)"));
    }
    if (name) claim_name(object_where_, "object", *name, object.where, ctx);
    if (material_ref) {
      object.material_name = *material_ref;
      material_references_.push_back(
          {scene_.objects.size(), *material_ref, ctx.sink.at(a.line_of("material"))});
    }
    scene_.objects.push_back(std::move(object));
  }

  /// <scale value="s"/> or <scale xyz="sx sy sz"/>; ones when invalid (already reported).
  static Eigen::Vector3d read_scale(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"value", "xyz"});
    expect_no_children(e, ctx.sink);
    if (a.has("value") == a.has("xyz")) {
      ctx.sink.error(e.GetLineNum(), "<scale> needs exactly one of 'value' or 'xyz'");
      return Eigen::Vector3d::Ones();
    }
    if (a.has("value")) {
      return Eigen::Vector3d::Constant(
          a.number("value", Presence::Required, Bound::Positive).value_or(1.0));
    }
    return a.vector3("xyz", Presence::Required, Bound::Positive).value_or(Eigen::Vector3d::Ones());
  }

  static ShapeSource read_shape(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    expect_no_children(e, ctx.sink);
    const std::string_view name = e.Name();
    const double u = ctx.unit_to_m;
    if (name == "mesh") {
      AttributeParser a(e, ctx.sink, {"file"});
      MeshSource mesh;
      mesh.scale_to_m = Eigen::Vector3d::Constant(u);
      if (const auto file = a.text("file", Presence::Required, Emptiness::Forbidden)) {
        std::error_code ec;
        const fs::path resolved = resolve_against(ctx.sink.file(), *file);
        fs::path absolute = fs::absolute(resolved, ec);
        mesh.file = ec ? resolved : absolute.lexically_normal();
        const scene_xml::FileProblem problem = scene_xml::check_readable_file(mesh.file);
        if (problem != scene_xml::FileProblem::None) {
          ctx.sink.error(a.line_of("file"),
                         concat("mesh file '", *file, "' ", scene_xml::describe(problem),
                                " (resolved to '", mesh.file.string(), "')"));
        }
      }
      return mesh;
    }
    // A primitive's dimensions, in metres, within what a haptic scene can mean: the
    // proxy's 1 um skin below, 10 km above (1e300 would overflow the BVH's quantiser).
    const auto extent = [&](const AttributeParser& a, std::string_view attribute, double value_m) {
      constexpr double kMin_m = 1e-6, kMax_m = 1e4;
      if (value_m > 0.0 && !(value_m >= kMin_m && value_m <= kMax_m)) {
        ctx.sink.error(a.line_of(attribute), concat("attribute '", attribute, "' on <", name,
                                                    "> must be between 1e-6 m and 1e4 m (is ", scene_xml::format_g(value_m), " m)"));
      }
      return value_m;
    };
    if (name == "plane") {
      AttributeParser a(e, ctx.sink, {"size", "exact"});
      PlaneSource plane;
      plane.exact = a.boolean("exact", Presence::Optional).value_or(plane.exact);
      if (const auto size = a.numbers("size", Presence::Required, 2, Bound::Positive)) {
        plane.size_x_m = extent(a, "size", (*size)[0] * u);
        plane.size_y_m = extent(a, "size", (*size)[1] * u);
      }
      return plane;
    }
    if (name == "sphere") {
      AttributeParser a(e, ctx.sink, {"radius", "subdivisions", "exact"});
      SphereSource sphere;
      sphere.exact = a.boolean("exact", Presence::Optional).value_or(sphere.exact);
      sphere.radius_m = extent(a, "radius", a.number("radius", Presence::Required, Bound::Positive).value_or(0.0) * u);
      sphere.subdivisions =
          a.integer("subdivisions", Presence::Optional, 0, 7).value_or(sphere.subdivisions);
      return sphere;
    }
    if (name == "box") {
      AttributeParser a(e, ctx.sink, {"size", "exact"});
      BoxSource box;
      box.exact = a.boolean("exact", Presence::Optional).value_or(box.exact);
      box.size_m = a.vector3("size", Presence::Required, Bound::Positive)
                       .value_or(Eigen::Vector3d::Zero()) * u;
      for (int i = 0; i < 3; ++i) (void)extent(a, "size", box.size_m[i]);
      return box;
    }
    if (name == "capsule") {
      AttributeParser a(e, ctx.sink, {"radius", "length", "segments", "exact"});
      CapsuleSource capsule;
      capsule.radius_m = extent(a, "radius", a.number("radius", Presence::Required, Bound::Positive).value_or(0.0) * u);
      capsule.length_m = extent(a, "length", a.number("length", Presence::Required, Bound::Positive).value_or(0.0) * u);
      capsule.segments = a.integer("segments", Presence::Optional, 3, 4096).value_or(capsule.segments);
      capsule.exact = a.boolean("exact", Presence::Optional).value_or(capsule.exact);
      return capsule;
    }
    AttributeParser a(e, ctx.sink, {"radius", "height", "segments", "exact"});  // cylinder
    CylinderSource cylinder;
    cylinder.exact = a.boolean("exact", Presence::Optional).value_or(cylinder.exact);
    cylinder.radius_m = extent(a, "radius", a.number("radius", Presence::Required, Bound::Positive).value_or(0.0) * u);
    cylinder.height_m = extent(a, "height", a.number("height", Presence::Required, Bound::Positive).value_or(0.0) * u);
    cylinder.segments = a.integer("segments", Presence::Optional, 3, 4096).value_or(cylinder.segments);
    return cylinder;
  }

  void read_rig(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser rig_attributes(e, ctx.sink, {"kind"});
    read_rig_kind(rig_attributes, e, ctx);
    for_each_child(e, ctx.sink, [&](const tinyxml2::XMLElement& child) {
      if (std::string_view(child.Name()) == "lift") {
        read_lift(child, ctx);
        return;
      }
      if (std::string_view(child.Name()) != "frame") {
        report_unknown_element(child, e, ctx.sink);
        return;
      }
      AttributeParser a(child, ctx.sink, {"name", "parent", "position", "rpy_deg", "quaternion_wxyz"});
      expect_no_children(child, ctx.sink);
      FrameDescription frame;
      frame.where = ctx.sink.at(child.GetLineNum());
      const auto name = a.text("name", Presence::Required, Emptiness::Forbidden);
      const auto parent = a.text("parent", Presence::Required, Emptiness::Forbidden);
      frame.X_PF = read_pose_attributes(a, ctx.sink, ctx.unit_to_m);
      if (!name || !parent) return;
      if (*name == "world") {
        ctx.sink.error(a.line_of("name"), "frame name 'world' is reserved");
        return;
      }
      if (!claim_name(frame_where_, "frame", *name, frame.where, ctx)) return;
      frame.name = *name;
      frame.parent = *parent;
      scene_.rig_frames.push_back(std::move(frame));
    });
  }

  /// <sharing>: one per scene, across includes.
  void read_sharing_once(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    if (scene_.sharing) {
      ctx.sink.error(e.GetLineNum(), concat("a scene has one <sharing> (the first is at ",
                                            where_text(scene_.sharing->where), ")"));
      return;
    }
    scene_.sharing = scene_xml::read_sharing(e, ctx.sink);
  }

  /// <lift range="MIN MAX" max_speed="V" max_acceleration="A"/>, in the file's length unit
  /// (per s, per s^2): one per scene. Whether it fits the rig is Rig::from_scene's to judge.
  void read_lift(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"range", "max_speed", "max_acceleration"});
    expect_no_children(e, ctx.sink);
    const SourceLocation where = ctx.sink.at(e.GetLineNum());
    const auto range = a.numbers("range", Presence::Required, 2, Bound::Any);
    const auto speed = a.number("max_speed", Presence::Required, Bound::Positive);
    const auto acceleration = a.number("max_acceleration", Presence::Required, Bound::Positive);
    if (scene_.rig_lift) {
      ctx.sink.error(e.GetLineNum(), concat("a rig has one <lift> (the first is at ", scene_.rig_lift->where.file, ":",
                                            std::to_string(scene_.rig_lift->where.line), ")"));
      return;
    }
    if (!range || !speed || !acceleration) return;
    if (!((*range)[0] <= 0.0 && (*range)[1] >= 0.0 && (*range)[0] < (*range)[1])) {
      ctx.sink.error(a.line_of("range"),
                     "lift range must be 'MIN MAX' with MIN <= 0 <= MAX and MIN < MAX: height 0 is where the "
                     "'phantom' frame puts the arm");
      return;
    }
    scene_.rig_lift = LiftDescription{.min_m = (*range)[0] * ctx.unit_to_m,
                                      .max_m = (*range)[1] * ctx.unit_to_m,
                                      .max_speed_mps = *speed * ctx.unit_to_m,
                                      .max_acceleration_mps2 = *acceleration * ctx.unit_to_m,
                                      .where = where};
  }

  /// <rig kind="mobile|desktop">: every <rig> that names a kind (across includes) must agree.
  void read_rig_kind(AttributeParser& a, const tinyxml2::XMLElement& e, const FileContext& ctx) {
    const auto kind = a.token("kind", Presence::Optional);
    if (!kind) return;
    RigKind parsed = RigKind::Mobile;
    if (*kind == "desktop") {
      parsed = RigKind::Desktop;
    } else if (*kind != "mobile") {
      ctx.sink.error(a.line_of("kind"), concat("invalid rig kind '", *kind, "' (expected mobile or desktop)"));
      return;
    }
    RigKindDeclaration& declared = scene_.rig_kind;
    if (declared.where && declared.kind != parsed) {
      ctx.sink.error(e.GetLineNum(), concat("<rig kind=\"", *kind, "\"> contradicts the rig kind declared at ",
                                            where_text(*declared.where)));
      return;
    }
    if (!declared.where) declared = {parsed, ctx.sink.at(e.GetLineNum())};
  }

  void read_plugins(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser plugins_attributes(e, ctx.sink, {});
    if (scene_.plugins_where.file.empty()) scene_.plugins_where = ctx.sink.at(e.GetLineNum());
    for_each_child(e, ctx.sink, [&](const tinyxml2::XMLElement& child) {
      if (std::string_view(child.Name()) != "plugin") {
        report_unknown_element(child, e, ctx.sink);
        return;
      }
      read_plugin(child, ctx);
    });
  }

  void read_plugin(const tinyxml2::XMLElement& e, const FileContext& ctx) {
    AttributeParser a(e, ctx.sink, {"kind", "name"});
    PluginDescription plugin;
    plugin.where = ctx.sink.at(e.GetLineNum());
    if (const auto kind = a.token("kind", Presence::Required)) {
      static const std::map<std::string, PluginKind, std::less<>> kinds = {
          {"device", PluginKind::Device}, {"tracker", PluginKind::Tracker},
          {"base", PluginKind::Base}, {"display", PluginKind::Display},
          {"link", PluginKind::Link}};
      if (const auto it = kinds.find(*kind); it != kinds.end()) {
        plugin.kind = it->second;
      } else {
        ctx.sink.error(a.line_of("kind"),
                       concat("unknown plugin kind '", *kind,
                              "' (expected device, tracker, base, display or link)"));
      }
    }
    plugin.name = a.text("name", Presence::Required, Emptiness::Forbidden).value_or("");
    read_params(e, ctx, concat("plugin '", plugin.name, "'"), plugin.params, nullptr);
    scene_.plugins.push_back(std::move(plugin));
  }

  /// <param name="..." value="..."/> children of `e` into `params` (and their lines into
  /// `where`, when given); `owner` names `e` in messages.
  void read_params(const tinyxml2::XMLElement& e, const FileContext& ctx, const std::string& owner,
                   std::map<std::string, std::string>& params, std::map<std::string, SourceLocation>* where) {
    std::map<std::string, int, std::less<>> param_lines;
    for_each_child(e, ctx.sink, [&](const tinyxml2::XMLElement& child) {
      if (std::string_view(child.Name()) != "param") {
        report_unknown_element(child, e, ctx.sink);
        return;
      }
      AttributeParser pa(child, ctx.sink, {"name", "value"});
      expect_no_children(child, ctx.sink);
      const auto name = pa.text("name", Presence::Required, Emptiness::Forbidden);
      const auto value = pa.text("value", Presence::Required);
      if (!name) return;
      const auto [it, inserted] = param_lines.emplace(*name, child.GetLineNum());
      if (!inserted) {
        ctx.sink.error(child.GetLineNum(), concat("duplicate param '", *name, "' in ", owner,
                                                  " (the first is at line ", it->second, ")"));
        return;
      }
      if (value) {
        params.emplace(*name, *value);
        if (where != nullptr) where->emplace(*name, ctx.sink.at(child.GetLineNum()));
      }
    });
  }

  /// <simulated_user>, <planner kind="...">, <server>: one per scene, across includes.
  void read_param_block(const tinyxml2::XMLElement& e, const FileContext& ctx, std::optional<ParamBlock>& slot,
                        bool has_kind) {
    AttributeParser a = has_kind ? AttributeParser(e, ctx.sink, {"kind"}) : AttributeParser(e, ctx.sink, {});
    if (slot) {
      ctx.sink.error(e.GetLineNum(), concat("second ", tag(e), " (the first is at ", where_text(slot->where), ")"));
      return;
    }
    ParamBlock block;
    block.where = ctx.sink.at(e.GetLineNum());
    if (has_kind) block.kind = a.token("kind", Presence::Required).value_or("");
    read_params(e, ctx, tag(e), block.params, &block.param_where);
    slot = std::move(block);
  }

  /// Each stiffness against the bound at the scene's rate (known only once all is read).
  void check_stiffness_against_rate() {
    const double rate_Hz = scene_.haptics.update_rate_Hz;
    if (rate_Hz < kMinHapticRate_Hz || rate_Hz > kMaxHapticRate_Hz) return;  // reported already
    const double max_N_per_m = max_stable_stiffness_N_per_m(rate_Hz);
    for (const StiffnessUse& use : stiffness_uses_) {
      if (use.stiffness_N_per_m <= max_N_per_m) continue;
      diagnostics_.push_back(
          {use.where, concat("attribute 'stiffness_N_per_m' on <material> must not exceed ",
                             scene_xml::format_g(max_N_per_m), " N/m, the stiffest the device renders stably at ",
                             scene_xml::format_g(rate_Hz), " Hz, got ", scene_xml::format_g(use.stiffness_N_per_m))});
    }
  }

  void resolve_material_references() {
    for (const MaterialReference& ref : material_references_) {
      const auto it = scene_.materials.find(ref.name);
      if (it == scene_.materials.end()) {
        diagnostics_.push_back({ref.where, concat("object '", scene_.objects[ref.object_index].name,
                                                  "' uses unknown material '", ref.name, "'")});
      } else {
        scene_.objects[ref.object_index].material = it->second;
      }
    }
  }

  SceneDescription scene_;
  Diagnostics diagnostics_;
  std::vector<OpenFile> open_files_;  ///< the include chain being read, root first
  std::set<fs::path> read_files_;     ///< every file read, by identity
  std::vector<MaterialReference> material_references_;
  std::map<std::string, SourceLocation, std::less<>> material_where_;
  std::map<std::string, SourceLocation, std::less<>> object_where_;
  std::map<std::string, SourceLocation, std::less<>> frame_where_;
  std::optional<SourceLocation> haptics_where_;
  struct StiffnessUse {
    double stiffness_N_per_m = 0.0;
    SourceLocation where;
  };
  std::vector<StiffnessUse> stiffness_uses_;
};

}  // namespace

Result<SceneDescription> read_scene_file(const std::filesystem::path& file) {
  SceneReader reader;
  reader.read_root_file(file);
  return reader.finish();
}

Result<SceneDescription> read_scene_string(std::string_view xml, const std::filesystem::path& file) {
  SceneReader reader;
  reader.read_root(xml, file);
  return reader.finish();
}

}  // namespace mhd
