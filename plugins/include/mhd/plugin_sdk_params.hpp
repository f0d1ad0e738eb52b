// MHD plugin SDK, parameter values: the typed view of a scene's <param>s that
// mhd::sdk::plugin_table hands a plugin's constructor. Header-only C++20 over
// mhd/plugin_params.hpp, whose one parser (and its rules: C-locale finite numbers,
// non-negative integers, blank-separated vectors, "true"/"false") the host applies too.
//
// Promises:
//   - Params's constructor runs sdk::check_params against the plugin's declarations and
//     throws ParamError with the first problem (unknown, repeated, ill-formed, out of
//     range, required but missing), so every getter reads a value that is already valid.
//   - A getter asking for a name the plugin did not declare throws std::logic_error: a
//     plugin bug its own tests catch, never a user error.
//   - Each parameter has one default, the declared one: a getter returns the scene's
//     value, else the declared default; with neither it throws std::logic_error (declare
//     a default, or read it with optional_* when absent means something of its own).
//   - A Params refers to the arrays it was made from: use it inside the constructor only.
#ifndef MHD_PLUGIN_SDK_PARAMS_HPP
#define MHD_PLUGIN_SDK_PARAMS_HPP

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace mhd::sdk {

/// A scene's parameter refused at open(); what() is the message open() returns.
class ParamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Params {
 public:
  /// Throws ParamError with the first problem sdk::check_params finds, cut to fit an
  /// mhd_error ("...)" marks a cut list of known names).
  Params(std::span<const mhd_param_decl> decls, const mhd_param* params, std::size_t count)
      : decls_(decls), params_(params), count_(count) {
    const std::vector<std::string> problems = check_params(decls.data(), decls.size(), params, count);
    if (problems.empty()) return;
    std::string message = problems.front();
    if (message.size() >= MHD_ERROR_MESSAGE_SIZE) message = message.substr(0, MHD_ERROR_MESSAGE_SIZE - 5) + "...)";
    throw ParamError(message);
  }

  /// Whether the scene gives `name`.
  [[nodiscard]] bool given(std::string_view name) const { return scene_value(name) != nullptr; }

  [[nodiscard]] std::optional<std::string> optional_text(std::string_view name) const {
    const char* v = scene_value(name);
    return v != nullptr ? std::optional<std::string>(v) : std::nullopt;
  }
  [[nodiscard]] std::string text(std::string_view name) const { return value_or_default(name); }

  [[nodiscard]] std::optional<double> optional_number(std::string_view name) const {
    const char* v = scene_value(name);
    return v != nullptr ? std::optional<double>(to_number(v)) : std::nullopt;
  }
  [[nodiscard]] double number(std::string_view name) const { return to_number(value_or_default(name)); }

  [[nodiscard]] std::optional<std::uint64_t> optional_integer(std::string_view name) const {
    const char* v = scene_value(name);
    return v != nullptr ? std::optional<std::uint64_t>(to_integer(v)) : std::nullopt;
  }
  [[nodiscard]] std::uint64_t integer(std::string_view name) const { return to_integer(value_or_default(name)); }

  [[nodiscard]] bool boolean(std::string_view name) const { return detail::trim(value_or_default(name)) == "true"; }

  /// "x y z" as V(x, y, z) (or V{x, y, z} for an aggregate such as std::array).
  template <class V = std::array<double, 3>>
  [[nodiscard]] std::optional<V> optional_vector3(std::string_view name) const {
    const char* v = scene_value(name);
    if (v == nullptr) return std::nullopt;
    const std::vector<double> x = to_numbers(v);
    return make<V>(x[0], x[1], x[2]);
  }
  template <class V = std::array<double, 3>>
  [[nodiscard]] V vector3(std::string_view name) const {
    const std::vector<double> x = to_numbers(value_or_default(name));
    return make<V>(x[0], x[1], x[2]);
  }

  /// "w x y z", normalised, as Q(w, x, y, z) (Eigen::Quaterniond's order) or Q{w, x, y, z}.
  template <class Q = std::array<double, 4>>
  [[nodiscard]] std::optional<Q> optional_quaternion(std::string_view name) const {
    const char* v = scene_value(name);
    if (v == nullptr) return std::nullopt;
    const std::vector<double> q = to_numbers(v);
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);  // > 0: checked
    return make<Q>(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
  }

 private:
  const mhd_param_decl& declaration(std::string_view name) const {
    const mhd_param_decl* d = find_declaration(decls_.data(), decls_.size(), name);
    if (d == nullptr) {
      throw std::logic_error("the plugin reads parameter '" + std::string(name) + "', which it does not declare");
    }
    return *d;
  }
  /// The scene's text for a declared name, NULL when absent.
  const char* scene_value(std::string_view name) const {
    (void)declaration(name);
    for (std::size_t i = 0; i < count_; ++i) {
      if (name == params_[i].name) return params_[i].value;
    }
    return nullptr;
  }
  const char* value_or_default(std::string_view name) const {
    if (const char* v = scene_value(name)) return v;
    const mhd_param_decl& d = declaration(name);
    if (d.default_value == nullptr) {
      throw std::logic_error("parameter '" + std::string(name) + "' has no default: read it with optional_*");
    }
    return d.default_value;
  }
  // The values were checked by check_params (or check_declarations for defaults).
  static double to_number(std::string_view v) { return detail::parse_number(v).value_or(0.0); }
  static std::uint64_t to_integer(std::string_view v) {
    v = detail::trim(v);
    std::uint64_t out = 0;
    std::from_chars(v.data(), v.data() + v.size(), out);
    return out;
  }
  static std::vector<double> to_numbers(std::string_view v) {
    std::vector<double> out = detail::parse_numbers(v).value_or(std::vector<double>{});
    out.resize(4, 0.0);
    return out;
  }
  template <class T, class... A>
  static T make(A... a) {
    if constexpr (std::is_aggregate_v<T>) {
      return T{a...};
    } else {
      return T(a...);
    }
  }

  std::span<const mhd_param_decl> decls_;
  const mhd_param* params_;
  std::size_t count_;
};

}  // namespace mhd::sdk

#endif  // MHD_PLUGIN_SDK_PARAMS_HPP
