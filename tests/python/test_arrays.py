"""Arrays across the binding: shape, dtype, and tribo's (i, j) layout (i along x, contact/grid.h)."""

import os
import unittest

import numpy as np

import tribo
from helpers import temp_dir


def rms_slope_periodic(h, lx, ly):
    # contact/surface.h: periodic forward differences along x (axis 0, i) and y (axis 1, j).
    nx, ny = h.shape
    gx = (np.roll(h, -1, axis=0) - h) / (lx / nx)
    gy = (np.roll(h, -1, axis=1) - h) / (ly / ny)
    return np.sqrt(np.mean(gx ** 2 + gy ** 2))


class SurfaceArrays(unittest.TestCase):
    def test_generated_surface_shape_dtype_and_target(self):
        h = tribo.gaussian_surface(grid=64, size_m=1e-3, spectrum="self_affine", rms_height_m=0.5e-6, hurst=0.8, seed=3)
        self.assertEqual(h.shape, (64, 64))
        self.assertEqual(h.dtype, np.float64)
        # Fortran order: memory index j*nx + i, as Eigen stores it.
        self.assertTrue(h.flags["F_CONTIGUOUS"])
        # Scaled to the target exactly, mean removed.
        self.assertAlmostEqual(np.sqrt(np.mean((h - h.mean()) ** 2)) / 0.5e-6, 1.0, delta=1e-12)
        self.assertLess(abs(h.mean()), 1e-12 * 0.5e-6 * 64)
        # Same seed, same bits; another seed, another surface.
        np.testing.assert_array_equal(h, tribo.self_affine_surface(64, 1e-3, 0.8, rms_height_m=0.5e-6, seed=3))
        self.assertGreater(np.abs(h - tribo.self_affine_surface(64, 1e-3, 0.8, rms_height_m=0.5e-6, seed=4)).max(), 1e-7)

    def test_rms_slope_target(self):
        h = tribo.gaussian_acf_surface(48, 1e-3, correlation_length_m=6e-5, rms_slope=0.05, seed=2)
        self.assertAlmostEqual(rms_slope_periodic(h, 1e-3, 1e-3) / 0.05, 1.0, delta=1e-12)

    def test_anisotropic_lay_is_along_axis_0(self):
        # Correlation 4x longer along x (the lay) than across: slopes along x (axis 0) are smaller.
        h = tribo.gaussian_acf_surface(128, 1e-3, correlation_length_m=1.6e-4, rms_height_m=1e-6,
                                       correlation_length_across_m=4e-5, seed=5)
        gx = np.diff(h, axis=0).std()
        gy = np.diff(h, axis=1).std()
        self.assertGreater(gy / gx, 2.5)  # ≈ 4 for a Gaussian ACF; a transposed layout gives ≈ 0.25

    def test_statistics_of_a_non_square_field_keep_x_and_y_apart(self):
        rng = np.random.default_rng(7)
        h = rng.normal(size=(12, 5)) * 1e-6
        lx, ly = 2e-3, 0.3e-3  # very different spacings: an i/j swap changes the slope a lot
        s = tribo.surface_statistics(h, lx, ly)
        self.assertAlmostEqual(s["rms_slope"] / rms_slope_periodic(h, lx, ly), 1.0, delta=1e-12)
        self.assertAlmostEqual(s["rq_m"] / h.std(), 1.0, delta=1e-12)
        self.assertEqual(s["max_m"], h.max())
        self.assertEqual(s["min_m"], h.min())

    def test_c_and_fortran_input_give_the_same_field(self):
        rng = np.random.default_rng(1)
        z = rng.normal(size=(6, 9))
        g_c = tribo.gap_from_heights(np.ascontiguousarray(z))
        g_f = tribo.gap_from_heights(np.asfortranarray(z))
        np.testing.assert_array_equal(g_c, z.max() - z)
        np.testing.assert_array_equal(g_f, z.max() - z)
        self.assertEqual(g_c.shape, (6, 9))
        # Integer input is converted, not rejected.
        np.testing.assert_array_equal(tribo.gap_from_heights(np.arange(6).reshape(2, 3)),
                                      5.0 - np.arange(6).reshape(2, 3))

    def test_surface_files_round_trip_with_rows_along_x(self):
        d = temp_dir(self)
        rng = np.random.default_rng(11)
        z = rng.normal(size=(7, 4))
        np.save(os.path.join(d, "c.npy"), np.ascontiguousarray(z))
        np.save(os.path.join(d, "f.npy"), np.asfortranarray(z))
        np.savetxt(os.path.join(d, "m.txt"), z * 1e6, fmt="%.17g")
        for name, scale in (("c.npy", 1.0), ("f.npy", 1.0), ("m.txt", 1e-6)):
            t = tribo.read_topography(os.path.join(d, name), height_scale=scale)
            self.assertEqual(t["heights_m"].shape, (7, 4), name)
            np.testing.assert_allclose(t["heights_m"], z, rtol=1e-15, atol=1e-15 * np.abs(z).max(), err_msg=name)
        # x-y-z columns: the file carries the sides (n · spacing).
        x, y = np.meshgrid(np.arange(7) * 2e-6, np.arange(4) * 3e-6, indexing="ij")
        np.savetxt(os.path.join(d, "s.xyz"), np.column_stack([x.ravel(), y.ravel(), z.ravel()]), fmt="%.17g")
        t = tribo.read_topography(os.path.join(d, "s.xyz"))
        np.testing.assert_allclose(t["heights_m"], z, rtol=1e-15)
        self.assertAlmostEqual(t["lx_m"] / 14e-6, 1.0, delta=1e-12)
        self.assertAlmostEqual(t["ly_m"] / 12e-6, 1.0, delta=1e-12)

    def test_bad_input_is_a_value_error_with_the_message(self):
        with self.assertRaisesRegex(ValueError, "missing.npy"):
            tribo.read_topography("/nonexistent/missing.npy")
        with self.assertRaisesRegex(ValueError, "hurst"):
            tribo.gaussian_surface(grid=32, hurst=1.5)
        with self.assertRaisesRegex(ValueError, "spectrum"):
            tribo.gaussian_surface(grid=32, spectrum="fractal")


class ContactArrays(unittest.TestCase):
    def test_pressure_carries_the_load_on_the_cells(self):
        n, size = 64, 1e-3
        h = tribo.self_affine_surface(n, size, 0.8, rms_height_m=0.5e-6, seed=1, cutoff_wavelength_m=3e-5)
        r = tribo.solve_contact(tribo.gap_from_heights(h), size, e_star_Pa=1.137e11, normal_load_N=2.0)
        self.assertTrue(r["summary"]["converged"])
        self.assertLessEqual(r["summary"]["residual"], 1e-8)
        p = r["pressure_Pa"]
        self.assertEqual(p.shape, (n, n))
        self.assertEqual(p.dtype, np.float64)
        cell = (size / n) ** 2
        self.assertAlmostEqual(p.sum() * cell / 2.0, 1.0, delta=1e-10)
        self.assertAlmostEqual(r["area_fraction"], np.count_nonzero(p > 0) / n ** 2, delta=1e-15)
        self.assertAlmostEqual(r["mean_gap_m"] / r["gap_m"].mean(), 1.0, delta=1e-12)
        # Contact only where the gap closed, and it touches the highest summit first.
        # (to the solver's tolerance: 1e-8 of the elastic deflection, far below 1e-6 Rq)
        self.assertLess(r["gap_m"][p > 0].max(), 1e-6 * 0.5e-6)
        self.assertGreater(r["gap_m"][p == 0].mean(), 0.1 * 0.5e-6)
        self.assertGreater(p.flat[np.argmax(h)], 0.0)

    def test_non_convergence_is_reported_not_raised(self):
        h = tribo.self_affine_surface(64, 1e-3, 0.8, rms_height_m=0.5e-6, seed=1)
        r = tribo.solve_contact(tribo.gap_from_heights(h), 1e-3, normal_load_N=2.0, max_iterations=2)
        self.assertFalse(r["summary"]["converged"])
        self.assertEqual(r["summary"]["iterations"], 2)
        self.assertTrue(r["summary"]["message"])

    def test_bad_contact_input_is_a_value_error(self):
        g = np.ones((8, 8)) * 1e-6
        with self.assertRaisesRegex(ValueError, "exactly one"):
            tribo.solve_contact(g, 1e-3, normal_load_N=1.0, approach_m=1e-7)
        with self.assertRaises(ValueError):
            tribo.solve_contact(g, 1e-3, normal_load_N=-1.0)


if __name__ == "__main__":
    unittest.main()
