// Reading measured topographies and writing fields.
//
// A height field h(i, j) has i along x (rows) and j along y (columns), as everywhere in contact/.
// File conventions:
//   .npy         2-D float64 or float32 (either byte order, C or Fortran order); a[i, j] = h(i, j).
//                write_npy writes float64, Fortran order, shape (nx, ny): numpy's a[i, j] is h(i, j).
//   ASCII matrix whitespace- or comma-separated numbers; file row i, column j is h(i, j);
//                lines starting with '#' or '%' are comments.
//   x-y-z        three columns x y z on a complete regular grid (any order of the lines); the grid
//                spacing is the distance between neighbouring distinct x (and y) values and the
//                sides are L = n · spacing.
// Heights are multiplied by `height_scale` (e.g. 1e-6 for files in µm) to give metres.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <istream>

namespace tribo::contact {

struct Topography {
  Eigen::ArrayXXd heights_m;
  double lx_m = 0.0;  // 0 when the file format carries no lateral size (matrix, .npy)
  double ly_m = 0.0;
  bool height_unit_from_file = false;  // the heights were converted to metres by the file's header
};

// Dispatches on the extension: .npy, .xyz (columns), a Dektak .csv, anything else as an ASCII
// matrix with an optional instrument header (read_ascii_topography). A file whose header states
// its height unit must be read with height_scale 1.
// Unreadable, malformed or non-finite data raise std::invalid_argument naming the file.
Topography read_topography(const std::filesystem::path& path, double height_scale = 1.0);

Eigen::ArrayXXd read_npy(const std::filesystem::path& path);
Eigen::ArrayXXd read_ascii_matrix(const std::filesystem::path& path);
Topography read_xyz(const std::filesystem::path& path);
// Measured maps with an instrument header (the lines before the numbers):
//   interferometer export: "h=ROWS w=COLS", "pixel size=VALUE UNIT", "data unit=UNIT",
//                          "height conversion factor (-> m)=FACTOR" (heights × factor are metres);
//   Gwyddion ASCII export: "# Width: VALUE UNIT" (columns), "# Height: VALUE UNIT" (rows),
//                          "# Value units: UNIT".
// The stated size sets lx_m (rows) and ly_m (columns), the stated unit converts the heights to
// metres; a count in the header that disagrees with the data is an error. Without a header this
// is read_ascii_matrix.
Topography read_ascii_topography(const std::filesystem::path& path);
Topography read_ascii_topography(std::istream& in, const std::filesystem::path& name);
// A Dektak stylus profile export (.csv: "Scan Parameters", "Length,VALUE um", ..., then
// "Lateral um,Raw Micrometer," and one "x,z" row per sample): an n × 1 profile in metres with
// lx_m = the scan Length (Length/n per sample) and ly_m one sample.
Topography read_dektak_csv(const std::filesystem::path& path);
Topography read_dektak_csv(std::istream& in, const std::filesystem::path& name);

// The same readers on a stream; `name` only labels the error messages (the fuzz harnesses in
// fuzz/ feed bytes through these without touching the disk).
Eigen::ArrayXXd read_npy(std::istream& in, const std::filesystem::path& name);
Eigen::ArrayXXd read_ascii_matrix(std::istream& in, const std::filesystem::path& name);
Topography read_xyz(std::istream& in, const std::filesystem::path& name);

// Limits against hostile or broken files, above any measured map: at most 2^28 heights (a
// 16384 x 16384 map) and 64 MiB per text line. Beyond them a file is an error, not an
// allocation the size of what it claims.
inline constexpr std::size_t kMaxSurfaceHeights = std::size_t{1} << 28;
inline constexpr std::size_t kMaxSurfaceLineBytes = std::size_t{1} << 26;

// Writes a float64 .npy (see above); throws std::runtime_error naming the file on I/O failure.
void write_npy(const std::filesystem::path& path, const Eigen::ArrayXXd& field);
// The same bytes into a stream (for atomic writers that own the file).
void write_npy(std::ostream& out, const Eigen::ArrayXXd& field);
// A profile (a 1-D field along x) as a float64 .npy of shape (n,).
void write_npy(std::ostream& out, const std::vector<double>& profile);

}  // namespace tribo::contact
