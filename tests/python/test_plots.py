"""tools/tribo_plots.py on a sweep of homogenise points: `stribecks` draws every point's Stribeck
curve from its law.json (a plain point's or a homogenise → rig chain's), `sweep` each column against
the axis. A hand-made sweep folder in the layout `tribo sweep` writes (docs/sweep.md); each mode
must exit 0 and write a PNG. Needs matplotlib (Debian's python3-matplotlib)."""

import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

from helpers import SOURCE_DIR

PLOTS = os.path.join(SOURCE_DIR, "tools", "tribo_plots.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def law(mu_scale):
    """A law.json with only what the Stribeck plot reads: three speeds, μ and the film's share."""
    speeds = [1e-5, 1e-3, 1e-1]
    return {"stribeck": [{"U_m_per_s": u, "mu": mu_scale * (0.19 - 0.5 * u), "fluid_share": min(1.0, 5.0 * u)}
                         for u in speeds]}


def write_sweep(root):
    """Two points over pin.tilt_rad: point 0 as a plain homogenise point, point 1 as a chain's."""
    axes = [{"key": "pin.tilt_rad", "values": [0.0, 1e-4]}, {"key": "homogenise.realisations", "values": [1.0]}]
    with open(os.path.join(root, "sweep.json"), "w") as f:
        json.dump({"axes": axes, "combine": "product",
                   "outputs": [{"column": "mu_2", "file": "law.json", "path": "stribeck.2.mu"}]}, f)
    rows = []
    for k, tilt in enumerate([0.0, 1e-4]):
        folder = os.path.join(root, "points", "%05d" % k, *(["homogenise"] if k == 1 else []))
        os.makedirs(folder)
        with open(os.path.join(folder, "law.json"), "w") as f:
            json.dump(law(1.0 - 0.5 * k), f)
        rows.append({"point_id": k, "pin.tilt_rad": tilt, "homogenise.realisations": 1, "status": "ok", "error": "",
                     "wall_s": 1.0, "mu_2": law(1.0 - 0.5 * k)["stribeck"][2]["mu"]})
    with open(os.path.join(root, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


class SweepPlots(unittest.TestCase):
    def run_mode(self, mode, root):
        done = subprocess.run([sys.executable, PLOTS, mode, root], capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        return done.stdout.split()

    def assertPng(self, path):
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), PNG_SIGNATURE, path)

    def test_stribecks_draws_plain_and_chained_points_on_one_plot(self):
        with tempfile.TemporaryDirectory() as root:
            write_sweep(root)
            written = self.run_mode("stribecks", root)
            self.assertEqual(written, [os.path.join(root, "plots", "stribeck_curves.png")])
            self.assertPng(written[0])

    def test_sweep_draws_each_column_against_the_axis(self):
        with tempfile.TemporaryDirectory() as root:
            write_sweep(root)
            written = self.run_mode("sweep", root)
            self.assertEqual(sorted(os.path.basename(p) for p in written), ["mu_2.png", "wall_s.png"])
            for path in written:
                self.assertPng(path)


if __name__ == "__main__":
    unittest.main()
