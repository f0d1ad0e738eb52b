#include "scene_xml/readable_file.h"

#include <array>
#include <fstream>
#include <system_error>

namespace mhd::scene_xml {

FileProblem check_readable_file(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) return FileProblem::NotFound;
  if (!std::filesystem::is_regular_file(status)) return FileProblem::NotRegularFile;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) return FileProblem::NotReadable;
  return FileProblem::None;
}

std::string_view describe(FileProblem problem) {
  switch (problem) {
    case FileProblem::None: return "";
    case FileProblem::NotFound: return "not found";
    case FileProblem::NotRegularFile: return "is not a regular file";
    case FileProblem::NotReadable: return "is not readable";
  }
  return "";
}

std::optional<std::string> read_whole_file(const std::filesystem::path& path, FileProblem& problem) {
  problem = check_readable_file(path);
  if (problem != FileProblem::None) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string bytes;
  std::array<char, 16384> buffer{};
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
    bytes.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) {
    problem = FileProblem::NotReadable;
    return std::nullopt;
  }
  return bytes;
}

}  // namespace mhd::scene_xml
