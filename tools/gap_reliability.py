#!/usr/bin/env python3
"""How often the gap diagnosis' verdicts were right, from selftest outputs.

    python3 tools/gap_reliability.py [--plot PNG] DIR [DIR ...]

Each DIR holds a `cases.jsonl` of `tribo gap selftest`. A case (seed and generator) diagnosed in
several DIRs counts once, with the last DIR's row (give them oldest first). Prints the share of
"none" verdicts whose truth was a control — the DiagnosisOptions::none_reliability that turns a
"none" verdict's bootstrap agreement into its confidence — and a reliability table of the verdicts
by their confidence, for the named ("effect") and the "none" verdicts apart; then, per generator,
the share of the withheld effects named by their strength in noise floors (the calibrated
baseline's held-out gap over the noise floor; the bins of gap::detection_table, `detection.csv` of
one set), with the cases whose truth was named or listed beside the verdict (indistinguishable or
alike at one load), and those named once the test the diagnosis proposed is run: where the selftest
ran a proposed test on the truth (`proposal_checks`), the verdict once its record is seen (`verdict_after`,
as `tribo gap diagnose --test` states it) replaces the verdict — a wrong verdict may be put right so, a
right one overturned; in journals from before that field, the one of the pair nearer the record
where the proposed separation is two noise floors or more. Rows of journals without a noise floor are left out of that table.
Before the tables, the withheld effects named, and those whose truth is among what the verdict adds
to the model (`verdict_adds`: the hardened locus brings the junction locus a model lacks; journals
from before that field, derived from the verdict) — beside the score, not in it.

With --plot PNG (needs matplotlib), both tables drawn: the reliability diagram (share right
against the mean confidence of each bin, with the diagonal a calibrated confidence would follow)
and the share named against the signal, per generator.
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


DECIDING_FLOORS = 2.0  # gap::kDecidingFloors
IMPLIES = {"strain_rate_hardening": ["rate_dependent_static"]}  # rig::EffectInfo::implies, for journals before verdict_adds


def verdict_adds(r):
    """What the verdict adds to the model (gap::Verdict::adds)."""
    if "verdict_adds" in r:
        return r["verdict_adds"]
    if r["verdict"] in ("none", "unexplained"):
        return []
    out = []
    effects = r["verdict"].split("+")
    for e in effects:
        out += [i for i in IMPLIES.get(e, []) if i not in effects and i not in (r.get("model_effects") or []) and i not in out]
        out.append(e)
    return out


def named_after_test(r):
    """Whether the truth is named once the deciding proposed test, if any, has been run."""
    right = bool(r["correct"])
    for k in r.get("proposal_checks") or []:
        if "verdict_after" in k:  # the record's own decision (journals from 2026-12-05 on)
            if k["verdict_after"] is not None:
                right = k["verdict_after"] == r["true_effect"]
        elif k.get("separation_floors") is not None and k["separation_floors"] >= DECIDING_FLOORS:
            right = bool(k["truth_nearer"])
    return right


def detection(rows):
    """Per generator, (lo, hi, cases, named, named or listed, named after the proposed test) of each signal bin."""
    table = {}
    for g in sorted({r.get("generator", "rig") for r in rows}):
        effects = [r for r in rows if r.get("generator", "rig") == g and r["true_effect"] != "none" and signal_floors(r) is not None]
        table[g] = []
        for lo, hi in FLOOR_BINS:
            sel = [r for r in effects if lo <= signal_floors(r) < hi]
            table[g].append((lo, hi, len(sel), sum(bool(r["correct"]) for r in sel), sum(named_or_listed(r) for r in sel),
                             sum(named_after_test(r) for r in sel)))
    return table


def reliability(rows):
    """Per verdict kind, (lo, hi, verdicts, right, mean confidence) of each confidence bin."""
    table = {}
    for kind, pick in (("effect", lambda r: r["verdict"] != "none"), ("none", lambda r: r["verdict"] == "none")):
        table[kind] = []
        for lo, hi in BINS:
            sel = [r for r in rows if pick(r) and r["confidence"] is not None and lo <= r["confidence"] < hi]
            mean = sum(r["confidence"] for r in sel) / len(sel) if sel else None
            table[kind].append((lo, min(hi, 1.0), len(sel), sum(bool(r["correct"]) for r in sel), mean))
    return table


def plot(path, rel, det, n_cases):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.5))
    a.plot([0, 1], [0, 1], color="0.6", lw=1, ls="--", label="calibrated")
    for kind, marker in (("effect", "o"), ("none", "s")):
        pts = [(m, right / n, n) for lo, hi, n, right, m in rel[kind] if n]
        a.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, label="verdict: an effect or unexplained" if kind == "effect" else "verdict: none")
        for x, y, n in pts:
            a.annotate(str(n), (x, y), textcoords="offset points", xytext=(4, -10), fontsize=7)
    a.set(xlim=(0, 1), ylim=(-0.05, 1.02), xlabel="stated confidence (bin mean)", ylabel="share of verdicts right",
          title="Reliability of the confidence (numbers: verdicts)")
    a.legend(loc="lower right", fontsize=8)
    labels = [f"{lo:g}–{hi:g}" if hi != float("inf") else f"≥{lo:g}" for lo, hi in FLOOR_BINS]
    x = range(len(labels))
    for k, (g, bins) in enumerate(det.items()):
        named = [right / n if n else float("nan") for lo, hi, n, right, listed, after in bins]
        listed = [lst / n if n else float("nan") for lo, hi, n, right, lst, after in bins]
        tested = [after / n if n else float("nan") for lo, hi, n, right, lst, after in bins]
        line, = b.plot([i + 0.05 * k for i in x], named, marker="o", label=f"{g}: named")
        b.plot([i + 0.05 * k for i in x], listed, marker="^", ls=":", color=line.get_color(), label=f"{g}: named or listed beside")
        b.plot([i + 0.05 * k for i in x], tested, marker="s", ls="--", color=line.get_color(), label=f"{g}: named after the proposed test")
        for i, (lo, hi, n, right, lst, after) in enumerate(bins):
            if n:
                b.annotate(str(n), (i + 0.05 * k, right / n), textcoords="offset points", xytext=(4, -10), fontsize=7, color=line.get_color())
    b.axhline(0.9, color="0.6", lw=1, ls="--")
    b.set(xticks=list(x), ylim=(-0.05, 1.02), xlabel="signal: calibrated baseline's held-out gap (noise floors)",
          ylabel="share of withheld effects", title="Withheld effects named, by signal (numbers: cases)")
    b.set_xticklabels(labels)
    b.legend(loc="lower right", fontsize=8)
    fig.suptitle(f"Gap diagnosis on its validation sets ({n_cases} cases)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


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
    args, png = argv[1:], None
    if args[0] == "--plot":
        if len(args) < 3:
            sys.exit("--plot needs a PNG path and at least one DIR")
        png, args = args[1], args[2:]
    rows = latest_rows(args)
    nones = [r for r in rows if r["verdict"] == "none"]
    right = sum(r["true_effect"] == "none" for r in nones)
    print(f"{len(rows)} cases; {len(nones)} 'none' verdicts, {right} of them controls"
          + (f": reliability of 'none' {right / len(nones):.3f}" if nones else ""))
    effects = [r for r in rows if r["true_effect"] != "none"]
    print(f"{len(effects)} withheld effects: {sum(bool(r['correct']) for r in effects)} named; "
          f"{sum(r['true_effect'] in verdict_adds(r) for r in effects)} with the truth among what the verdict adds")
    rel, det = reliability(rows), detection(rows)
    print("kind,confidence_from,confidence_to,verdicts,right")
    for kind, bins in rel.items():
        for lo, hi, n, right, _ in bins:
            print(f"{kind},{lo:g},{hi:g},{n},{right}")
    print("generator,signal_floors_from,signal_floors_to,effect_cases,named,named_or_listed,named_after_proposed_test")
    for g, bins in det.items():
        for lo, hi, n, right, listed, after in bins:
            print(f"{g},{lo:g},{hi:g},{n},{right},{listed},{after}")
    if png:
        plot(png, rel, det, len(rows))
        print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
