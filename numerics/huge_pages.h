// Large grids on transparent huge pages. A 1024² grid of doubles spans 2048 pages of 4 KiB: 2048
// page faults when it is first touched, and as many TLB entries when the FFT's column passes
// stride through it. On Linux with transparent huge pages in "madvise" mode (Debian's default)
// memory gets 2-MiB pages only where madvise(MADV_HUGEPAGE) asked for them, before the first
// touch; then the same grid is four pages.
#pragma once

#include <cstddef>

#include <Eigen/Core>

namespace tribo::numerics {

// Asks the kernel to back the whole pages inside [data, data + bytes) with huge pages. Advice only:
// nothing is read or written, and where it cannot be taken (below 2 MiB, no transparent huge
// pages, another system) the memory stays as it is. Returns whether the kernel took the advice.
bool advise_huge_pages(void* data, std::size_t bytes);

// An uninitialised rows × cols array, advised before its first touch.
Eigen::ArrayXXd huge_page_array(Eigen::Index rows, Eigen::Index cols);

}  // namespace tribo::numerics
