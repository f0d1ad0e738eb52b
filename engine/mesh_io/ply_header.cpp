#include "mesh_io/ply_header.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <string>
#include <vector>

namespace mhd {
namespace {

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

enum class PlyFormat { Ascii, Binary };

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;  ///< the least one element can take in the file
  std::vector<std::string> properties;
};

/// Bytes of a PLY scalar type (0 for an unknown name).
std::uint64_t type_bytes(std::string_view type) {
  static constexpr std::pair<std::string_view, std::uint64_t> kTypes[] = {
      {"char", 1},   {"uchar", 1},  {"int8", 1},  {"uint8", 1},    {"short", 2},  {"ushort", 2},
      {"int16", 2},  {"uint16", 2}, {"int", 4},   {"uint", 4},     {"int32", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  for (const auto& [name, bytes] : kTypes) {
    if (name == type) return bytes;
  }
  return 0;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) { return a > kMax - b ? kMax : a + b; }
std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) { return b != 0 && a > kMax / b ? kMax : a * b; }

MeshHeaderCheck failure(std::string message) { return message; }

/// "100000000 vertex and 100000000 face" (every element with a non-zero count).
std::string describe_counts(const std::vector<Element>& elements) {
  std::vector<std::string> parts;
  for (const Element& e : elements) {
    if (e.count > 0) parts.push_back(fmt::format("{} {}", e.count, e.name));
  }
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) text += i + 1 == parts.size() ? " and " : ", ";
    text += parts[i];
  }
  return text;
}

}  // namespace

bool has_ply_magic(std::string_view head) {
  return head.starts_with("ply\n") || head.starts_with("ply\r\n") || head.starts_with("ply \n") ||
         head.starts_with("ply \r\n");
}

MeshHeaderCheck check_ply_header(std::string_view head, std::uint64_t file_size) {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<Element> elements;
  std::size_t pos = 0;
  std::optional<std::size_t> body_start;
  while (pos < head.size()) {
    const std::size_t end = head.find('\n', pos);
    if (end == std::string_view::npos) break;  // an unfinished line: the header runs on
    std::string_view line = head.substr(pos, end - pos);
    pos = end + 1;
    if (line.ends_with('\r')) line.remove_suffix(1);
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty()) continue;
    if (words[0] == "end_header") {
      body_start = pos;
      break;
    }
    if (words[0] == "format" && words.size() >= 2) {
      if (words[1] == "ascii") {
        format = PlyFormat::Ascii;
      } else if (words[1] == "binary_little_endian" || words[1] == "binary_big_endian") {
        format = PlyFormat::Binary;
      } else {
        return failure(fmt::format("PLY header: unknown format '{}'", words[1]));
      }
    } else if (words[0] == "element" && words.size() >= 3) {
      Element e;
      e.name = std::string(words[1]);
      const std::string_view count = words[2];
      const auto [ptr, ec] = std::from_chars(count.data(), count.data() + count.size(), e.count);
      if (ec != std::errc() || ptr != count.data() + count.size()) {
        return failure(fmt::format("PLY header: invalid count '{}' for element '{}'", count, words[1]));
      }
      elements.push_back(std::move(e));
    } else if (words[0] == "property") {
      // "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME", known types
      // only: assimp 5.2 aborts on some malformed property lines instead of failing.
      const bool list = words.size() >= 2 && words[1] == "list";
      const bool well_formed = list ? words.size() == 5 && type_bytes(words[2]) > 0 && type_bytes(words[3]) > 0
                                    : words.size() == 3 && type_bytes(words[1]) > 0;
      if (!well_formed || elements.empty()) {
        return failure(fmt::format("PLY header: malformed property line '{}'", line));
      }
      // A list takes at least its count; a scalar its size (binary) or a number (ASCII).
      const std::uint64_t bytes = format == PlyFormat::Ascii ? 2 : type_bytes(words[list ? 2 : 1]);
      elements.back().min_bytes = saturating_add(elements.back().min_bytes, bytes);
      elements.back().properties.emplace_back(words.back());
    }
    // comment, obj_info and unknown lines say nothing about sizes.
  }
  if (!body_start) {
    return failure(head.size() < file_size
                       ? fmt::format("PLY header: no end_header in the first {} bytes", head.size())
                       : std::string("PLY header: no end_header"));
  }
  std::uint64_t needed = 0;
  MeshHeaderClaims check;
  for (const Element& e : elements) {
    if (e.name != "vertex") continue;
    for (const char* axis : {"x", "y", "z"}) {
      if (std::find(e.properties.begin(), e.properties.end(), axis) == e.properties.end()) {
        return failure(fmt::format("PLY header: element 'vertex' has no property '{}'", axis));
      }
    }
  }
  for (Element& e : elements) {
    e.min_bytes = std::max<std::uint64_t>(e.min_bytes, 1);  // an element is at least a byte (or a line end)
    needed = saturating_add(needed, saturating_mul(e.count, e.min_bytes));
    if (e.name == "face") check.claimed_faces = e.count;
  }
  const std::uint64_t body_bytes = file_size - std::min<std::uint64_t>(file_size, *body_start);
  if (needed > body_bytes) {
    return failure(fmt::format("PLY header claims {} elements, at least {} bytes of {} data, but only {} bytes "
                               "follow the header",
                               describe_counts(elements), needed == kMax ? std::string("2^64") : std::to_string(needed),
                               format == PlyFormat::Ascii ? "ASCII" : "binary", body_bytes));
  }
  return check;
}

}  // namespace mhd
