#pragma once
// Reads the typed settings of a <simulated_user>, <planner> or <server> block: each getter
// marks its parameter as known, returns the fallback when it is absent, and records a
// diagnostic at the param's file:line when the value is malformed. finish() reports every
// parameter nobody asked for. Numbers are C-locale decimals and must be finite.

#include "diagnostics/diagnostic.h"
#include "scene/scene_description.h"

#include <cstdint>
#include <set>
#include <string>
#include <string_view>

namespace mhd {

class ParamBlockReader {
 public:
  /// `block` may be null (no element in the scene: every getter returns its fallback).
  /// `element` names the block in messages, e.g. "<server>".
  ParamBlockReader(const ParamBlock* block, std::string element);

  [[nodiscard]] double number(std::string_view name, double fallback);
  [[nodiscard]] double positive(std::string_view name, double fallback);      ///< > 0
  [[nodiscard]] double non_negative(std::string_view name, double fallback);  ///< >= 0
  [[nodiscard]] double fraction(std::string_view name, double fallback);      ///< in [0, 1]
  /// A finite number in [low, high]; `unit` (may be empty) is named in the message.
  [[nodiscard]] double within(std::string_view name, double fallback, double low, double high, std::string_view unit);
  [[nodiscard]] std::uint64_t unsigned_integer(std::string_view name, std::uint64_t fallback);
  [[nodiscard]] bool boolean(std::string_view name, bool fallback);  ///< true/false/1/0
  [[nodiscard]] std::string text(std::string_view name, const std::string& fallback);
  /// True when the scene gives the parameter (and marks it known).
  [[nodiscard]] bool has(std::string_view name);

  /// Adds "unknown parameter 'x' in <server> (known: a, b)" for each unasked parameter
  /// and returns every diagnostic so far.
  [[nodiscard]] Diagnostics finish();
  /// Records a problem with a parameter's value (e.g. two that contradict each other).
  void error(std::string_view name, const std::string& message);

 private:
  [[nodiscard]] const std::string* find(std::string_view name);
  [[nodiscard]] SourceLocation where(std::string_view name) const;

  const ParamBlock* block_;
  std::string element_;
  std::set<std::string, std::less<>> known_;
  Diagnostics diagnostics_;
};

}  // namespace mhd
