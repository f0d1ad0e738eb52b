#pragma once
// Typed, checked access to the attributes of one XML element. Constructing the parser
// reports every attribute that the element does not know; each getter reports what is
// wrong with its attribute (missing, malformed, out of range) and returns nullopt then.

#include "scene_xml/diagnostic_sink.h"

#include <Eigen/Core>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tinyxml2 {
class XMLAttribute;
class XMLElement;
}  // namespace tinyxml2

namespace mhd::scene_xml {

enum class Presence { Optional, Required };
enum class Bound { Any, Positive, NonNegative };
enum class Emptiness { Allowed, Forbidden };

class AttributeParser {
 public:
  AttributeParser(const tinyxml2::XMLElement& element, const DiagnosticSink& sink,
                  std::initializer_list<std::string_view> known);

  [[nodiscard]] bool has(std::string_view name) const;
  /// Line of the attribute if present, else of the element.
  [[nodiscard]] int line_of(std::string_view name) const;
  [[nodiscard]] int line() const;
  /// "<name>", for messages.
  [[nodiscard]] std::string tag() const;

  /// The raw value; with Emptiness::Forbidden an empty value is an error.
  std::optional<std::string> text(std::string_view name, Presence presence,
                                  Emptiness emptiness = Emptiness::Allowed);
  /// The value with XML white space trimmed (for enumerations such as unit="mm").
  std::optional<std::string> token(std::string_view name, Presence presence);
  std::optional<double> number(std::string_view name, Presence presence, Bound bound);
  /// Exactly `count` white-space separated numbers.
  std::optional<std::vector<double>> numbers(std::string_view name, Presence presence,
                                             std::size_t count, Bound bound);
  std::optional<Eigen::Vector3d> vector3(std::string_view name, Presence presence, Bound bound);
  std::optional<int> integer(std::string_view name, Presence presence, int min, int max);
  /// "true" or "false".
  std::optional<bool> boolean(std::string_view name, Presence presence);

 private:
  const tinyxml2::XMLAttribute* find(std::string_view name, Presence presence) const;
  std::optional<double> parse_one(const tinyxml2::XMLAttribute& attribute, std::string_view token,
                                  Bound bound) const;

  const tinyxml2::XMLElement* element_;
  const DiagnosticSink* sink_;
};

}  // namespace mhd::scene_xml
