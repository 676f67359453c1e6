"""tools/slip_speed_profile.py bins a trace's friction by the slider's slip speed U = v − ẋ: on a
made-up record whose friction is a known step in U, each quarter-decade bin holds the samples and
the mean μ put there and the time they stand for (the record's own sampling times), the slips are counted once each despite the velocity channel's noise, and the
lift's excess is the closed form μk f_max exp(−(U/U_s)^n). A trace without ẋ, or a run the bundle
does not hold, is refused (exit 2)."""

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

from helpers import SOURCE_DIR

TOOL = os.path.join(SOURCE_DIR, "tools", "slip_speed_profile.py")


def write_bundle(root, rows, columns="t_s,xdot_m_per_s,friction_N"):
    os.makedirs(os.path.join(root, "traces"))
    with open(os.path.join(root, "experiment.toml"), "w") as f:
        f.write("[rig]\nnormal_load_N = 100.0\n")
    with open(os.path.join(root, "runs.csv"), "w") as f:
        f.write("run_id,v_m_per_s,file\n0,0.01,traces/run_0.csv\n")
    with open(os.path.join(root, "traces", "run_0.csv"), "w") as f:
        f.write(columns + "\n" + "".join(",".join(f"{x:.9g}" for x in r) + "\n" for r in rows))


def three_cycles(stuck, stuck_dt_s, slip_dt_s, noise_m_per_s):
    """Three stick-slip cycles at v = 10 mm/s: `stuck` samples (ẋ = v ± the noise, alternating; μ = 0.2)
    `stuck_dt_s` apart, then 10 samples at U = 0.05 m/s (μ 0.15) and 10 at U = 0.2 m/s (μ 0.1),
    `slip_dt_s` apart and `slip_dt_s` after the last stuck sample."""
    rows, t = [], 0.0
    for _ in range(3):
        for i in range(stuck):
            rows.append((t, 0.01 + (noise_m_per_s if i % 2 else -noise_m_per_s), 20.0))
            t += stuck_dt_s if i < stuck - 1 else slip_dt_s
        for u, mu in ((0.05, 0.15), (0.2, 0.10)):
            for _ in range(10):
                rows.append((t, 0.01 - u, 100.0 * mu)); t += slip_dt_s
    return rows


def profile(rows):
    """The tool's output on a one-run bundle of `rows`, and its bins by their lower edge."""
    with tempfile.TemporaryDirectory() as root:
        write_bundle(root, rows)
        out = subprocess.run([sys.executable, TOOL, root], capture_output=True, text=True, check=True).stdout
    return out, {line.split(",")[0]: line.split(",")[2:] for line in out.splitlines() if line[0].isdigit()}


class SlipSpeedProfile(unittest.TestCase):
    def test_bins_friction_by_slip_speed_and_counts_each_slip_once(self):
        # 1 ms apart; ẋ's noise ±0.5 mm/s while stuck.
        out, bins = profile(three_cycles(20, 1e-3, 1e-3, 0.0005))
        self.assertIn("run 0, v_drive = 0.01 m/s, 3 slips", out)
        # U = 0.05 lies in [0.0316, 0.0562), U = 0.2 in [0.178, 0.316); the stuck samples' U = ±0.5 mm/s
        # fall in [0.000316, 0.000562) (the positive half) or are left out (U ≤ 0.1 mm/s).
        self.assertEqual(bins["0.0316"], ["30", "0.1500", "10.00"])
        self.assertEqual(bins["0.178"], ["30", "0.1000", "10.00"])
        self.assertEqual(bins["0.000316"][:2], ["30", "0.2000"])

    def test_time_per_slip_is_the_records_own_for_a_record_sampled_densely_in_slip(self):
        # Stuck every 5 ms (12 samples), slipping every 0.5 ms: each slip sample stands for 0.5 ms, so
        # 5 ms per slip in each bin — the mean spacing (196 ms over 95 intervals) would have put 21 ms there.
        _, bins = profile(three_cycles(12, 5e-3, 0.5e-3, 0.0))
        self.assertEqual(bins["0.0316"], ["30", "0.1500", "5.00"])
        self.assertEqual(bins["0.178"], ["30", "0.1000", "5.00"])

    def test_lift_excess_is_the_closed_form_and_a_trace_without_xdot_is_refused(self):
        truth = {"parameters": {"coulomb.mu_k": 0.2, "lift.max_fraction": 0.5, "lift.stribeck_speed_m_per_s": 0.025,
                                "lift.exponent": 1.5}}
        with tempfile.TemporaryDirectory() as root:
            write_bundle(root, [(0.0, 0.01, 20.0), (1e-3, 0.01, 20.0)])
            with open(os.path.join(root, "truth.json"), "w") as f:
                json.dump(truth, f)
            out = subprocess.run([sys.executable, TOOL, root, "--truth", os.path.join(root, "truth.json")],
                                 capture_output=True, text=True, check=True).stdout
            self.assertIn(f"0.05,{0.2 * 0.5 * math.exp(-(2.0 ** 1.5)):.5f}", out)  # 0.00591
            bad = os.path.join(root, "bad")
            write_bundle(bad, [(0.0, 20.0), (1e-3, 20.0)], columns="t_s,friction_N")
            run = subprocess.run([sys.executable, TOOL, bad], capture_output=True, text=True)
        self.assertEqual(run.returncode, 2)
        self.assertIn("no xdot_m_per_s column", run.stderr)

    def test_a_run_the_bundle_does_not_hold_is_refused(self):
        with tempfile.TemporaryDirectory() as root:
            write_bundle(root, [(0.0, 0.01, 20.0), (1e-3, 0.01, 20.0)])
            run = subprocess.run([sys.executable, TOOL, root, "--run", "7"], capture_output=True, text=True)
        self.assertEqual(run.returncode, 2)
        self.assertIn("runs.csv: no run_id 7", run.stderr)
        self.assertEqual(run.stdout, "")


if __name__ == "__main__":
    unittest.main()
