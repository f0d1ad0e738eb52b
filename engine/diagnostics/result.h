#pragma once
// The engine's one result type: a value, or the error that stopped it (std::expected is
// C++23). The error is a list of diagnostics, each tied to a file and line, unless a
// layer has a richer error of its own (a plugin's kind and path, a calibration's
// parameter): Result<T, PluginError>. Functions that can fail return a Result and throw
// nothing for bad input; value() on an error is the caller's bug and throws
// BadResultAccess naming the error it ignored.

#include "diagnostics/diagnostic.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace mhd {

/// value() on an error, or error() on a value.
class BadResultAccess : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace result_detail {
[[nodiscard]] inline std::string describe(const Diagnostics& d) { return to_string(d); }
template <class E>
[[nodiscard]] std::string describe(const E& e) {
  if constexpr (std::is_convertible_v<const E&, std::string>) {
    return std::string(e);
  } else if constexpr (requires { e.to_string(); }) {
    return e.to_string();
  } else if constexpr (requires { std::string(*e.begin()); }) {
    std::string out;
    for (const auto& item : e) {
      if (!out.empty()) out += '\n';
      out.append(item);
    }
    return out;
  } else if constexpr (requires { e.begin()->to_string(); }) {
    std::string out;
    for (const auto& item : e) {
      if (!out.empty()) out += '\n';
      out.append(item.to_string());
    }
    return out;
  } else if constexpr (requires { e.message(); }) {
    return e.message();
  } else if constexpr (requires { e.message; }) {
    return std::string(e.message);
  } else {
    return "an error";
  }
}
[[nodiscard]] const Diagnostics& no_diagnostics() noexcept;
/// Adds "failed, no diagnostic given" to an empty list.
void never_empty(Diagnostics& errors);
[[noreturn]] void throw_bad_value_access(const std::string& error);
[[noreturn]] void throw_bad_error_access();
}  // namespace result_detail

template <class T, class E = Diagnostics>
class [[nodiscard]] Result {
  static_assert(!std::is_same_v<std::remove_cvref_t<T>, std::remove_cvref_t<E>>, "a value and an error of one type");

 public:
  // Implicit, so that a function returns either its value or its error.
  Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}
  /// An error. With E = Diagnostics, an empty list is itself an error ("no diagnostic
  /// given") rather than a failure nobody can explain.
  Result(E error) : state_(std::in_place_index<1>, std::move(error)) {
    if constexpr (std::is_same_v<E, Diagnostics>) {
      result_detail::never_empty(std::get<1>(state_));
    }
  }
  /// One diagnostic as the error.
  Result(Diagnostic error)
    requires std::is_same_v<E, Diagnostics>
      : Result(Diagnostics{std::move(error)}) {}

  [[nodiscard]] bool ok() const noexcept { return state_.index() == 0; }
  explicit operator bool() const noexcept { return ok(); }

  /// The value; throws BadResultAccess (naming the error) when !ok().
  [[nodiscard]] T& value() & { return check(), std::get<0>(state_); }
  [[nodiscard]] const T& value() const& { return check(), std::get<0>(state_); }
  [[nodiscard]] T&& value() && { return check(), std::get<0>(std::move(state_)); }
  /// The value, or `fallback` when !ok().
  [[nodiscard]] T value_or(T fallback) const& { return ok() ? std::get<0>(state_) : std::move(fallback); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  /// The error; throws BadResultAccess when ok().
  [[nodiscard]] const E& error() const {
    if (ok()) result_detail::throw_bad_error_access();
    return std::get<1>(state_);
  }
  /// The error as text, one line per diagnostic; "" when ok().
  [[nodiscard]] std::string error_text() const { return ok() ? std::string() : result_detail::describe(error()); }
  /// The diagnostics whatever the outcome: the error's, or none when ok().
  [[nodiscard]] const Diagnostics& diagnostics() const noexcept
    requires std::is_same_v<E, Diagnostics>
  {
    return ok() ? result_detail::no_diagnostics() : std::get<1>(state_);
  }

 private:
  void check() const {
    if (!ok()) result_detail::throw_bad_value_access(result_detail::describe(std::get<1>(state_)));
  }
  std::variant<T, E> state_;
};

/// Success with nothing to return, or the error.
template <class E>
class [[nodiscard]] Result<void, E> {
 public:
  Result() = default;
  Result(E error) : error_(std::move(error)) {
    if constexpr (std::is_same_v<E, Diagnostics>) {
      result_detail::never_empty(*error_);
    }
  }
  Result(Diagnostic error)
    requires std::is_same_v<E, Diagnostics>
      : Result(Diagnostics{std::move(error)}) {}

  [[nodiscard]] bool ok() const noexcept { return !error_.has_value(); }
  explicit operator bool() const noexcept { return ok(); }
  /// The error; throws BadResultAccess when ok().
  [[nodiscard]] const E& error() const {
    if (ok()) result_detail::throw_bad_error_access();
    return *error_;
  }
  [[nodiscard]] std::string error_text() const { return ok() ? std::string() : result_detail::describe(*error_); }
  /// The diagnostics whatever the outcome: the error's, or none when ok().
  [[nodiscard]] const Diagnostics& diagnostics() const noexcept
    requires std::is_same_v<E, Diagnostics>
  {
    return ok() ? result_detail::no_diagnostics() : *error_;
  }

 private:
  std::optional<E> error_;
};

/// A call that returns nothing but can fail.
template <class E = Diagnostics>
using Status = Result<void, E>;

}  // namespace mhd
