#include "scene_xml/xml_attribute_parser.h"

#include "scene_xml/message_text.h"
#include "scene_xml/number_parser.h"

#include <tinyxml2.h>

#include <algorithm>

namespace mhd::scene_xml {

AttributeParser::AttributeParser(const tinyxml2::XMLElement& element, const DiagnosticSink& sink,
                                 std::initializer_list<std::string_view> known)
    : element_(&element), sink_(&sink) {
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      sink.error(a->GetLineNum(), concat("unknown attribute '", name, "' on ", tag()));
    }
  }
}

bool AttributeParser::has(std::string_view name) const {
  return element_->FindAttribute(std::string(name).c_str()) != nullptr;
}

int AttributeParser::line_of(std::string_view name) const {
  const tinyxml2::XMLAttribute* a = element_->FindAttribute(std::string(name).c_str());
  return a != nullptr ? a->GetLineNum() : element_->GetLineNum();
}

int AttributeParser::line() const { return element_->GetLineNum(); }

std::string AttributeParser::tag() const { return concat("<", element_->Name(), ">"); }

const tinyxml2::XMLAttribute* AttributeParser::find(std::string_view name, Presence presence) const {
  const tinyxml2::XMLAttribute* a = element_->FindAttribute(std::string(name).c_str());
  if (a == nullptr && presence == Presence::Required) {
    sink_->error(line(), concat("missing required attribute '", name, "' on ", tag()));
  }
  return a;
}

std::optional<std::string> AttributeParser::text(std::string_view name, Presence presence,
                                                 Emptiness emptiness) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  std::string value = a->Value();
  if (emptiness == Emptiness::Forbidden && value.empty()) {
    sink_->error(a->GetLineNum(), concat("attribute '", name, "' on ", tag(), " must not be empty"));
    return std::nullopt;
  }
  return value;
}

std::optional<std::string> AttributeParser::token(std::string_view name, Presence presence) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  return std::string(trim_xml_space(a->Value()));
}

std::optional<double> AttributeParser::parse_one(const tinyxml2::XMLAttribute& attribute,
                                                 std::string_view token, Bound bound) const {
  const ParsedDouble parsed = parse_double(token);
  const std::string_view shown = trim_xml_space(token);
  const std::string_view name = attribute.Name();
  const int at = attribute.GetLineNum();
  switch (parsed.status) {
    case NumberStatus::Ok:
      break;
    case NumberStatus::Invalid:
      sink_->error(at, concat("invalid number '", shown, "' for attribute '", name, "' on ", tag()));
      return std::nullopt;
    case NumberStatus::NonFinite:
      sink_->error(at,
                   concat("non-finite number '", shown, "' for attribute '", name, "' on ", tag()));
      return std::nullopt;
    case NumberStatus::OutOfRange:
      sink_->error(at, concat("number '", shown, "' for attribute '", name, "' on ", tag(),
                              " is out of range"));
      return std::nullopt;
  }
  if (bound == Bound::Positive && !(parsed.value > 0.0)) {
    sink_->error(at, concat("attribute '", name, "' on ", tag(), " must be > 0, got ", shown));
    return std::nullopt;
  }
  if (bound == Bound::NonNegative && !(parsed.value >= 0.0)) {
    sink_->error(at, concat("attribute '", name, "' on ", tag(), " must be >= 0, got ", shown));
    return std::nullopt;
  }
  return parsed.value;
}

std::optional<double> AttributeParser::number(std::string_view name, Presence presence,
                                              Bound bound) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  return parse_one(*a, a->Value(), bound);
}

std::optional<std::vector<double>> AttributeParser::numbers(std::string_view name,
                                                            Presence presence, std::size_t count,
                                                            Bound bound) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  const std::vector<std::string_view> tokens = split_xml_space(a->Value());
  if (tokens.size() != count) {
    sink_->error(a->GetLineNum(), concat("attribute '", name, "' on ", tag(), " needs ", count,
                                         " numbers, got ", tokens.size()));
    return std::nullopt;
  }
  std::vector<double> values;
  values.reserve(count);
  for (const std::string_view t : tokens) {
    const std::optional<double> v = parse_one(*a, t, bound);
    if (!v) return std::nullopt;  // one error per attribute is enough
    values.push_back(*v);
  }
  return values;
}

std::optional<Eigen::Vector3d> AttributeParser::vector3(std::string_view name, Presence presence,
                                                        Bound bound) {
  const std::optional<std::vector<double>> v = numbers(name, presence, 3, bound);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<int> AttributeParser::integer(std::string_view name, Presence presence, int min,
                                            int max) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  const ParsedInteger parsed = parse_integer(a->Value());
  const std::string_view shown = trim_xml_space(a->Value());
  if (parsed.status != NumberStatus::Ok) {
    sink_->error(a->GetLineNum(),
                 concat("invalid integer '", shown, "' for attribute '", name, "' on ", tag()));
    return std::nullopt;
  }
  if (parsed.value < min || parsed.value > max) {
    sink_->error(a->GetLineNum(), concat("attribute '", name, "' on ", tag(), " must be in [", min,
                                         ", ", max, "], got ", shown));
    return std::nullopt;
  }
  return static_cast<int>(parsed.value);
}

std::optional<bool> AttributeParser::boolean(std::string_view name, Presence presence) {
  const tinyxml2::XMLAttribute* a = find(name, presence);
  if (a == nullptr) return std::nullopt;
  const std::string_view value = trim_xml_space(a->Value());
  if (value == "true") return true;
  if (value == "false") return false;
  sink_->error(a->GetLineNum(), concat("invalid boolean '", value, "' for attribute '", name,
                                       "' on ", tag(), " (expected true or false)"));
  return std::nullopt;
}

}  // namespace mhd::scene_xml
