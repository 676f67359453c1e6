// Surface readers on hostile input (issue 18, fuzz/): each case once crashed, hung, allocated
// what a file merely claimed, or threw something other than the documented
// std::invalid_argument. The inputs are also in fuzz/corpus/surface/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "contact/surface_io.h"

namespace tribo::contact {
namespace {

std::string npy(const std::string& dict, const std::string& data) {
  std::string header = dict;
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  return out + header + data;
}

std::string doubles(std::initializer_list<double> v) {
  std::string s;
  for (double x : v) s.append(reinterpret_cast<const char*>(&x), sizeof x);
  return s;
}

// The message of the std::invalid_argument `read` throws on `bytes` ("" when it accepts them).
template <class Read>
std::string error_of(const std::string& bytes, Read read) {
  std::istringstream in(bytes);
  try {
    read(in);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

const auto npy_reader = [](std::istream& in) { return read_npy(in, "h.npy"); };
const auto ascii_reader = [](std::istream& in) { return read_ascii_matrix(in, "h.txt"); };
const auto xyz_reader = [](std::istream& in) { return read_xyz(in, "h.xyz"); };

TEST(SurfaceHostile, LongNpyHeaderIsParsedWithoutRecursion) {
  // std::regex recursed once per character of whitespace: 60 kB of it overflowed the stack.
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::string(60000, ' ') + "1, 2), }";
  std::string header = dict + "\n";
  std::string bytes("\x93NUMPY\x02\x00", 8);
  const auto n = static_cast<std::uint32_t>(header.size());
  for (int b = 0; b < 4; ++b) bytes += static_cast<char>((n >> (8 * b)) & 0xff);
  bytes += header + doubles({1.5, -2.5});
  std::istringstream in(bytes);
  const Eigen::ArrayXXd h = read_npy(in, "h.npy");
  ASSERT_EQ(h.rows(), 1);
  ASSERT_EQ(h.cols(), 2);
  EXPECT_EQ(h(0, 1), -2.5);
}

TEST(SurfaceHostile, NpyShapeClaimsAreCheckedAgainstLimitsAndBytes) {
  // 30 digits: std::stol threw std::out_of_range (not the documented error).
  EXPECT_NE(error_of(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (123456789012345678901234567890, 2), }", ""),
                     npy_reader)
                .find("more than"),
            std::string::npos);
  // rows · cols overflowed 64 bits and sized the buffer.
  EXPECT_NE(error_of(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }", ""), npy_reader)
                .find("more than"),
            std::string::npos);
  // Within the limit but far beyond the file: an error once the bytes run out, not a 2 GiB buffer.
  EXPECT_NE(error_of(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (16384, 16384), }", doubles({1.0})), npy_reader)
                .find("truncated .npy data"),
            std::string::npos);
  EXPECT_NE(error_of(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", doubles({1, 2, 3})), npy_reader)
                .find("must be 2-D"),
            std::string::npos);
  EXPECT_NE(error_of(npy("{'descr': '<i8', 'fortran_order': False, 'shape': (1, 1), }", doubles({1})), npy_reader).find("dtype"),
            std::string::npos);
  EXPECT_NE(error_of(npy("{'descr': '<f8', 'shape': (1, 1), }", doubles({1})), npy_reader).find("h.npy"), std::string::npos);
}

TEST(SurfaceHostile, XyzWithInfiniteCoordinatesIsRejected) {
  // x = inf made the spacing NaN, every spacing check passed and lround(NaN) indexed the array
  // far out of bounds (a write outside the heights).
  EXPECT_NE(error_of("0 0 1\n0 1 2\ninf 0 3\ninf 1 4\n", xyz_reader).find("finite"), std::string::npos);
  EXPECT_NE(error_of("0 0 1\n0 1 2\nnan 0 3\nnan 1 4\n", xyz_reader).find("finite"), std::string::npos);
  // Finite but spanning more than a double: the spacing overflows.
  EXPECT_NE(error_of("-1.7e308 0 1\n-1.7e308 1 2\n1.7e308 0 3\n1.7e308 1 4\n", xyz_reader).find("span"), std::string::npos);
}

TEST(SurfaceHostile, XyzDuplicatePointIsNamedAsSuch) {
  // Four points on a 2 × 2 grid, one node twice and one missing.
  EXPECT_NE(error_of("0 0 1\n0 0 2\n1 0 3\n1 1 4\n", xyz_reader).find("two points fall on the grid node"), std::string::npos);
}

TEST(SurfaceHostile, HeaderCountsMustBeWholeNumbersWithinTheLimit) {
  // A header claiming 2.8e62 columns reached the mismatch message as a cast to long: undefined
  // behaviour (UBSan, fuzz_surface, 2026-11-29). A count is a whole number up to the height limit.
  const auto topography = [](std::istream& in) { return read_ascii_topography(in, "h.txt"); };
  const std::string huge = error_of("h=3 w=2.8e62\n1 2\n", topography);
  EXPECT_NE(huge.find("h.txt"), std::string::npos);
  EXPECT_NE(huge.find("header w"), std::string::npos);
  EXPECT_NE(huge.find("whole number"), std::string::npos);
  EXPECT_NE(error_of("h=1.5 w=2\n1 2\n", topography).find("header h"), std::string::npos);
  // A whole claim that disagrees with the data is still the mismatch, with both shapes.
  EXPECT_NE(error_of("h=3 w=2\n1 2\n", topography).find("header says 3 x 2 heights, the file holds 1 x 2"), std::string::npos);
}

TEST(SurfaceHostile, AsciiTokensMustBeWholeNumbers) {
  // A NUL byte ended the token for strtod, so "1\0x" read as 1.
  EXPECT_NE(error_of(std::string("1 2\n3 4\0x\n", 10), ascii_reader).find("is not a number"), std::string::npos);
  // Messages quote at most 40 bytes of a token.
  const std::string msg = error_of(std::string(100000, 'z') + "\n", ascii_reader);
  EXPECT_NE(msg.find("line 1"), std::string::npos);
  EXPECT_LT(msg.size(), 200u);
}

TEST(SurfaceHostile, OverlongLineIsRejectedBeforeItIsHeld) {
  std::string bytes(kMaxSurfaceLineBytes + 1, '1');
  EXPECT_NE(error_of(bytes, ascii_reader).find("longer than"), std::string::npos);
}

TEST(SurfaceHostile, HeightScaleMustNotOverflowTheHeights) {
  // Finite heights times a finite scale gave infinities that reached the contact solver.
  const auto file = std::filesystem::temp_directory_path() / "tribo_surface_hostile_scale.txt";
  std::ofstream(file) << "1e300 1\n2 3\n";
  try {
    read_topography(file, 1e10);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("overflow"), std::string::npos) << e.what();
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace tribo::contact
