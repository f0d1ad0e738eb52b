#pragma once
// glibc's malloc backs its large blocks with transparent huge pages only when told so at
// start (GLIBC_TUNABLES=glibc.malloc.hugetlb=1). A cold load of a 100 M-triangle mesh
// grows gigabytes through malloc (the mesh reader's arrays, Bullet's tree builds); on a
// 2-core virtual machine a fault per 4 KiB page made it 148 s, against 78-103 s with huge
// pages (docs/benchmarks.md, "Meshes at size").

namespace mhd::cli {

/// Whether `subcommand` loads scenes without a real-time loop: validate, strokes,
/// proxy-replay, plan-sim, share-sim and cache. Huge pages can stall a thread that grows
/// its heap while the kernel compacts memory for one, so `run`, `try`, `viewer` and the
/// servers keep glibc's default.
[[nodiscard]] bool wants_huge_page_malloc(const char* subcommand);

/// Runs `program` (this one: /proc/self/exe) with `argv` once more, with
/// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES. Returns, changing nothing, where that
/// tunable is set already (by a user, to either value, or by a run before this one), in
/// a secure-execution process, where the C library is not glibc, or when the exec fails.
void restart_with_huge_page_malloc(const char* program, char** argv);

}  // namespace mhd::cli
