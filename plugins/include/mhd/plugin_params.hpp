// MHD plugin SDK, parameters: declaring a plugin's parameters (mhd_param_decl, ABI 3) and
// checking a scene's <param>s against them. Header-only C++20 over mhd/plugin_abi.h, used
// by every in-tree plugin and by the host, so `mhd validate` and a plugin's open() apply
// one parser with one set of rules:
//   numbers are C-locale decimals (std::from_chars), finite, with optional blanks around;
//   integers are non-negative decimals; vectors are three numbers separated by blanks;
//   quaternions four ("w x y z", non-zero norm); choices one of the declared words;
//   booleans "true" or "false"; text is non-empty.
// A plugin declares its table of parameters as a constexpr array:
//   constexpr std::array kParams{
//       mhd::sdk::number("rate_hz", "Hz", "120", "samples per second", mhd::sdk::positive()),
//       mhd::sdk::choice("hand_model", "kinematic|impedance", "kinematic", "how the hand moves")};
#ifndef MHD_PLUGIN_PARAMS_HPP
#define MHD_PLUGIN_PARAMS_HPP

#include <mhd/plugin_abi.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mhd::sdk {

/// A range of a number, an integer or each component of a vector.
struct Range {
  std::uint32_t flags = 0;
  double min_value = 0.0;
  double max_value = 0.0;
};

constexpr Range any() { return {}; }
constexpr Range positive() { return {MHD_PARAM_HAS_MIN | MHD_PARAM_MIN_EXCLUSIVE, 0.0, 0.0}; }  ///< > 0
constexpr Range non_negative() { return {MHD_PARAM_HAS_MIN, 0.0, 0.0}; }                          ///< >= 0
constexpr Range at_least(double min) { return {MHD_PARAM_HAS_MIN, min, 0.0}; }
constexpr Range between(double min, double max) { return {MHD_PARAM_HAS_MIN | MHD_PARAM_HAS_MAX, min, max}; }
/// In [0, 1).
constexpr Range fraction() { return {MHD_PARAM_HAS_MIN | MHD_PARAM_HAS_MAX | MHD_PARAM_MAX_EXCLUSIVE, 0.0, 1.0}; }
/// In (min, max].
constexpr Range above_up_to(double min, double max) {
  return {MHD_PARAM_HAS_MIN | MHD_PARAM_MIN_EXCLUSIVE | MHD_PARAM_HAS_MAX, min, max};
}

/// default_value NULL: the parameter has no default (absent means "not used").
constexpr mhd_param_decl number(const char* name, const char* unit, const char* default_value, const char* doc,
                                Range range = {}) {
  return {name, MHD_PARAM_NUMBER, unit, range.flags, range.min_value, range.max_value, nullptr, default_value, doc};
}
constexpr mhd_param_decl integer(const char* name, const char* unit, const char* default_value, const char* doc,
                                 Range range = {}) {
  return {name, MHD_PARAM_INTEGER, unit, range.flags, range.min_value, range.max_value, nullptr, default_value, doc};
}
constexpr mhd_param_decl vector3(const char* name, const char* unit, const char* default_value, const char* doc,
                                 Range range = {}) {
  return {name, MHD_PARAM_VECTOR3, unit, range.flags, range.min_value, range.max_value, nullptr, default_value, doc};
}
constexpr mhd_param_decl quaternion(const char* name, const char* default_value, const char* doc) {
  return {name, MHD_PARAM_QUATERNION, "", 0u, 0.0, 0.0, nullptr, default_value, doc};
}
constexpr mhd_param_decl text(const char* name, const char* default_value, const char* doc) {
  return {name, MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, default_value, doc};
}
/// A text the scene must give.
constexpr mhd_param_decl required_text(const char* name, const char* doc) {
  return {name, MHD_PARAM_TEXT, "", MHD_PARAM_REQUIRED, 0.0, 0.0, nullptr, nullptr, doc};
}
/// choices: words separated by '|'.
constexpr mhd_param_decl choice(const char* name, const char* choices, const char* default_value, const char* doc) {
  return {name, MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, choices, default_value, doc};
}
constexpr mhd_param_decl boolean(const char* name, const char* default_value, const char* doc) {
  return {name, MHD_PARAM_BOOL, "", 0u, 0.0, 0.0, nullptr, default_value, doc};
}

/// Two declaration tables as one (e.g. a shared block of parameters and a plugin's own).
template <std::size_t N, std::size_t M>
constexpr std::array<mhd_param_decl, N + M> join(const std::array<mhd_param_decl, N>& a,
                                                 const std::array<mhd_param_decl, M>& b) {
  std::array<mhd_param_decl, N + M> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
  for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
  return out;
}

namespace detail {

inline std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

inline std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// Blank-separated numbers; nothing when a word is not a number.
inline std::optional<std::vector<double>> parse_numbers(std::string_view text) {
  std::vector<double> values;
  text = trim(text);
  while (!text.empty()) {
    const std::size_t end = text.find_first_of(" \t");
    const std::optional<double> v = parse_number(text.substr(0, end));
    if (!v) return std::nullopt;
    values.push_back(*v);
    text = end == std::string_view::npos ? std::string_view{} : trim(text.substr(end));
  }
  return values;
}

inline std::string format_number(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), v);
  return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

inline bool in_range(const mhd_param_decl& d, double v) {
  if ((d.flags & MHD_PARAM_HAS_MIN) != 0u) {
    if ((d.flags & MHD_PARAM_MIN_EXCLUSIVE) != 0u ? !(v > d.min_value) : !(v >= d.min_value)) return false;
  }
  if ((d.flags & MHD_PARAM_HAS_MAX) != 0u) {
    if ((d.flags & MHD_PARAM_MAX_EXCLUSIVE) != 0u ? !(v < d.max_value) : !(v <= d.max_value)) return false;
  }
  return true;
}

inline bool is_choice(const mhd_param_decl& d, std::string_view word) {
  std::string_view choices = d.choices != nullptr ? d.choices : "";
  while (true) {
    const std::size_t bar = choices.find('|');
    if (choices.substr(0, bar) == word && !word.empty()) return true;
    if (bar == std::string_view::npos) return false;
    choices.remove_prefix(bar + 1);
  }
}

}  // namespace detail

/// The range in words: "> 0", "in [0, 1]", "" for none.
inline std::string range_text(const mhd_param_decl& d) {
  const bool has_min = (d.flags & MHD_PARAM_HAS_MIN) != 0u;
  const bool has_max = (d.flags & MHD_PARAM_HAS_MAX) != 0u;
  const bool open_min = (d.flags & MHD_PARAM_MIN_EXCLUSIVE) != 0u;
  const bool open_max = (d.flags & MHD_PARAM_MAX_EXCLUSIVE) != 0u;
  const std::string lo = detail::format_number(d.min_value);
  const std::string hi = detail::format_number(d.max_value);
  if (has_min && has_max) return std::string("in ") + (open_min ? "(" : "[") + lo + ", " + hi + (open_max ? ")" : "]");
  if (has_min) return std::string(open_min ? "> " : ">= ") + lo;
  if (has_max) return std::string(open_max ? "< " : "<= ") + hi;
  return {};
}

/// What a valid value of `d` looks like: "a number > 0 (s)", "one of kinematic|impedance".
inline std::string expected_text(const mhd_param_decl& d) {
  const std::string range = range_text(d);
  const std::string unit = d.unit != nullptr && d.unit[0] != '\0' ? std::string(" (") + d.unit + ")" : std::string();
  const std::string ranged = range.empty() ? std::string() : " " + range;
  switch (d.type) {
    case MHD_PARAM_NUMBER: return "a number" + ranged + unit;
    case MHD_PARAM_INTEGER: return "a non-negative integer" + ranged + unit;
    case MHD_PARAM_VECTOR3: return "three numbers 'x y z'" + (range.empty() ? std::string() : ", each" + ranged) + unit;
    case MHD_PARAM_QUATERNION: return "four numbers 'w x y z' of non-zero norm";
    case MHD_PARAM_CHOICE: return std::string("one of ") + (d.choices != nullptr ? d.choices : "");
    case MHD_PARAM_BOOL: return "true or false";
    case MHD_PARAM_TEXT: return "a non-empty text";
  }
  return "a value of an unknown type";
}

/// Whether `value` is valid for `d`: nothing when it is, else
/// "parameter 'rate_hz' must be a number > 0 (Hz), got 'abc'".
inline std::optional<std::string> check_value(const mhd_param_decl& d, std::string_view value) {
  bool ok = false;
  switch (d.type) {
    case MHD_PARAM_NUMBER: {
      const std::optional<double> v = detail::parse_number(value);
      ok = v && detail::in_range(d, *v);
      break;
    }
    case MHD_PARAM_INTEGER: {
      const std::string_view t = detail::trim(value);
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
      ok = !t.empty() && ec == std::errc{} && end == t.data() + t.size() &&
           detail::in_range(d, static_cast<double>(v));
      break;
    }
    case MHD_PARAM_VECTOR3:
    case MHD_PARAM_QUATERNION: {
      const std::size_t count = d.type == MHD_PARAM_VECTOR3 ? 3 : 4;
      const std::optional<std::vector<double>> v = detail::parse_numbers(value);
      ok = v && v->size() == count;
      if (ok && d.type == MHD_PARAM_VECTOR3) {
        for (double x : *v) ok = ok && detail::in_range(d, x);
      }
      if (ok && d.type == MHD_PARAM_QUATERNION) {
        double n2 = 0.0;
        for (double x : *v) n2 += x * x;
        ok = n2 > 1e-12;
      }
      break;
    }
    case MHD_PARAM_CHOICE: ok = detail::is_choice(d, detail::trim(value)); break;
    case MHD_PARAM_BOOL: ok = detail::trim(value) == "true" || detail::trim(value) == "false"; break;
    case MHD_PARAM_TEXT: ok = !detail::trim(value).empty(); break;
  }
  if (ok) return std::nullopt;
  return "parameter '" + std::string(d.name != nullptr ? d.name : "") + "' must be " + expected_text(d) + ", got '" +
         std::string(value) + "'";
}

/// Whether a plugin's table of declarations is usable: nothing when it is, else why
/// ("declaration 2 has no name"). Names unique and non-empty, known types, docs present,
/// choices declared for a choice, every default valid for its own declaration.
inline std::optional<std::string> check_declarations(const mhd_param_decl* decls, std::size_t count) {
  if (decls == nullptr && count != 0) return "params is NULL but param_count is " + std::to_string(count);
  for (std::size_t i = 0; i < count; ++i) {
    const mhd_param_decl& d = decls[i];
    const std::string at = "parameter declaration " + std::to_string(i);
    if (d.name == nullptr || d.name[0] == '\0') return at + " has no name";
    if (d.type < MHD_PARAM_NUMBER || d.type > MHD_PARAM_BOOL) return at + " ('" + d.name + "') has an unknown type";
    if (d.doc == nullptr || d.doc[0] == '\0') return at + " ('" + d.name + "') has no doc";
    if (d.type == MHD_PARAM_CHOICE && (d.choices == nullptr || d.choices[0] == '\0')) {
      return at + " ('" + d.name + "') is a choice with no choices";
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (std::strcmp(decls[j].name, d.name) == 0) return at + " repeats the name '" + d.name + "'";
    }
    if (d.default_value != nullptr) {
      if (auto problem = check_value(d, d.default_value)) return at + ": its default is invalid: " + *problem;
    }
  }
  return std::nullopt;
}

/// The declaration named `name`, or NULL.
inline const mhd_param_decl* find_declaration(const mhd_param_decl* decls, std::size_t count, std::string_view name) {
  for (std::size_t i = 0; i < count; ++i) {
    if (decls[i].name != nullptr && name == decls[i].name) return &decls[i];
  }
  return nullptr;
}

/// Every problem of `params` against the declarations, in the order given, then the
/// required parameters that are missing: unknown names ("unknown parameter 'x' (known:
/// a, b)"), names given twice, invalid values. Empty when open() may be called.
inline std::vector<std::string> check_params(const mhd_param_decl* decls, std::size_t decl_count,
                                             const mhd_param* params, std::size_t param_count) {
  std::vector<std::string> problems;
  if (params == nullptr && param_count != 0) {
    problems.emplace_back("parameter array is NULL but its count is not zero");
    return problems;
  }
  for (std::size_t i = 0; i < param_count; ++i) {
    if (params[i].name == nullptr || params[i].value == nullptr) {
      problems.push_back("parameter " + std::to_string(i) + " has a NULL name or value");
      continue;
    }
    bool repeated = false;
    for (std::size_t j = 0; j < i; ++j) {
      repeated = repeated || (params[j].name != nullptr && std::strcmp(params[j].name, params[i].name) == 0);
    }
    if (repeated) {
      problems.push_back("parameter '" + std::string(params[i].name) + "' is given twice");
      continue;
    }
    const mhd_param_decl* d = find_declaration(decls, decl_count, params[i].name);
    if (d == nullptr) {
      std::string known;
      for (std::size_t k = 0; k < decl_count; ++k) known += (k == 0 ? "" : ", ") + std::string(decls[k].name);
      problems.push_back("unknown parameter '" + std::string(params[i].name) + "' (known: " +
                         (known.empty() ? std::string("none") : known) + ")");
      continue;
    }
    if (auto problem = check_value(*d, params[i].value)) problems.push_back(*problem);
  }
  for (std::size_t k = 0; k < decl_count; ++k) {
    if ((decls[k].flags & MHD_PARAM_REQUIRED) == 0u) continue;
    bool given = false;
    for (std::size_t i = 0; i < param_count; ++i) {
      given = given || (params[i].name != nullptr && std::strcmp(params[i].name, decls[k].name) == 0);
    }
    if (!given) problems.push_back("parameter '" + std::string(decls[k].name) + "' is required");
  }
  return problems;
}

/// One line for `mhd plugins --describe`: "rate_hz  number > 0 (Hz), default 120: doc".
inline std::string describe(const mhd_param_decl& d) {
  std::string line = std::string(d.name) + "  " + expected_text(d);
  if ((d.flags & MHD_PARAM_REQUIRED) != 0u) {
    line += ", required";
  } else if (d.default_value != nullptr) {
    line += ", default '" + std::string(d.default_value) + "'";
  } else {
    line += ", optional";
  }
  return line + ": " + (d.doc != nullptr ? d.doc : "");
}

}  // namespace mhd::sdk

#endif  // MHD_PLUGIN_PARAMS_HPP
