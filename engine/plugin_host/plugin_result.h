#pragma once
// A value or the PluginError that stopped it (std::expected is C++23). Nothing here
// throws across the plugin ABI; value() on an error is a host bug and throws
// std::bad_variant_access.

#include "plugin_host/plugin_error.h"

#include <optional>
#include <utility>
#include <variant>

namespace mhd {

template <class T>
class [[nodiscard]] PluginResult {
 public:
  // Implicit, so a function returns either a value or a PluginError.
  PluginResult(T value) : state_(std::in_place_index<0>, std::move(value)) {}
  PluginResult(PluginError error) : state_(std::in_place_index<1>, std::move(error)) {}

  [[nodiscard]] bool ok() const noexcept { return state_.index() == 0; }
  explicit operator bool() const noexcept { return ok(); }

  [[nodiscard]] T& value() & { return std::get<0>(state_); }
  [[nodiscard]] const T& value() const& { return std::get<0>(state_); }
  [[nodiscard]] T&& value() && { return std::get<0>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  /// Precondition: !ok().
  [[nodiscard]] const PluginError& error() const { return std::get<1>(state_); }

 private:
  std::variant<T, PluginError> state_;
};

template <>
class [[nodiscard]] PluginResult<void> {
 public:
  PluginResult() = default;
  PluginResult(PluginError error) : error_(std::move(error)) {}

  [[nodiscard]] bool ok() const noexcept { return !error_.has_value(); }
  explicit operator bool() const noexcept { return ok(); }

  /// Precondition: !ok().
  [[nodiscard]] const PluginError& error() const { return error_.value(); }

 private:
  std::optional<PluginError> error_;
};

/// Outcome of a call that returns nothing but can fail.
using PluginStatus = PluginResult<void>;

}  // namespace mhd
