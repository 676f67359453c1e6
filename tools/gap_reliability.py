#!/usr/bin/env python3
"""How often the gap diagnosis' verdicts were right, from selftest outputs.

    python3 tools/gap_reliability.py DIR [DIR ...]

Each DIR holds a `cases.jsonl` of `tribo gap selftest`. A case (seed and generator) diagnosed in
several DIRs counts once, with the last DIR's row (give them oldest first). Prints the share of
"none" verdicts whose truth was a control — the DiagnosisOptions::none_reliability that turns a
"none" verdict's bootstrap agreement into its confidence — and a reliability table of the verdicts
by their confidence, for the named ("effect") and the "none" verdicts apart; then, per generator,
the share of the withheld effects named by their strength in noise floors (the calibrated
baseline's held-out gap over the noise floor; the bins of gap::detection_table, `detection.csv` of
one set), with the cases whose truth was named or listed beside the verdict (indistinguishable or
alike at one load). Rows of journals without a noise floor are left out of that table.
"""
import json
import sys
from pathlib import Path

BINS = [(0.0, 0.5), (0.5, 0.7), (0.7, 0.8), (0.8, 0.9), (0.9, 1.0001)]
FLOOR_BINS = [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0), (3.0, 5.0), (5.0, 10.0), (10.0, float("inf"))]


def signal_floors(r):
    floor = r.get("noise_floor")
    return r["heldout_gap_before"] / floor if floor else None


def named_or_listed(r):
    beside = (r.get("indistinguishable_from") or []) + (r.get("alike_mechanisms") or [])
    return bool(r["correct"]) or r["true_effect"] in beside


def detection(rows):
    print("generator,signal_floors_from,signal_floors_to,effect_cases,named,named_or_listed")
    for g in sorted({r.get("generator", "rig") for r in rows}):
        effects = [r for r in rows if r.get("generator", "rig") == g and r["true_effect"] != "none" and signal_floors(r) is not None]
        for lo, hi in FLOOR_BINS:
            sel = [r for r in effects if lo <= signal_floors(r) < hi]
            print(f"{g},{lo:g},{hi:g},{len(sel)},{sum(bool(r['correct']) for r in sel)},{sum(named_or_listed(r) for r in sel)}")


def latest_rows(dirs):
    rows = {}
    for d in dirs:
        path = Path(d) / "cases.jsonl"
        if not path.is_file():
            sys.exit(f"{path}: no such file (a tribo gap selftest output directory holds it)")
        for n, line in enumerate(path.read_text().splitlines(), 1):
            try:
                r = json.loads(line)
                rows[(r["seed"], r.get("generator", "rig"))] = r
            except (json.JSONDecodeError, KeyError) as e:
                sys.exit(f"{path}:{n}: not a selftest row ({e})")
    return list(rows.values())


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) >= 2 else 2
    rows = latest_rows(argv[1:])
    nones = [r for r in rows if r["verdict"] == "none"]
    right = sum(r["true_effect"] == "none" for r in nones)
    print(f"{len(rows)} cases; {len(nones)} 'none' verdicts, {right} of them controls"
          + (f": reliability of 'none' {right / len(nones):.3f}" if nones else ""))
    print("kind,confidence_from,confidence_to,verdicts,right")
    for kind, pick in (("effect", lambda r: r["verdict"] != "none"), ("none", lambda r: r["verdict"] == "none")):
        for lo, hi in BINS:
            sel = [r for r in rows if pick(r) and r["confidence"] is not None and lo <= r["confidence"] < hi]
            print(f"{kind},{lo:g},{min(hi, 1.0):g},{len(sel)},{sum(bool(r['correct']) for r in sel)}")
    detection(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
