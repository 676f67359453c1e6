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

#include <filesystem>

namespace tribo::contact {

struct Topography {
  Eigen::ArrayXXd heights_m;
  double lx_m = 0.0;  // 0 when the file format carries no lateral size (matrix, .npy)
  double ly_m = 0.0;
};

// Dispatches on the extension: .npy, .xyz (columns), anything else as an ASCII matrix.
// Unreadable, malformed or non-finite data raise std::invalid_argument naming the file.
Topography read_topography(const std::filesystem::path& path, double height_scale = 1.0);

Eigen::ArrayXXd read_npy(const std::filesystem::path& path);
Eigen::ArrayXXd read_ascii_matrix(const std::filesystem::path& path);
Topography read_xyz(const std::filesystem::path& path);

// Writes a float64 .npy (see above); throws std::runtime_error naming the file on I/O failure.
void write_npy(const std::filesystem::path& path, const Eigen::ArrayXXd& field);
// The same bytes into a stream (for atomic writers that own the file).
void write_npy(std::ostream& out, const Eigen::ArrayXXd& field);

}  // namespace tribo::contact
