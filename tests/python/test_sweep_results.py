"""read_sweep_results on a real `tribo sweep` output: columns, dtypes, failure rows, and the
values against the same points run through the bindings."""

import os
import unittest

import numpy as np

import tribo
from helpers import example, run_cli, temp_dir, write_config

SPEC = """
[base]
command = "rig"
config = "{config}"

[[axis]]
key = "rig.drive_speed_m_per_s"
values = [1e-3, 3e-2]

[[axis]]
key = "rig.mass_kg"
values = [0.99822, -1.0]    # a negative mass: that point fails and is recorded as failed

[outputs]
columns = ["summary.json:regime", "summary.json:peak_to_peak_m", "summary.json:mu_s_mean", "summary.json:period_s"]
"""


class SweepResults(unittest.TestCase):
    def test_rig_sweep_round_trip(self):
        d = temp_dir(self)
        spec = write_config(d, "spec.toml", SPEC.format(config=example("rig-coulomb.toml")))
        out = os.path.join(d, "out")
        p = run_cli("sweep", spec, "--out", out)
        self.assertIn(p.returncode, (0, 1), p.stderr)  # a failed point may set a non-zero status
        r = tribo.read_sweep_results(out)
        self.assertEqual(list(r)[:3], ["point_id", "rig.drive_speed_m_per_s", "rig.mass_kg"])
        self.assertEqual(r["point_id"].dtype, np.int64)
        np.testing.assert_array_equal(r["point_id"], np.arange(4))
        self.assertEqual(r["rig.drive_speed_m_per_s"].dtype, np.float64)
        np.testing.assert_array_equal(r["rig.drive_speed_m_per_s"], [1e-3, 1e-3, 3e-2, 3e-2])
        self.assertEqual(list(r["status"]), ["ok", "failed", "ok", "failed"])
        self.assertEqual(r["regime"].dtype.kind, "U")
        # Failed points: empty outputs read as NaN, the error names the key.
        self.assertTrue(np.isnan(r["peak_to_peak_m"][[1, 3]]).all())
        self.assertIn("mass_kg", r["error"][1])
        # The ok points against the bindings: results.csv writes 17 digits, so the same doubles.
        for k in (0, 2):
            py = tribo.run_rig(example("rig-coulomb.toml"),
                               overrides={"rig.drive_speed_m_per_s": float(r["rig.drive_speed_m_per_s"][k])})
            s = py["summary"]
            self.assertEqual(r["regime"][k], s["regime"])
            for col in ("peak_to_peak_m", "mu_s_mean", "period_s"):
                self.assertLessEqual(abs(r[col][k] - s[col]), 1e-12 * abs(s[col]), col)
        # A file path works as well as the folder; a missing file is an error.
        self.assertEqual(tribo.read_sweep_results(os.path.join(out, "results.csv"))["status"].tolist(),
                         r["status"].tolist())
        with self.assertRaises(FileNotFoundError):
            tribo.read_sweep_results(os.path.join(d, "nowhere.csv"))

    def test_parsing_rules_on_a_written_file(self):
        d = temp_dir(self)
        path = write_config(d, "results.csv", "point_id,a.b,status,error,wall_s,regime,x_m\n"
                                              "0,1.5,ok,,0.1,stick_slip,2.5e-3\n"
                                              '1,2,failed,"bad, quoted",0.2,,\n')
        r = tribo.read_sweep_results(path)
        np.testing.assert_array_equal(r["a.b"], [1.5, 2.0])
        self.assertEqual(r["x_m"][0], 2.5e-3)
        self.assertTrue(np.isnan(r["x_m"][1]))
        self.assertEqual(r["error"][1], "bad, quoted")
        self.assertEqual(r["regime"].tolist(), ["stick_slip", ""])


class TomlText(unittest.TestCase):
    def test_dumps_round_trips_through_tomllib(self):
        import math
        import tomllib

        doc = {"a": 1, "b": 0.1 + 0.2, "c": "x \"q\" \\ é", "d": [1.5e-300, -2.0], "e": True,
               "t": {"n": 3, "inf": math.inf, "sub": {"k": "v"}},
               "axis": [{"key": "rig.mass_kg", "values": [1.0, 2.0]}, {"key": "a.b", "from": 1e-3}],
               "key with space": 4}
        back = tomllib.loads(tribo.toml_dumps(doc))
        self.assertEqual(back, doc)
        self.assertEqual(back["b"], 0.1 + 0.2)  # the same double, not a rounded one


if __name__ == "__main__":
    unittest.main()
