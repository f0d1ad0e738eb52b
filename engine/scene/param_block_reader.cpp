#include "scene/param_block_reader.h"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <utility>

namespace mhd {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool parse_double(std::string_view text, double& out) {
  text = trim(text);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

}  // namespace

ParamBlockReader::ParamBlockReader(const ParamBlock* block, std::string element)
    : block_(block), element_(std::move(element)) {}

const std::string* ParamBlockReader::find(std::string_view name) {
  known_.emplace(name);
  if (block_ == nullptr) return nullptr;
  const auto it = block_->params.find(std::string(name));
  return it == block_->params.end() ? nullptr : &it->second;
}

bool ParamBlockReader::has(std::string_view name) { return find(name) != nullptr; }

SourceLocation ParamBlockReader::where(std::string_view name) const {
  if (block_ == nullptr) return {};
  const auto it = block_->param_where.find(std::string(name));
  return it == block_->param_where.end() ? block_->where : it->second;
}

void ParamBlockReader::error(std::string_view name, const std::string& message) {
  diagnostics_.push_back({where(name), message});
}

double ParamBlockReader::number(std::string_view name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  double out = 0.0;
  if (!parse_double(*value, out)) {
    error(name, "param '" + std::string(name) + "' in " + element_ + " must be a finite number, got '" + *value + "'");
    return fallback;
  }
  return out;
}

double ParamBlockReader::positive(std::string_view name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  double out = 0.0;
  if (!parse_double(*value, out) || out <= 0.0) {
    error(name, "param '" + std::string(name) + "' in " + element_ + " must be a positive number, got '" + *value + "'");
    return fallback;
  }
  return out;
}

double ParamBlockReader::within(std::string_view name, double fallback, double low, double high,
                                std::string_view unit) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  double out = 0.0;
  if (!parse_double(*value, out) || !(out >= low && out <= high)) {
    error(name, fmt::format("param '{}' in {} must be a number in [{:g}, {:g}]{}{}, got '{}'", name, element_, low, high,
                            unit.empty() ? "" : " ", unit, *value));
    return fallback;
  }
  return out;
}

double ParamBlockReader::non_negative(std::string_view name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  double out = 0.0;
  if (!parse_double(*value, out) || out < 0.0) {
    error(name, "param '" + std::string(name) + "' in " + element_ + " must be a non-negative number, got '" + *value + "'");
    return fallback;
  }
  return out;
}

double ParamBlockReader::fraction(std::string_view name, double fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  double out = 0.0;
  if (!parse_double(*value, out) || out < 0.0 || out > 1.0) {
    error(name, "param '" + std::string(name) + "' in " + element_ + " must be a number in [0, 1], got '" + *value + "'");
    return fallback;
  }
  return out;
}

std::uint64_t ParamBlockReader::unsigned_integer(std::string_view name, std::uint64_t fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const std::string_view text = trim(*value);
  std::uint64_t out = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    error(name, "param '" + std::string(name) + "' in " + element_ + " must be a non-negative integer, got '" + *value + "'");
    return fallback;
  }
  return out;
}

bool ParamBlockReader::boolean(std::string_view name, bool fallback) {
  const std::string* value = find(name);
  if (value == nullptr) return fallback;
  const std::string_view text = trim(*value);
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  error(name, "param '" + std::string(name) + "' in " + element_ + " must be true or false, got '" + *value + "'");
  return fallback;
}

std::string ParamBlockReader::text(std::string_view name, const std::string& fallback) {
  const std::string* value = find(name);
  return value == nullptr ? fallback : *value;
}

Diagnostics ParamBlockReader::finish() {
  if (block_ != nullptr) {
    for (const auto& [name, value] : block_->params) {
      if (known_.count(name) != 0) continue;
      std::string known_list;
      for (const auto& k : known_) known_list += (known_list.empty() ? "" : ", ") + k;
      error(name, "unknown param '" + name + "' in " + element_ + " (known: " + known_list + ")");
    }
  }
  return diagnostics_;
}

}  // namespace mhd
