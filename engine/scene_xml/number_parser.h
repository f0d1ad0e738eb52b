#pragma once
// Text to numbers for scene attributes. A number must use the whole token
// ("1.5abc" is not 1.5); surrounding XML white space is allowed, as XML Schema allows.

#include <string_view>
#include <vector>

namespace mhd::scene_xml {

enum class NumberStatus { Ok, Invalid, NonFinite, OutOfRange };

struct ParsedDouble {
  double value = 0.0;
  NumberStatus status = NumberStatus::Invalid;
};

struct ParsedInteger {
  long long value = 0;
  NumberStatus status = NumberStatus::Invalid;
};

/// Strips XML white space (space, tab, CR, LF) from both ends.
[[nodiscard]] std::string_view trim_xml_space(std::string_view text);

/// Splits on runs of XML white space; no empty tokens.
[[nodiscard]] std::vector<std::string_view> split_xml_space(std::string_view text);

/// Decimal floating point (std::from_chars, general format), optionally with one
/// leading '+'. "nan" and "inf" parse but come back NonFinite; overflow is OutOfRange.
[[nodiscard]] ParsedDouble parse_double(std::string_view token);

/// Decimal integer, optionally with one leading '+'.
[[nodiscard]] ParsedInteger parse_integer(std::string_view token);

}  // namespace mhd::scene_xml
