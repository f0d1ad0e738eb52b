#include "diagnostics/result.h"

#include <utility>

namespace mhd::result_detail {

const Diagnostics& no_diagnostics() noexcept {
  static const Diagnostics none;
  return none;
}

void never_empty(Diagnostics& errors) {
  if (!errors.empty()) return;
  Diagnostic d;
  d.message = "failed, no diagnostic given";
  errors.push_back(std::move(d));
}

void throw_bad_value_access(const std::string& error) {
  throw BadResultAccess("value() of a result that holds an error: " + error);
}

void throw_bad_error_access() { throw BadResultAccess("error() of a result that holds a value"); }

}  // namespace mhd::result_detail
