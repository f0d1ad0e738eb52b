#pragma once
// A mesh file read by assimp in a child process. assimp's readers can crash (a COLLADA
// file with a misspelt attribute segfaults) or loop for ever on a corrupt file, and
// neither can be caught or bounded in the process that runs them. The child streams the
// triangles back through a pipe as assimp holds them; the parent ends a child that
// crashes, runs past its time limit or allocates past its memory limit, and says so. Where no child can start (fork refused
// under strict overcommit, or by a process limit), the same records are taken in this
// process: the load still works, and says it was not contained.

#include "diagnostics/result.h"
#include "geometry/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace mhd {

/// How long a read may take: base_s plus seconds_per_mib for each MiB of the file (a
/// 100 M-triangle PLY of 1.9 GB read in 30 s; text formats and sanitizer builds are
/// slower). Past it the child is killed.
/// And the memory it may take beyond what the process held: memory_base_bytes plus
/// memory_per_file_byte for each byte of the files it opens (the mesh file and side files
/// such as a glTF's .bin), at most the memory available when it starts (ReadMemoryLimit).
/// assimp took 75 (binary PLY), 180 (binary STL) and 320 (OBJ) bytes a triangle at 1 M
/// triangles, 4 to 27 times the file. An allocation past it ends the read.
struct MeshReadLimits {
  double base_s = 30.0;
  double seconds_per_mib = 1.0;
  std::uint64_t memory_base_bytes = std::uint64_t{1} << 30;
  double memory_per_file_byte = 256.0;
};

/// What assimp read, before MHD's clean-up.
struct AssimpRead {
  /// Every triangle of every triangle mesh in the file (points and lines left out),
  /// vertices as assimp's floats; a corner past its own mesh's vertices is UINT32_MAX.
  TriangleMesh mesh;
  /// Faces that are not triangles (points, lines).
  std::size_t dropped = 0;
  /// Corners not shared: several triangle meshes, or more vertices than faces.
  bool unshared = false;
  /// Empty when the child process read the file; else why none could start, e.g.
  /// "cannot start a process for the reader: Cannot allocate memory". The file was then
  /// read in this process, with no limit on its time or memory.
  std::string unisolated_read;
};

/// Reads `file` with assimp (positions only; triangulated, scene-graph transforms applied)
/// in a child process, or in this one where no child can start. `progress`, if set,
/// receives assimp's fraction done. The error is the reason alone, e.g. "assimp could not
/// read it: ...", "assimp crashed reading it (signal 11, Segmentation fault)", "assimp
/// did not finish reading it within 30 s ..." or "assimp needed more than 1.0 GiB of
/// memory to read it ...".
[[nodiscard]] Result<AssimpRead, std::string> read_with_assimp(const std::filesystem::path& file,
                                                               const std::function<void(double)>& progress,
                                                               const MeshReadLimits& limits);

}  // namespace mhd
