#include "numerics/huge_pages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace tribo::numerics {

bool advise_huge_pages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::size_t kHugePage = std::size_t{2} << 20;
  if (data == nullptr || bytes < kHugePage) return false;
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) / page * page;
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / page * page;
  if (end <= begin) return false;
  // EINVAL (a kernel without transparent huge pages) and ENOMEM leave the pages as they were;
  // either way the memory is valid, so the only outcome to report is whether it was taken.
  return madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0;
#else
  (void)data;
  (void)bytes;
  return false;
#endif
}

Eigen::ArrayXXd huge_page_array(Eigen::Index rows, Eigen::Index cols) {
  Eigen::ArrayXXd a(rows, cols);
  advise_huge_pages(a.data(), sizeof(double) * static_cast<std::size_t>(a.size()));
  return a;
}

}  // namespace tribo::numerics
