#include "scene_xml/xml_parse_error.h"

#include "scene_xml/message_text.h"

#include <tinyxml2.h>

#include <string_view>

namespace mhd::scene_xml {
namespace {

// tinyxml2's ErrorStr() ends in ": XMLElement name=foo" when it knows the element.
std::string element_in_error(const tinyxml2::XMLDocument& document) {
  const char* raw = document.ErrorStr();
  const std::string_view text = raw != nullptr ? raw : "";
  constexpr std::string_view marker = "XMLElement name=";
  const std::size_t at = text.find(marker);
  if (at == std::string_view::npos) return {};
  std::string_view name = text.substr(at + marker.size());
  const std::size_t end = name.find_first_of(" \t\r\n");
  if (end != std::string_view::npos) name = name.substr(0, end);
  return std::string(name);
}

}  // namespace

std::string describe_xml_error(const tinyxml2::XMLDocument& document) {
  const std::string element = element_in_error(document);
  const std::string tag = element.empty() ? std::string("an element") : concat("<", element, ">");
  std::string what;
  switch (document.ErrorID()) {
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      what = concat(tag, " has no matching end tag");
      break;
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      what = concat("cannot parse ", tag, " (unclosed or badly formed tag)");
      break;
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      what = concat("bad attribute in ", tag,
                    " (values need quotes, names must be unique within an element)");
      break;
    case tinyxml2::XML_ERROR_PARSING_TEXT:
      what = "bad text (content after the root element, or a stray '<' or '&')";
      break;
    case tinyxml2::XML_ERROR_PARSING_CDATA:
      what = "unterminated CDATA section";
      break;
    case tinyxml2::XML_ERROR_PARSING_COMMENT:
      what = "unterminated comment";
      break;
    case tinyxml2::XML_ERROR_PARSING_DECLARATION:
      what = "bad <?...?> declaration";
      break;
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
      what = "bad <!...> section";
      break;
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
      what = "the document is empty";
      break;
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
      what = "elements are nested too deeply";
      break;
    default:
      what = concat("parse error (", tinyxml2::XMLDocument::ErrorIDToName(document.ErrorID()), ")");
      break;
  }
  return concat("malformed XML: ", what);
}

}  // namespace mhd::scene_xml
