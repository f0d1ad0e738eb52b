#pragma once
// `mhd cache list` and `mhd cache clear`: the on-disk BVH cache of loaded meshes
// (engine/mesh_io/mesh_cache.h), in $MHD_CACHE_DIR, else $XDG_CACHE_HOME/mhd, else
// ~/.cache/mhd. list prints each entry (size, last use), the total and the size limit
// ($MHD_CACHE_MAX_MB, default 512 MiB); clear removes every entry. Exit status 0, or 1
// when no cache folder is known (no HOME) or a removal failed.

#include <CLI/CLI.hpp>

void add_cache_command(CLI::App& app);
