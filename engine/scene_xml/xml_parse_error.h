#pragma once
// Turns tinyxml2's parse error into a sentence for a diagnostic.

namespace tinyxml2 {
class XMLDocument;
}

#include <string>

namespace mhd::scene_xml {

/// "malformed XML: ..." for a document whose Parse() failed; its line is
/// document.ErrorLineNum() (0 when tinyxml2 knows none).
[[nodiscard]] std::string describe_xml_error(const tinyxml2::XMLDocument& document);

}  // namespace mhd::scene_xml
