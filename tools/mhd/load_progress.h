#pragma once
// Progress of a scene's mesh loads (reading, tree building, cache reads) on stderr,
// shown without -v by every command that compiles a scene: a large mesh takes seconds.

#include "mesh_io/mesh_loader.h"

namespace mhd::cli {

/// On a terminal, one line rewritten in place; elsewhere (a log, a pipe) one line as
/// each step starts and one as it ends, so a log is not flooded.
[[nodiscard]] MeshProgress stderr_load_progress();

}  // namespace mhd::cli
