#pragma once
// Problems found in user input, each tied to the file and line where it stands.

#include <string>
#include <vector>

namespace mhd {

struct SourceLocation {
  std::string file;  ///< path as the user gave it or as resolved from an include
  int line = 0;      ///< 1-based; 0 when unknown (file-level problems)
};

struct Diagnostic {
  SourceLocation where;
  std::string message;

  /// "file:line: error: message" (or "file: error: message" when line is 0).
  [[nodiscard]] std::string to_string() const;
};

using Diagnostics = std::vector<Diagnostic>;

/// One line per diagnostic, as Diagnostic::to_string; "" for none.
[[nodiscard]] std::string to_string(const Diagnostics& diagnostics);

}  // namespace mhd
