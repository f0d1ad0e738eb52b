#pragma once
// Whether a path names a regular file this process can read, and reading one whole;
// neither ever opens (and so blocks on) a FIFO or device.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace mhd::scene_xml {

enum class FileProblem { None, NotFound, SymlinkLoop, NotRegularFile, NotReadable };

[[nodiscard]] FileProblem check_readable_file(const std::filesystem::path& path);

/// "not found", "is a symlink loop", "is not a regular file", "is not readable" (empty
/// for None).
[[nodiscard]] std::string_view describe(FileProblem problem);

/// The file's bytes, or nullopt with `problem` set.
[[nodiscard]] std::optional<std::string> read_whole_file(const std::filesystem::path& path,
                                                         FileProblem& problem);

}  // namespace mhd::scene_xml
