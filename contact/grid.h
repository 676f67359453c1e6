// The grid and the field type shared by contact/ and lubrication/.
//
// Where it lives: dependencies point contact ← lubrication (DESIGN §1), so the one type both use
// belongs to the lower library; tribo_lubrication already links tribo_contact, and a target of
// its own for one header would add a dependency edge without adding a subject.
//
// Grid: nx × ny points at spacing dx × dy (m). The same struct serves two readings.
//   cells  (contact/: surfaces, the FFT half-space) — point (i, j) stands for the cell
//          [i dx, (i + 1) dx] × [j dy, (j + 1) dy] (its centre where a position is needed); the
//          cells cover period_x × period_y = nx dx × ny dy, the period of a periodic half-space
//          or surface, or the patch of a non-periodic one. Grid::patch builds it from the sides.
//   nodes  (lubrication/: the finite-volume Reynolds solver) — point (i, j) is the node
//          (i dx, j dy); the nodes span span_x × span_y = (nx − 1) dx × (ny − 1) dy, and a grid
//          periodic in y has the period ny dy (node ny ≡ node 0).
// An n × n periodic surface of side L (dx = L/n) becomes the Reynolds cell of (n + 1) × n nodes
// at the same spacing: node column n repeats column 0, so span_x = period_y = L
// (lubrication/geometry.h periodic_film_cell).
//
// Field: a scalar on a grid is an Eigen::ArrayXXd of nx rows (x, index i) and ny columns (y,
// index j). Eigen stores it column-major, so x is the contiguous index and the value (i, j) sits
// at linear index j·nx + i (Grid::index); f(i, j) and f(Grid::index(i, j)) are the same value.
// Masks on a grid (lubrication's wetted nodes) are Eigen::ArrayXX<bool> with the same layout.
#pragma once

#include <Eigen/Core>

namespace tribo::contact {

struct Grid {
  Eigen::Index nx = 0, ny = 0;  // points along x and y
  double dx_m = 0, dy_m = 0;    // spacing along x and y

  // nx × ny cells covering lx_m × ly_m: spacing lx_m / nx, ly_m / ny.
  static Grid patch(Eigen::Index nx, Eigen::Index ny, double lx_m, double ly_m) {
    return {nx, ny, lx_m / static_cast<double>(nx), ly_m / static_cast<double>(ny)};
  }

  // nx·dx: the side the cells cover — the period of a periodic grid.
  double period_x_m() const { return static_cast<double>(nx) * dx_m; }
  double period_y_m() const { return static_cast<double>(ny) * dy_m; }
  // (nx − 1)·dx: the distance from the first node to the last.
  double span_x_m() const { return static_cast<double>(nx - 1) * dx_m; }
  double span_y_m() const { return static_cast<double>(ny - 1) * dy_m; }
  double cell_area_m2() const { return dx_m * dy_m; }
  // period_x · period_y: the area the nx × ny cells cover.
  double area_m2() const { return period_x_m() * period_y_m(); }

  Eigen::Index size() const { return nx * ny; }
  Eigen::Index index(Eigen::Index i, Eigen::Index j) const { return j * nx + i; }
  // A field on this grid, every value `value`.
  Eigen::ArrayXXd field(double value = 0.0) const { return Eigen::ArrayXXd::Constant(nx, ny, value); }
  // Whether `f` has this grid's shape (nx × ny).
  bool holds(const Eigen::ArrayXXd& f) const { return f.rows() == nx && f.cols() == ny; }
};

// Throws std::invalid_argument naming the bad field: fewer than 1 point per side ("grid"), or a
// non-positive or non-finite cell size.
void validate(const Grid& grid);

}  // namespace tribo::contact
