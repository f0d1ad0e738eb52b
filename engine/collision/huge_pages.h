#pragma once
// Load-time memory advice for the arrays of large meshes: anonymous arrays in 2 MiB pages
// (a fault per 2 MiB, not per 4 KiB, which on a virtual machine is most of a copy's
// time), and a file mapping's pages mapped a range at a time or let go.

#include <cstddef>
#include <vector>

namespace mhd {

/// Asks for transparent huge pages over the 2 MiB pages wholly inside [data, data+bytes),
/// before they are first written. Advice only: where the kernel declines, nothing changes.
void advise_huge_pages(void* data, std::size_t bytes);

/// Maps the pages of [data, data+bytes) of a file mapping in one call (MADV_POPULATE_READ)
/// rather than a fault each. Advice only.
void populate_for_reading(const void* data, std::size_t bytes);

/// Lets go of the pages wholly inside [data, data+bytes) of a private file mapping that
/// was never written there: they leave the process's memory and come back from the file
/// when next read. Never call it on anonymous memory or on written pages (it drops them).
void release_file_pages(const void* data, std::size_t bytes);

/// v sized to n elements, its storage advised into huge pages before the elements are
/// made (for arrays of millions of elements).
template <class T, class A>
void resize_in_huge_pages(std::vector<T, A>& v, std::size_t n) {
  v.clear();
  v.shrink_to_fit();
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

}  // namespace mhd
