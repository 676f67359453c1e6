"""The Reynolds bindings: problems as objects with array attributes, solutions against closed forms
(which also pins the (i, j) layout: i is x, the sliding direction)."""

import math
import unittest

import numpy as np

import tribo


def inclined_pad_pressure(x, h1, h2, length, eta, u):
    # d/dx(h³ dp/dx) = 6 η U dh/dx with p(0) = p(L) = 0 (U = U1 + U2, lubrication/reynolds.h):
    # dp/dx = 6 η U (1/h² − h_m/h³), h linear, integrals in closed form.
    s = (h2 - h1) / length
    h = h1 + s * x
    i2 = (1 / h1 - 1 / h) / s                 # ∫ h⁻² dx from 0
    i3 = (1 / h1 ** 2 - 1 / h ** 2) / (2 * s)  # ∫ h⁻³ dx from 0
    i2_l = (1 / h1 - 1 / h2) / s
    i3_l = (1 / h1 ** 2 - 1 / h2 ** 2) / (2 * s)
    return 6 * eta * u * (i2 - (i2_l / i3_l) * i3)


class Reynolds(unittest.TestCase):
    def test_inclined_pad_along_x_matches_the_closed_form(self):
        nx, ny, length = 161, 5, 0.02
        h1, h2, eta, u = 2e-5, 1e-5, 0.05, 2.0
        x = np.arange(nx) * length / (nx - 1)
        gap = np.repeat((h1 + (h2 - h1) * x / length)[:, None], ny, axis=1)  # varies along i only
        prob = tribo.reynolds_problem(gap, dx_m=length / (nx - 1), dy_m=1e-3, viscosity_Pa_s=eta,
                                      sliding_speed_m_per_s=u, boundary_y="periodic", cavitation="none")
        self.assertEqual(prob.gap_m.shape, (nx, ny))
        s = tribo.solve_reynolds(prob)
        self.assertTrue(s["summary"]["converged"])
        p = s["pressure_Pa"]
        self.assertEqual(p.shape, (nx, ny))
        self.assertEqual(p.dtype, np.float64)
        exact = inclined_pad_pressure(x, h1, h2, length, eta, u)
        # Periodic in y with a gap uniform in y: every column j is the 1-D solution.
        for j in range(ny):
            np.testing.assert_allclose(p[:, j], p[:, 0], rtol=0, atol=1e-9 * exact.max())
        # Second-order finite volumes: at 161 nodes the error is ~1e-5 of the peak.
        self.assertLess(np.abs(p[:, 0] - exact).max(), 2e-4 * exact.max())
        # Load: trapezoid of p over the area (ny·dy periodic width).
        load = np.trapz(exact, x) * ny * 1e-3
        self.assertAlmostEqual(s["load_N"] / load, 1.0, delta=1e-3)
        # Mass balance of the discrete fluxes.
        self.assertLess(abs(s["flow"]["net_outflow_m3_per_s"]), 1e-9 * abs(s["flow"]["inflow_x0_m3_per_s"]))

    def test_squeeze_film_between_discs_matches_appendix_iii(self):
        r, h, hdot, eta = 4.7625e-3, 1e-6, -1e-6, 0.021
        prob = tribo.parallel_discs_problem(radius_m=r, gap_m=h, gap_rate_m_per_s=hdot, viscosity_Pa_s=eta, n=96,
                                            cavitation="none")
        self.assertEqual(prob.disc[2], r)
        s = tribo.solve_reynolds(prob)
        closed = 3 * math.pi * eta * r ** 4 * (-hdot) / (2 * h ** 3)  # thesis (3.2.2)
        self.assertAlmostEqual(s["load_N"] / closed, 1.0, delta=5e-3)
        self.assertTrue(s["wetted"].dtype == np.bool_)
        self.assertGreater(s["wetted"].mean(), 0.7)  # π/4 of the square, plus the rim margin

    def test_problem_attributes_round_trip_and_resolve(self):
        prob = tribo.parallel_discs_problem(gap_m=1e-6, gap_rate_m_per_s=-1e-6, n=33)
        load1 = tribo.solve_reynolds(prob)["load_N"]
        prob.viscosity_Pa_s = 2 * prob.viscosity_Pa_s  # linear in η
        self.assertAlmostEqual(tribo.solve_reynolds(prob)["load_N"] / load1, 2.0, delta=1e-10)
        g = prob.gap_m.copy()
        prob.gap_m = 2 * g  # load ∝ 1/h³ at fixed ḣ
        np.testing.assert_array_equal(prob.gap_m, 2 * g)
        self.assertAlmostEqual(tribo.solve_reynolds(prob)["load_N"] / load1, 2.0 / 8.0, delta=1e-10)
        prob.cavitation = "none"
        self.assertEqual(prob.cavitation, "none")
        with self.assertRaisesRegex(ValueError, "cavitation"):
            prob.cavitation = "half_sommerfeld"

    def test_bad_film_is_a_value_error(self):
        with self.assertRaises(ValueError):
            tribo.reynolds_problem(np.zeros((8, 8)), dx_m=1e-5)  # h must be > 0

    def test_rough_pair_film_in_contact(self):
        lower = tribo.gaussian_acf_surface(32, 1e-3, correlation_length_m=6.25e-5, rms_height_m=4.3e-7, seed=1)
        upper = tribo.gaussian_acf_surface(32, 1e-3, correlation_length_m=6.25e-5, rms_height_m=6.4e-8, seed=2)
        f = tribo.rough_pair_film(upper, lower, 1e-3, normal_load_N=0.5, contact_gap_fraction=0.1)
        self.assertTrue(f["contact"]["converged"])
        self.assertEqual(f["problem"].gap_m.shape, (33, 32))  # (n + 1) × n periodic cell
        self.assertGreaterEqual(f["problem"].gap_m.min(), f["floor_m"] * (1 - 1e-12))
        sigma = math.hypot(np.std(upper), np.std(lower))
        self.assertAlmostEqual(f["composite_rms_height_m"] / sigma, 1.0, delta=1e-12)


if __name__ == "__main__":
    unittest.main()
