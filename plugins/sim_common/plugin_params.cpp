#include "sim_common/plugin_params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace mhd::plugin_support {
namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_view(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

[[noreturn]] void fail(const char* name, const char* what, const std::string& value) {
  throw ParamError("parameter '" + std::string(name) + "' must be " + what + ", got '" + value + "'");
}

}  // namespace

ParamReader::ParamReader(std::span<const mhd_param_decl> decls, const mhd_param* params, std::size_t count)
    : decls_(decls) {
  const std::vector<std::string> problems = sdk::check_params(decls.data(), decls.size(), params, count);
  if (!problems.empty()) {
    std::string message = problems.front();
    if (message.size() >= MHD_ERROR_MESSAGE_SIZE) message = message.substr(0, MHD_ERROR_MESSAGE_SIZE - 5) + "...)";
    throw ParamError(message);
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (params[i].name == nullptr || params[i].value == nullptr) {
      throw ParamError("parameter " + std::to_string(i) + " has a NULL name or value");
    }
    const std::string name = params[i].name;
    const bool seen = std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
    if (seen) throw ParamError("parameter '" + name + "' is given twice");
    entries_.push_back({name, params[i].value});
  }
}

const std::string* ParamReader::find(const char* name) {
  if (sdk::find_declaration(decls_.data(), decls_.size(), name) == nullptr) {
    throw std::logic_error("the plugin reads parameter '" + std::string(name) + "', which it does not declare");
  }
  if (std::find(known_.begin(), known_.end(), name) == known_.end()) known_.emplace_back(name);
  for (const Entry& e : entries_) {
    if (e.name == name) return &e.value;
  }
  return nullptr;
}

std::optional<double> ParamReader::optional_number(const char* name) {
  const std::string* value = find(name);
  if (value == nullptr) return std::nullopt;
  const auto v = parse_view(*value);
  if (!v) fail(name, "a number", *value);
  return v;
}

double ParamReader::number(const char* name, double fallback) { return optional_number(name).value_or(fallback); }

double ParamReader::positive(const char* name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const auto v = parse_view(*value);
  if (!v || !(*v > 0.0)) fail(name, "a positive number", *value);
  return *v;
}

double ParamReader::non_negative(const char* name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const auto v = parse_view(*value);
  if (!v || !(*v >= 0.0)) fail(name, "a non-negative number", *value);
  return *v;
}

double ParamReader::fraction(const char* name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const auto v = parse_view(*value);
  if (!v || !(*v >= 0.0 && *v < 1.0)) fail(name, "a number in [0, 1)", *value);
  return *v;
}

std::uint64_t ParamReader::unsigned_integer(const char* name, std::uint64_t fallback, std::uint64_t max_value) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const std::string_view text = trim(*value);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || v > max_value) {
    fail(name, ("an integer from 0 to " + std::to_string(max_value)).c_str(), *value);
  }
  return v;
}

std::optional<std::vector<double>> ParamReader::numbers(const char* name, std::size_t count, const char* what) {
  const std::string* value = find(name);
  if (value == nullptr) return std::nullopt;
  std::vector<double> v;
  std::string_view rest = trim(*value);
  while (!rest.empty() && v.size() <= count) {
    const std::size_t end = std::min(rest.find_first_of(" \t"), rest.size());
    const auto x = parse_view(rest.substr(0, end));
    if (!x) fail(name, what, *value);
    v.push_back(*x);
    rest = trim(rest.substr(end));
  }
  if (v.size() != count) fail(name, what, *value);
  return v;
}

std::optional<Eigen::Vector3d> ParamReader::optional_vector3(const char* name) {
  const auto v = numbers(name, 3, "three numbers 'x y z'");
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

Eigen::Vector3d ParamReader::vector3(const char* name, const Eigen::Vector3d& fallback) {
  return optional_vector3(name).value_or(fallback);
}

std::optional<Eigen::Quaterniond> ParamReader::optional_quaternion(const char* name) {
  const char* what = "a quaternion 'w x y z' of non-zero norm";
  const auto v = numbers(name, 4, what);
  if (!v) return std::nullopt;
  Eigen::Quaterniond q((*v)[0], (*v)[1], (*v)[2], (*v)[3]);
  if (!(q.norm() > 0.0)) fail(name, what, *find(name));
  return q.normalized();
}

std::string ParamReader::required_text(const char* name) {
  const std::string* value = find(name);
  if (value == nullptr) throw ParamError("missing parameter '" + std::string(name) + "'");
  if (value->empty()) fail(name, "a non-empty string", *value);
  return *value;
}

bool ParamReader::given(const char* name) { return find(name) != nullptr; }

std::optional<std::string> ParamReader::optional_text(const char* name) {
  if (find(name) == nullptr) return std::nullopt;
  return required_text(name);
}

void ParamReader::reject_unknown() const {
  for (const Entry& e : entries_) {
    if (std::find(known_.begin(), known_.end(), e.name) != known_.end()) continue;
    // The known names, as many as fit in an mhd_error message.
    constexpr std::size_t kLimit = MHD_ERROR_MESSAGE_SIZE - 1;
    const std::string head = "unknown parameter '" + e.name + "' (known: ";
    std::string list;
    for (std::size_t i = 0; i < known_.size(); ++i) {
      const std::string next = (i == 0 ? "" : ", ") + known_[i];
      const bool last = i + 1 == known_.size();
      if (head.size() + list.size() + next.size() + (last ? 1 : 6) > kLimit) {
        list += ", ...";
        break;
      }
      list += next;
    }
    throw ParamError(head + list + ")");
  }
}

}  // namespace mhd::plugin_support
