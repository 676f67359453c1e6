"""The bindings reproduce the CLI: the same config through the built `tribo` and through Python
gives the same numbers (to 1e-12 relative; the same library calls, so usually bit for bit)."""

import csv
import json
import os
import unittest

import numpy as np

import tribo
from helpers import example, example_text, run_cli, run_cli_json, temp_dir, write_config

REL = 1e-12


class CliMatch(unittest.TestCase):
    def assertClose(self, python_value, cli_value, key, rel=REL):
        self.assertIsNotNone(cli_value, key)
        scale = max(abs(cli_value), 1e-300)
        self.assertLessEqual(abs(python_value - cli_value), rel * scale,
                             f"{key}: python {python_value!r} vs cli {cli_value!r}")

    def assertFieldClose(self, python_field, npy_path, key, rel=REL):
        cli_field = np.load(npy_path)
        self.assertEqual(python_field.shape, cli_field.shape, key)
        scale = np.abs(cli_field).max()
        self.assertLessEqual(np.abs(python_field - cli_field).max(), rel * scale, key)


class Contact(CliMatch):
    def test_gaussian_elastic_plastic_with_tangential_load(self):
        d = temp_dir(self)
        # examples/contact-gaussian.toml at 64² instead of 512² (same surface spectrum, seconds not minutes).
        cfg = write_config(d, "contact.toml", example_text("contact-gaussian.toml", [("grid = 512", "grid = 64")]))
        cli = run_cli_json(["contact", cfg], os.path.join(d, "out"), "contact.json")
        py = tribo.contact_from_toml(cfg)
        s = py["summary"]
        for key in ("area_fraction", "real_area_m2", "plastic_area_m2", "max_pressure_Pa", "mean_gap_m", "approach_m",
                    "shear_stress_Pa", "pressure_cap_Pa", "surface_rq_m", "surface_rms_slope", "normal_load_N"):
            self.assertClose(s[key], cli[key], key)
        self.assertEqual(s["iterations"], cli["iterations"])
        self.assertEqual(s["converged"], cli["converged"])
        self.assertTrue(s["converged"])
        self.assertGreater(s["area_fraction"], 0.0)
        self.assertFieldClose(py["pressure_Pa"], os.path.join(d, "out", "pressure.npy"), "pressure")
        self.assertFieldClose(py["gap_m"], os.path.join(d, "out", "gap.npy"), "gap")

        # The keyword route (surface generator + solve_contact) gives the same contact.
        h = tribo.self_affine_surface(64, 1e-3, 0.8, rms_height_m=0.57e-6, seed=1, rolloff_wavelength_m=2.5e-4,
                                      cutoff_wavelength_m=8e-6)
        np.testing.assert_array_equal(tribo.gap_from_heights(h), py["gap0_m"])
        r = tribo.solve_contact(tribo.gap_from_heights(h), 1e-3, e_star_Pa=1.137e11, normal_load_N=50.0,
                                hardness_Pa=1.18e9, tangential_load_N=10.0, alpha=25.0, tolerance=1e-8)
        self.assertClose(r["area_fraction"], cli["area_fraction"], "keyword area_fraction")
        self.assertClose(r["junction"]["shear_stress_Pa"], cli["shear_stress_Pa"], "keyword shear_stress_Pa")
        self.assertEqual(r["summary"]["iterations"], cli["iterations"])

    def test_sphere_non_periodic(self):
        d = temp_dir(self)
        cfg = write_config(d, "sphere.toml", example_text("contact-sphere.toml", [("grid = 512", "grid = 96")]))
        cli = run_cli_json(["contact", cfg], os.path.join(d, "out"), "contact.json")
        py = tribo.run_contact(cfg)
        for key in ("area_fraction", "real_area_m2", "max_pressure_Pa", "approach_m", "contact_radius_m",
                    "hertz_contact_radius_m"):
            self.assertClose(py["summary"][key], cli[key], key)
        # The same through a dotted override of the full-size example.
        py2 = tribo.run_contact(example("contact-sphere.toml"), overrides={"domain.grid": 96})
        self.assertClose(py2["summary"]["area_fraction"], cli["area_fraction"], "override area_fraction")

    def test_bad_config_message_is_the_clis(self):
        d = temp_dir(self)
        cfg = write_config(d, "bad.toml", example_text("contact-sphere.toml", [("radius_m = 0.01", "radius_m = -0.01")]))
        p = run_cli("contact", cfg, "--out", os.path.join(d, "out"))
        self.assertEqual(p.returncode, 2)
        with self.assertRaises(ValueError) as e:
            tribo.contact_from_toml(cfg)
        self.assertIn("radius_m", str(e.exception))
        self.assertIn(str(e.exception), p.stderr)


class Reynolds(CliMatch):
    def test_parallel_discs(self):
        d = temp_dir(self)
        cfg = write_config(d, "discs.toml", example_text("reynolds-parallel-discs.toml", [("n = 256", "n = 64")]))
        cli = run_cli_json(["reynolds", cfg], os.path.join(d, "out"), "reynolds.json")
        py = tribo.reynolds_from_toml(cfg)
        for key in ("load_N", "max_pressure_Pa", "reference_load_N", "load_relative_error"):
            self.assertClose(py["summary"][key], cli[key], key)
        self.assertFieldClose(py["pressure_Pa"], os.path.join(d, "out", "pressure_Pa.npy"), "pressure")
        # Squeeze film against Appendix III within the grid's discretisation error.
        self.assertLess(abs(py["summary"]["load_relative_error"]), 0.02)
        # Solving the returned problem again gives the same load.
        self.assertClose(tribo.solve_reynolds(py["problem"])["load_N"], cli["load_N"], "re-solve load_N")

    def test_rough_pair_deformed_by_contact(self):
        d = temp_dir(self)
        cfg = write_config(d, "rough.toml", example_text("reynolds-rough-pair-loaded.toml", [("n = 128", "n = 48")]))
        cli = run_cli_json(["reynolds", cfg], os.path.join(d, "out"), "reynolds.json")
        py = tribo.reynolds_from_toml(cfg)
        s = py["summary"]
        for key in ("load_N", "max_pressure_Pa", "cavitated_fraction"):
            self.assertClose(s[key], cli[key], key)
        for key in ("contact_area_fraction", "contact_mean_gap_m", "composite_rms_height_m"):
            self.assertClose(s["geometry"][key], cli["geometry"][key], key)
        self.assertEqual(s["iterations"], cli["iterations"])
        self.assertTrue(s["converged"])
        self.assertFieldClose(py["pressure_Pa"], os.path.join(d, "out", "pressure_Pa.npy"), "pressure")
        self.assertFieldClose(py["fill_fraction"], os.path.join(d, "out", "fill_fraction.npy"), "fill fraction")


class Rig(CliMatch):
    NUMERIC = ("period_s", "peak_to_peak_m", "mean_displacement_m", "stick_time_s", "slip_time_s", "mu_s_mean",
               "load_rate_mean_per_s", "mean_friction_N", "mu_at_reversal_mean", "end_time_s", "window_start_s")

    def compare_summaries(self, py, cli):
        for key in self.NUMERIC:
            if cli[key] is None:
                self.assertIsNone(py[key], key)
            else:
                self.assertClose(py[key], cli[key], key)
        for key in ("regime", "breakaways", "reattachments", "reversals", "completed", "events", "integrator_steps",
                    "friction_law"):
            self.assertEqual(py[key], cli[key], key)
        for key, value in cli["rig"].items():
            self.assertClose(py["rig"][key], value, "rig." + key)

    def test_coulomb_stick_slip(self):
        d = temp_dir(self)
        out = os.path.join(d, "out")
        cli = run_cli_json(["rig", example("rig-coulomb.toml")], out, "summary.json")
        py = tribo.rig_from_toml(example("rig-coulomb.toml"))
        self.compare_summaries(py["summary"], cli)
        self.assertEqual(py["summary"]["regime"], "stick_slip")
        # trace.csv holds 6 significant digits: the arrays agree to that.
        with open(os.path.join(out, "trace.csv")) as f:
            rows = list(csv.DictReader(f))  # plain CSV: the header is the first line
        self.assertEqual(len(rows), len(py["trace"]["t_s"]))
        for col in ("t_s", "x_m", "xdot_m_per_s", "friction_N", "friction_true_N", "drive_speed_m_per_s", "x_drive_m"):
            a = py["trace"][col]
            self.assertEqual(a.dtype, np.float64)
            b = np.array([float(r[col]) for r in rows])
            np.testing.assert_allclose(a, b, rtol=1e-5, atol=1e-5 * np.abs(b).max(), err_msg=col)
        self.assertEqual(list(py["trace"]["slipping"]), [r["phase"] == "slip" for r in rows])
        with open(os.path.join(out, "events.csv")) as f:
            events = list(csv.DictReader(f))
        self.assertEqual(list(py["events"]["event"]), [e["event"] for e in events])

    def test_overrides_match_an_edited_config(self):
        d = temp_dir(self)
        cfg = write_config(d, "rig.toml", example_text("rig-coulomb.toml", [
            ("drive_speed_m_per_s = 1e-3", "drive_speed_m_per_s = 0.02"), ("mu_k = 0.2", "mu_k = 0.25")]))
        cli = run_cli_json(["rig", cfg], os.path.join(d, "out"), "summary.json")
        py = tribo.run_rig(example("rig-coulomb.toml"),
                           overrides={"rig.drive_speed_m_per_s": 0.02, "friction.mu_k": 0.25})
        self.compare_summaries(py["summary"], cli)
        # And from a dict.
        import tomllib
        with open(cfg, "rb") as f:
            doc = tomllib.load(f)
        self.compare_summaries(tribo.run_rig(doc)["summary"], cli)

    def test_bad_rig_config_is_a_value_error_naming_the_key(self):
        with self.assertRaisesRegex(ValueError, r"with overrides.*mass_kg"):
            tribo.run_rig(example("rig-coulomb.toml"), overrides={"rig.mass_kg": -1.0})
        with self.assertRaisesRegex(ValueError, "typo_key"):
            tribo.run_rig(example("rig-coulomb.toml"), overrides={"rig.typo_key": 1.0})


class Homogenise(CliMatch):
    def test_small_homogenisation_matches_the_cli(self):
        d = temp_dir(self)
        # The thesis steel pair at 32² with one realisation and a short Stribeck curve.
        cfg = write_config(d, "steel.toml", example_text("thesis-steel.toml", [
            ("grid = 128", "grid = 32"), ("realisations = 4", "realisations = 1"), ("count = 25", "count = 5"),
            ("min_contact_grid = 2048", "min_contact_grid = 64"), ("junction_grid = 4096", "junction_grid = 0")]))
        cli_out = os.path.join(d, "cli")
        p = run_cli("homogenise", cfg, "--out", cli_out, "--no-plots")
        self.assertEqual(p.returncode, 0, p.stderr)
        with open(os.path.join(cli_out, "law.json")) as f:
            cli = json.load(f)
        law = tribo.homogenise_from_toml(cfg, os.path.join(d, "py"))
        self.assertClose(law["junction"]["mu_s_max"], cli["junction"]["mu_s_max"], "mu_s_max")
        self.assertClose(law["junction"]["mu_boundary"], cli["junction"]["mu_boundary"], "mu_boundary")
        for a, b in zip(law["stribeck"], cli["stribeck"]):
            self.assertClose(a["mu"], b["mu"], "stribeck mu")
            # Λ = h̄/σ with σ the cells' composite rms roughness.
            self.assertClose(b["film_parameter"], b["separation_m"] / cli["cells"]["sigma_m"], "film parameter")
        # One patch on its own: realisation 0 is the patch the CLI cached.
        patch = tribo.homogenise_patch(cfg, 0)
        with open(os.path.join(cli_out, "patches", "realisation-0.json")) as f:
            cached = json.load(f)["patch"]
        self.assertClose(patch["mu_s_max"], cached["mu_s_max"], "patch mu_s_max")
        np.testing.assert_allclose(patch["area_fraction"], np.array(cached["area_fraction"], dtype=float), rtol=REL)
        # read_law checks and returns the table as arrays.
        t = tribo.read_law(os.path.join(cli_out, "law.json"))["table"]
        self.assertEqual(t["solid_load_N"].dtype, np.float64)
        self.assertEqual(t["solid_load_N"][-1], 0.0)
        self.assertTrue(np.all(np.diff(t["separation_m"]) > 0))


if __name__ == "__main__":
    unittest.main()
