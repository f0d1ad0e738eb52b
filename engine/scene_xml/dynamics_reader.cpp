#include "scene_xml/dynamics_reader.h"

#include "scene_xml/xml_attribute_parser.h"

#include <tinyxml2.h>

namespace mhd::scene_xml {

std::optional<ObjectDynamics> read_dynamics(const tinyxml2::XMLElement& e, const DiagnosticSink& sink) {
  AttributeParser a(e, sink, {"mass_kg", "friction"});
  const std::size_t errors_before = sink.error_count();
  if (e.FirstChildElement() != nullptr) sink.error(e.FirstChildElement()->GetLineNum(), "<dynamics> takes attributes only");
  const auto mass_kg = a.number("mass_kg", Presence::Required, Bound::Positive);
  const auto friction = a.number("friction", Presence::Optional, Bound::NonNegative);
  if (!mass_kg || sink.error_count() != errors_before) return std::nullopt;
  return ObjectDynamics{*mass_kg, friction.value_or(kDefaultBodyFriction)};
}

}  // namespace mhd::scene_xml
