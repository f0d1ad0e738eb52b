#pragma once
// Collects the errors found in one scene file: every message gets that file's name
// and the line it concerns. Several sinks (one per included file) share one list.

#include "diagnostics/diagnostic.h"

#include <cstddef>
#include <string>
#include <utility>

namespace mhd::scene_xml {

class DiagnosticSink {
 public:
  DiagnosticSink(std::string file, Diagnostics& out) : file_(std::move(file)), out_(&out) {}

  void error(int line, std::string message) const {
    out_->push_back(Diagnostic{at(line), std::move(message)});
  }
  [[nodiscard]] SourceLocation at(int line) const { return SourceLocation{file_, line}; }
  [[nodiscard]] const std::string& file() const { return file_; }
  /// Errors in the shared list so far (all files): a reader compares two counts to see
  /// whether a part it read was clean.
  [[nodiscard]] std::size_t error_count() const { return out_->size(); }

 private:
  std::string file_;
  Diagnostics* out_;
};

}  // namespace mhd::scene_xml
