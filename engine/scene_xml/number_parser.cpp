#include "scene_xml/number_parser.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace mhd::scene_xml {
namespace {

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// from_chars takes no '+'; XML Schema numbers may have one.
std::string_view strip_plus(std::string_view token) {
  if (token.size() >= 2 && token.front() == '+' && token[1] != '+' && token[1] != '-') {
    token.remove_prefix(1);
  }
  return token;
}

}  // namespace

std::string_view trim_xml_space(std::string_view text) {
  while (!text.empty() && is_xml_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_xml_space(text.back())) text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> split_xml_space(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_xml_space(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !is_xml_space(text[i])) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

ParsedDouble parse_double(std::string_view token) {
  token = strip_plus(trim_xml_space(token));
  ParsedDouble out;
  if (token.empty()) return out;
  const char* last = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), last, out.value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    out.status = NumberStatus::OutOfRange;
  } else if (ec != std::errc{} || ptr != last) {
    out.status = NumberStatus::Invalid;
  } else if (!std::isfinite(out.value)) {
    out.status = NumberStatus::NonFinite;
  } else {
    out.status = NumberStatus::Ok;
  }
  return out;
}

ParsedInteger parse_integer(std::string_view token) {
  token = strip_plus(trim_xml_space(token));
  ParsedInteger out;
  if (token.empty()) return out;
  const char* last = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), last, out.value, 10);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    out.status = NumberStatus::OutOfRange;
  } else if (ec != std::errc{} || ptr != last) {
    out.status = NumberStatus::Invalid;
  } else {
    out.status = NumberStatus::Ok;
  }
  return out;
}

}  // namespace mhd::scene_xml
