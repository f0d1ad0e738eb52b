#include "scene/diagnostic.h"

namespace mhd {

std::string Diagnostic::to_string() const {
  std::string out = where.file;
  if (where.line > 0) {
    out += ':';
    out += std::to_string(where.line);
  }
  out += ": error: ";
  out += message;
  return out;
}

}  // namespace mhd
