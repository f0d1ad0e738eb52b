#include "output_path_check.h"

#include <fmt/core.h>

#include <system_error>
#include <variant>

namespace mhd::cli {

std::optional<std::string> output_path_problem(const std::filesystem::path& output,
                                               const std::vector<std::filesystem::path>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(output, ec);
  if (ec || !fs::exists(status)) return std::nullopt;  // a new file
  if (!fs::is_regular_file(status)) {
    return fmt::format("'{}' is not a regular file (a device, a FIFO or a folder); outputs are written only as new "
                       "files or over regular files",
                       output.string());
  }
  for (const fs::path& input : inputs) {
    if (fs::equivalent(output, input, ec) && !ec) {
      return fmt::format("'{}' is '{}', which this command reads; choose another output file", output.string(),
                         input.string());
    }
  }
  return std::nullopt;
}

std::vector<std::filesystem::path> scene_inputs(const SceneDescription& scene) {
  std::vector<std::filesystem::path> inputs{scene.file};
  for (const ObjectDescription& object : scene.objects) {
    if (const auto* mesh = std::get_if<MeshSource>(&object.shape)) inputs.push_back(mesh->file);
  }
  return inputs;
}

}  // namespace mhd::cli
