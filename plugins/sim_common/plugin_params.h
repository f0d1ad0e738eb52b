#pragma once
// Reading a plugin's <param> strings for open(): first checked against the plugin's
// declarations (mhd/plugin_params.hpp, the parser the host's `mhd validate` applies too),
// then read typed; a parameter the plugin never declared is an error, and so is a getter
// asking for an undeclared name (a plugin bug, caught by the plugin's tests). The messages are the ones open()
// returns, e.g. "parameter 'rate_hz' must be a positive number, got 'abc'".

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::plugin_support {

class ParamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Each getter marks its parameter as known and returns the fallback when it is absent.
/// Numbers are C-locale decimals (std::from_chars), finite, with optional surrounding
/// blanks. Every getter throws ParamError with the message open() returns.
class ParamReader {
 public:
  /// Throws ParamError with the first problem sdk::check_params finds (a NULL array with
  /// a non-zero count, a NULL name or value, a name given twice, an unknown name, a value
  /// its declaration refuses, a required parameter missing). `decls` must outlive this.
  ParamReader(std::span<const mhd_param_decl> decls, const mhd_param* params, std::size_t count);

  [[nodiscard]] std::optional<double> optional_number(const char* name);
  [[nodiscard]] double number(const char* name, double fallback);
  [[nodiscard]] double positive(const char* name, double fallback);      ///< > 0
  [[nodiscard]] double non_negative(const char* name, double fallback);  ///< >= 0
  [[nodiscard]] double fraction(const char* name, double fallback);      ///< in [0, 1)
  /// A non-negative integer no larger than max_value.
  [[nodiscard]] std::uint64_t unsigned_integer(const char* name, std::uint64_t fallback, std::uint64_t max_value);
  /// Three numbers separated by blanks: "x y z".
  [[nodiscard]] std::optional<Eigen::Vector3d> optional_vector3(const char* name);
  [[nodiscard]] Eigen::Vector3d vector3(const char* name, const Eigen::Vector3d& fallback);
  /// Four numbers "w x y z" of non-zero norm; returned normalised.
  [[nodiscard]] std::optional<Eigen::Quaterniond> optional_quaternion(const char* name);
  /// A non-empty string.
  [[nodiscard]] std::string required_text(const char* name);
  /// Whether the scene gives `name` (marks it as known).
  [[nodiscard]] bool given(const char* name);
  /// A non-empty string, when given.
  [[nodiscard]] std::optional<std::string> optional_text(const char* name);

  /// Throws ParamError "unknown parameter 'x' (known: a, b)" for the first parameter
  /// (in the order given) that no getter asked for. Call after every getter.
  void reject_unknown() const;

 private:
  struct Entry {
    std::string name;
    std::string value;
  };
  /// Remembers `name` as known; the value when given.
  const std::string* find(const char* name);
  /// `count` blank-separated finite numbers; `what` names the form in the error.
  std::optional<std::vector<double>> numbers(const char* name, std::size_t count, const char* what);

  std::span<const mhd_param_decl> decls_;
  std::vector<Entry> entries_;
  std::vector<std::string> known_;
};

}  // namespace mhd::plugin_support
