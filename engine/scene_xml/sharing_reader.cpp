#include "scene_xml/sharing_reader.h"

#include "scene_xml/message_text.h"
#include "scene_xml/xml_attribute_parser.h"

#include <tinyxml2.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace mhd::scene_xml {
namespace {

// "1 2 3": rig ids in [0, kMaxRigId], at least one, at most kMaxSharingRigs, none twice.
std::vector<std::uint32_t> parse_rigs(const std::string& text, int line, const DiagnosticSink& sink) {
  std::vector<std::uint32_t> rigs;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (word.size() > 6 || word.find_first_not_of("0123456789") != std::string::npos) {
      sink.error(line, "rigs must be rig ids in [0, " + std::to_string(kMaxRigId) + "], got '" + text + "'");
      return {};
    }
    const auto rig = static_cast<std::uint32_t>(std::stoul(word));
    if (std::find(rigs.begin(), rigs.end(), rig) != rigs.end()) {
      sink.error(line, "rigs names rig " + word + " twice");
      return {};
    }
    rigs.push_back(rig);
  }
  if (rigs.empty()) sink.error(line, "rigs must name at least one rig");
  if (rigs.size() > static_cast<std::size_t>(kMaxSharingRigs)) {
    sink.error(line, "rigs names more than " + std::to_string(kMaxSharingRigs) + " rigs");
  }
  return rigs;
}

SharedObjectDescription read_shared_object(const tinyxml2::XMLElement& e, const DiagnosticSink& sink) {
  AttributeParser a(e, sink, {"object", "id", "rigs"});
  if (e.FirstChildElement() != nullptr) {
    sink.error(e.FirstChildElement()->GetLineNum(), "<shared_object> takes attributes only");
  }
  SharedObjectDescription d;
  d.where = sink.at(e.GetLineNum());
  d.object = a.text("object", Presence::Required, Emptiness::Forbidden).value_or("");
  d.id = static_cast<std::uint32_t>(a.integer("id", Presence::Required, 0, 2147483647).value_or(0));
  if (const auto rigs = a.text("rigs", Presence::Required, Emptiness::Forbidden)) {
    d.rigs = parse_rigs(*rigs, a.line_of("rigs"), sink);
  }
  return d;
}

}  // namespace

SharingDescription read_sharing(const tinyxml2::XMLElement& e, const DiagnosticSink& sink) {
  AttributeParser a(e, sink, {"rig_id"});
  SharingDescription s;
  s.where = sink.at(e.GetLineNum());
  const std::optional<int> rig_id = a.integer("rig_id", Presence::Required, 0, kMaxRigId);
  s.rig_id = static_cast<std::uint32_t>(rig_id.value_or(0));
  s.rig_id_read = rig_id.has_value();
  for (const tinyxml2::XMLElement* child = e.FirstChildElement(); child != nullptr;
       child = child->NextSiblingElement()) {
    if (std::string(child->Name()) != "shared_object") {
      sink.error(child->GetLineNum(), concat("unknown element <", child->Name(), "> in <sharing> (expected <shared_object>)"));
      continue;
    }
    if (s.objects.size() == static_cast<std::size_t>(kMaxSceneSharedObjects)) {
      sink.error(child->GetLineNum(), "a scene shares at most " + std::to_string(kMaxSceneSharedObjects) + " objects");
      break;
    }
    s.objects.push_back(read_shared_object(*child, sink));
  }
  if (s.objects.empty()) sink.error(e.GetLineNum(), "<sharing> names no <shared_object>");
  return s;
}

Diagnostics check_sharing(const SceneDescription& scene) {
  Diagnostics out;
  if (!scene.sharing) return out;
  const SharingDescription& sharing = *scene.sharing;
  for (std::size_t i = 0; i < sharing.objects.size(); ++i) {
    const SharedObjectDescription& d = sharing.objects[i];
    if (d.object.empty() || d.rigs.empty()) continue;  // reported when read
    const auto object = std::find_if(scene.objects.begin(), scene.objects.end(),
                                     [&](const ObjectDescription& o) { return o.name == d.object; });
    if (object == scene.objects.end()) {
      out.push_back({d.where, "shared object '" + d.object + "' is not an <object> of the scene"});
    } else if (!object->dynamics) {
      out.push_back({d.where, "shared object '" + d.object +
                                  "' is not pushable: only an object with <dynamics> can be shared (its authority "
                                  "runs its physics)"});
    }
    if (sharing.rig_id_read && std::find(d.rigs.begin(), d.rigs.end(), sharing.rig_id) == d.rigs.end()) {
      out.push_back({d.where, "shared object '" + d.object + "': rigs does not name this rig (<sharing rig_id=\"" +
                                  std::to_string(sharing.rig_id) + "\">)"});
    }
    for (std::size_t j = 0; j < i; ++j) {
      const SharedObjectDescription& before = sharing.objects[j];
      if (before.object == d.object) {
        out.push_back({d.where, "object '" + d.object + "' is shared twice (the first at line " +
                                    std::to_string(before.where.line) + ")"});
      } else if (before.id == d.id) {
        out.push_back({d.where, "shared object id " + std::to_string(d.id) + " is taken by '" + before.object +
                                    "' (line " + std::to_string(before.where.line) + ")"});
      }
    }
  }
  return out;
}

}  // namespace mhd::scene_xml
