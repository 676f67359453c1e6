// numerics/huge_pages.h: the advice reaches the kernel, where the kernel offers huge pages, and
// changes no value.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "numerics/huge_pages.h"

namespace tribo::numerics {
namespace {

// The transparent-huge-page mode of this kernel: "always", "madvise", "never", or "" without THP.
std::string thp_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  const auto a = line.find('['), b = line.find(']');
  return a == std::string::npos || b == std::string::npos ? "" : line.substr(a + 1, b - a - 1);
}

// Bytes on huge pages (AnonHugePages) in the mappings of this process that overlap [begin, end)
// (the advice splits a mapping: the allocator's header page stays in one of its own).
std::uint64_t huge_bytes_in(std::uintptr_t begin, std::uintptr_t end) {
  std::ifstream in("/proc/self/smaps");
  std::string line;
  bool inside = false;
  std::uint64_t bytes = 0;
  while (std::getline(in, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo < end && hi > begin;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      std::uint64_t kib = 0;
      std::istringstream(line.substr(14)) >> kib;
      bytes += kib * 1024;
    }
  }
  return bytes;
}

// Under 2 MiB there is no whole huge page to ask for: no advice.
TEST(HugePages, SmallBlocksAreLeftAlone) {
  Eigen::ArrayXXd a(256, 256);  // 512 KiB
  EXPECT_FALSE(advise_huge_pages(a.data(), sizeof(double) * static_cast<std::size_t>(a.size())));
  EXPECT_FALSE(advise_huge_pages(nullptr, std::size_t{64} << 20));
}

// A 1024² grid (8 MiB) advised before its first touch: where the kernel's mode honours the advice
// ("madvise" or "always"), some of its three to four whole 2-MiB extents are huge pages once
// written (all of them on an idle machine; the kernel may fall back to small pages where its free
// memory is fragmented, so one is asked for) — none would be in "madvise" mode without the advice.
// The values written are read back unchanged.
TEST(HugePages, AFreshGridIsBackedByHugePagesWhereTheKernelOffersThem) {
  const std::string mode = thp_mode();
  if (mode != "madvise" && mode != "always") GTEST_SKIP() << "transparent huge pages: '" << mode << "'";
  Eigen::ArrayXXd a = huge_page_array(1024, 1024);
  for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = static_cast<double>(i);
  const auto begin = reinterpret_cast<std::uintptr_t>(a.data());
  EXPECT_GE(huge_bytes_in(begin, begin + sizeof(double) * static_cast<std::size_t>(a.size())), std::uint64_t{2} << 20);
  EXPECT_EQ(a(1023, 1023), static_cast<double>(1024 * 1024 - 1));
  EXPECT_EQ(a.sum(), 0.5 * static_cast<double>(a.size()) * static_cast<double>(a.size() - 1));
}

}  // namespace
}  // namespace tribo::numerics
