"""tools/gap_reliability.py pools the journals of several selftest sets: a case diagnosed in two
sets counts once (the later row), and the detection table bins the withheld effects by their signal
in noise floors as gap::detection_table does (tests/gap/selftest_summary_test.cpp holds the same
bins), the truth named or listed beside the verdict counted apart."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

from helpers import SOURCE_DIR

TOOL = os.path.join(SOURCE_DIR, "tools", "gap_reliability.py")


def case(seed, truth, verdict, floors, confidence=0.5, beside=(), generator="independent", checks=()):
    return {"seed": seed, "generator": generator, "true_effect": truth, "verdict": verdict, "correct": truth == verdict,
            "confidence": confidence, "noise_floor": 0.02, "heldout_gap_before": 0.02 * floors,
            "indistinguishable_from": [], "alike_mechanisms": list(beside),
            "proposal_checks": [{"against": a, "test": "heavier_load", "separation_floors": f, "truth_nearer": t} for a, f, t in checks]}


class GapReliability(unittest.TestCase):
    def test_pools_sets_and_bins_effects_by_signal(self):
        old = [case(1, "squeeze_film", "none", 0.5), case(2, "instrument", "instrument", 12.0)]
        # Seed 1's proposed test decides for the truth; seed 3's separates the pair by too little to count;
        # seed 6's overturns a right verdict.
        new = [case(1, "squeeze_film", "rate_dependent_static", 2.5, beside=["squeeze_film"],
                    checks=[("squeeze_film", 6.8, True)]),  # replaces seed 1
               case(3, "thermal_thinning", "hydrodynamic_lift", 4.0, checks=[("thermal_thinning", 1.5, True)]),
               case(6, "rate_dependent_static", "rate_dependent_static", 3.5, checks=[("squeeze_film", 2.5, False)]),
               # Seed 7's record kept the wrong verdict although the proposal promised 4 floors; seed 8's put it right.
               dict(case(7, "instrument", "squeeze_film", 5.5, checks=[("instrument", 4.0, True)]),
                    proposal_checks=[{"against": "instrument", "separation_floors": 4.0, "truth_nearer": True, "verdict_after": "squeeze_film"}]),
               dict(case(8, "instrument", "squeeze_film", 6.0),
                    proposal_checks=[{"against": "instrument", "separation_floors": 1.0, "truth_nearer": True, "verdict_after": "instrument"}]),
               case(4, "none", "none", 0.8, confidence=0.7),
               case(5, "slip_transient", "slip_transient", 0.3, generator="rig")]
        with tempfile.TemporaryDirectory() as root:
            dirs = []
            for name, rows in (("a", old), ("b", new)):
                os.mkdir(os.path.join(root, name))
                with open(os.path.join(root, name, "cases.jsonl"), "w") as f:
                    f.writelines(json.dumps(r) + "\n" for r in rows)
                dirs.append(os.path.join(root, name))
            out = subprocess.run([sys.executable, TOOL, *dirs], capture_output=True, text=True, check=True).stdout
        self.assertIn("8 cases; 1 'none' verdicts, 1 of them controls", out)
        self.assertIn("7 withheld effects: 3 named; 3 with the truth among what the verdict adds", out)
        table = {tuple(line.split(",")[:3]): tuple(int(x) for x in line.split(",")[3:])
                 for line in out.splitlines() if line.startswith(("independent,", "rig,"))}
        self.assertEqual(table[("independent", "2", "3")], (1, 0, 1, 1))   # seed 1 from set b: listed, named after its test
        self.assertEqual(table[("independent", "3", "5")], (2, 1, 1, 0))   # seed 3 stays wrong, seed 6 is overturned
        self.assertEqual(table[("independent", "5", "10")], (2, 0, 0, 1))   # seeds 7 and 8: the record's decision counts
        self.assertEqual(table[("independent", "10", "inf")], (1, 1, 1, 1))
        self.assertEqual(table[("independent", "0", "1")], (0, 0, 0, 0))   # set a's row of seed 1 is gone; controls stay out
        self.assertEqual(table[("rig", "0", "1")], (1, 1, 1, 1))

    def test_plot_draws_both_tables_into_a_png(self):
        rows = [case(1, "instrument", "instrument", 12.0, confidence=0.95), case(2, "none", "none", 0.4, confidence=0.7),
                case(3, "squeeze_film", "rate_dependent_static", 6.0, confidence=0.3)]
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "cases.jsonl"), "w") as f:
                f.writelines(json.dumps(r) + "\n" for r in rows)
            png = os.path.join(root, "reliability.png")
            out = subprocess.run([sys.executable, TOOL, "--plot", png, root], capture_output=True, text=True, check=True).stdout
            with open(png, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertIn("wrote " + png, out)
        self.assertIn("effect,0.9,1,1,1", out)   # the instrument, named at 95 %: right
        self.assertIn("effect,0,0.5,1,0", out)   # the film taken for ageing at 30 %: wrong
        self.assertIn("none,0.7,0.8,1,1", out)

    def test_the_truth_among_what_the_verdict_adds_is_counted_beside_the_score(self):
        # Kato's ageing named the hardened locus on a model without the locus (a journal from before
        # verdict_adds: derived, the locus brought); the same verdict on a model with the locus adds the
        # hardening alone; a pair holding the truth; a journal that states what was added.
        rows = [case(1, "rate_dependent_static", "strain_rate_hardening", 9.0),
                dict(case(2, "rate_dependent_static", "strain_rate_hardening", 9.0), model_effects=["rate_dependent_static"]),
                case(3, "squeeze_film", "thermal_thinning+squeeze_film", 4.0),
                dict(case(4, "rate_dependent_static", "strain_rate_hardening", 9.0), verdict_adds=["strain_rate_hardening"]),
                case(5, "none", "none", 0.8)]
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "cases.jsonl"), "w") as f:
                f.writelines(json.dumps(r) + "\n" for r in rows)
            out = subprocess.run([sys.executable, TOOL, root], capture_output=True, text=True, check=True).stdout
        self.assertIn("4 withheld effects: 0 named; 2 with the truth among what the verdict adds", out)

    def test_plot_without_a_directory_is_refused(self):
        run = subprocess.run([sys.executable, TOOL, "--plot", "x.png"], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--plot needs a PNG path", run.stderr)


if __name__ == "__main__":
    unittest.main()
