#pragma once
// The one exception the bindings throw for a problem the engine found in user input
// (a scene, a recording, a HIP path, a plugin) or for a run that ended on a fault. It
// crosses into Python as mhd.MhdError, whose message is the engine's own
// "file:line: error: message" lines and whose `diagnostics` attribute lists them;
// `report` is the server's report when a fault ended a run, else None.

#include "haptic_server/haptic_server.h"
#include "diagnostics/diagnostic.h"

#include <optional>
#include <stdexcept>
#include <string>

namespace mhd::python {

class EngineError : public std::runtime_error {
 public:
  /// The message is the diagnostics' lines.
  explicit EngineError(Diagnostics diagnostics);
  /// A message of its own (e.g. a run's fault, which already names the plugin and scene line).
  EngineError(const std::string& message, Diagnostics diagnostics, std::optional<ServerReport> report);

  [[nodiscard]] const Diagnostics& diagnostics() const noexcept { return diagnostics_; }
  [[nodiscard]] const std::optional<ServerReport>& report() const noexcept { return report_; }

 private:
  Diagnostics diagnostics_;
  std::optional<ServerReport> report_;
};

/// The diagnostics' lines ("file:line: error: message"), one per line.
[[nodiscard]] std::string diagnostics_text(const Diagnostics& diagnostics);

}  // namespace mhd::python
