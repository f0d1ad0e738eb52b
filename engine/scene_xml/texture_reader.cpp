#include "scene_xml/texture_reader.h"

#include "scene/plausible_bounds.h"
#include "scene_xml/message_text.h"
#include "scene_xml/number_parser.h"
#include "scene_xml/readable_file.h"
#include "scene_xml/xml_attribute_parser.h"

#include <tinyxml2.h>

#include <array>
#include <string_view>
#include <system_error>

namespace mhd::scene_xml {
namespace {

namespace fs = std::filesystem;

struct KindName {
  std::string_view name;
  TextureKind kind;
};
constexpr std::array<KindName, 3> kKinds = {
    {{"grating", TextureKind::Grating}, {"noise", TextureKind::Noise}, {"image", TextureKind::HeightMap}}};

/// The attributes that only one kind takes, and that kind's name.
struct KindOnly {
  std::string_view attribute;
  std::string_view kind;
};
constexpr std::array<KindOnly, 6> kKindOnly = {{{"direction", "grating"},
                                                {"max_period_m", "noise"},
                                                {"seed", "noise"},
                                                {"file", "image"},
                                                {"size_m", "image"},
                                                {"period_m", "grating or noise"}}};

class TextureReader {
 public:
  TextureReader(const tinyxml2::XMLElement& e, const DiagnosticSink& sink)
      : e_(e),
        sink_(sink),
        a_(e, sink,
           {"kind", "depth_m", "period_m", "max_period_m", "direction", "seed", "file", "size_m", "projection",
            "friction_contrast"}) {}

  std::optional<HapticTextureSpec> read() {
    report_children();
    const auto kind = read_kind();
    if (!kind) return std::nullopt;
    spec_.kind = *kind;
    read_depth();
    read_projection();
    if (const auto c = a_.number("friction_contrast", Presence::Optional, Bound::NonNegative)) {
      spec_.friction_contrast = *c;
      if (*c > 1.0) fail("friction_contrast", concat("must not exceed 1 (friction stays >= 0), got ", format_g(*c)));
    }
    switch (spec_.kind) {
      case TextureKind::Grating: read_grating(); break;
      case TextureKind::Noise: read_noise(); break;
      case TextureKind::HeightMap: read_image(); break;
    }
    return ok_ ? std::optional<HapticTextureSpec>(spec_) : std::nullopt;
  }

 private:
  void fail(std::string_view attribute, const std::string& what) {
    sink_.error(a_.line_of(attribute), concat("attribute '", attribute, "' on <texture> ", what));
    ok_ = false;
  }

  void report_children() {
    for (const tinyxml2::XMLNode* n = e_.FirstChild(); n != nullptr; n = n->NextSibling()) {
      if (const tinyxml2::XMLElement* child = n->ToElement()) {
        sink_.error(child->GetLineNum(), concat("unknown element <", child->Name(), "> in <texture>"));
        ok_ = false;
      } else if (const tinyxml2::XMLText* t = n->ToText(); t != nullptr && !trim_xml_space(t->Value()).empty()) {
        sink_.error(t->GetLineNum(), "unexpected text in <texture>");
        ok_ = false;
      }
    }
  }

  std::optional<TextureKind> read_kind() {
    const auto kind = a_.token("kind", Presence::Required);
    if (!kind) return std::nullopt;
    std::string_view kind_name;
    std::optional<TextureKind> found;
    for (const KindName& k : kKinds) {
      if (k.name == *kind) {
        found = k.kind;
        kind_name = k.name;
      }
    }
    if (!found) {
      sink_.error(a_.line_of("kind"), concat("unknown texture kind '", *kind, "' (expected grating, noise or image)"));
      return std::nullopt;
    }
    for (const KindOnly& only : kKindOnly) {
      if (a_.has(only.attribute) && only.kind.find(kind_name) == std::string_view::npos) {
        fail(only.attribute, concat("applies to kind ", only.kind, " only, not to kind ", kind_name));
      }
    }
    return found;
  }

  void read_depth() {
    const auto depth = a_.number("depth_m", Presence::Required, Bound::NonNegative);
    if (!depth) {
      ok_ = false;
      return;
    }
    spec_.depth_m = *depth;
    if (*depth > kMaxTextureDepth_m) {
      fail("depth_m", concat("must not exceed ", format_g(kMaxTextureDepth_m),
                             " m (deeper relief is a shape: model it as geometry), got ", format_g(*depth)));
    }
  }

  void read_projection() {
    const auto projection = a_.token("projection", Presence::Optional);
    if (!projection) return;
    if (*projection == "xy") {
      spec_.projection = TextureProjection::Xy;
    } else if (*projection == "yz") {
      spec_.projection = TextureProjection::Yz;
    } else if (*projection == "zx") {
      spec_.projection = TextureProjection::Zx;
    } else {
      fail("projection", concat("must be xy, yz or zx (the object-frame plane the texture is projected onto), got '",
                                *projection, "'"));
    }
  }

  /// A length in [kMinTexturePeriod_m, kMaxTexturePeriod_m].
  bool check_length(std::string_view attribute, double value_m) {
    if (value_m >= kMinTexturePeriod_m && value_m <= kMaxTexturePeriod_m) return true;
    fail(attribute, concat("must be within [", format_g(kMinTexturePeriod_m), ", ", format_g(kMaxTexturePeriod_m),
                           "] m, got ", format_g(value_m)));
    return false;
  }

  void read_period(Presence presence) {
    const auto period = a_.number("period_m", presence, Bound::Positive);
    if (!period) {
      if (presence == Presence::Required || a_.has("period_m")) ok_ = false;
      return;
    }
    spec_.period_m = *period;
    check_length("period_m", *period);
  }

  void read_grating() {
    read_period(Presence::Required);
    if (const auto d = a_.numbers("direction", Presence::Optional, 2, Bound::Any)) {
      spec_.direction_uv = {(*d)[0], (*d)[1]};
      if (spec_.direction_uv.cwiseAbs().maxCoeff() == 0.0) fail("direction", "must not be \"0 0\"");
    } else if (a_.has("direction")) {
      ok_ = false;
    }
  }

  void read_noise() {
    read_period(Presence::Required);
    spec_.max_period_m = 4.0 * spec_.period_m;
    if (const auto longest = a_.number("max_period_m", Presence::Optional, Bound::Positive)) {
      spec_.max_period_m = *longest;
      if (check_length("max_period_m", *longest) && *longest < spec_.period_m) {
        fail("max_period_m", concat("must not be below period_m (", format_g(spec_.period_m), "), got ",
                                    format_g(*longest)));
      }
    } else if (a_.has("max_period_m")) {
      ok_ = false;
    }
    if (const auto seed = a_.integer("seed", Presence::Optional, 0, 2'147'483'647)) {
      spec_.seed = static_cast<std::uint64_t>(*seed);
    } else if (a_.has("seed")) {
      ok_ = false;
    }
  }

  void read_image() {
    if (const auto size = a_.numbers("size_m", Presence::Required, 2, Bound::Positive)) {
      spec_.image_size_m = {(*size)[0], (*size)[1]};
      if (check_length("size_m", spec_.image_size_m.x())) check_length("size_m", spec_.image_size_m.y());
    } else {
      ok_ = false;
    }
    const auto file = a_.text("file", Presence::Required, Emptiness::Forbidden);
    if (!file) {
      ok_ = false;
      return;
    }
    fs::path resolved(*file);
    if (!resolved.is_absolute()) resolved = fs::path(sink_.file()).parent_path() / resolved;
    std::error_code ec;
    const fs::path absolute = fs::absolute(resolved, ec);
    spec_.image_file = ec ? resolved.lexically_normal() : absolute.lexically_normal();
    const FileProblem problem = check_readable_file(spec_.image_file);
    if (problem != FileProblem::None) {
      sink_.error(a_.line_of("file"), concat("texture image '", *file, "' ", describe(problem), " (resolved to '",
                                             spec_.image_file.string(), "')"));
      ok_ = false;
    }
  }

  const tinyxml2::XMLElement& e_;
  const DiagnosticSink& sink_;
  AttributeParser a_;
  HapticTextureSpec spec_;
  bool ok_ = true;
};

}  // namespace

std::optional<HapticTextureSpec> read_texture(const tinyxml2::XMLElement& e, const DiagnosticSink& sink) {
  return TextureReader(e, sink).read();
}

}  // namespace mhd::scene_xml
