#!/usr/bin/env python3
"""Friction against the slider's slip speed in a bundle's stick-slip traces.

    python3 tools/slip_speed_profile.py BUNDLE [--run ID] [--truth truth.json]

For every constant-speed trace with the columns t_s, xdot_m_per_s and friction_N (or mu) of a
bundle (gap/bundle.h), the slip speed U = v_drive − ẋ (m/s; 0 while the slider sticks to the disc)
and μ = F / W, binned in U by quarter decades from 0.1 mm/s: per bin the number of samples, their
mean μ, and the time a slip spends there (ms per slip, a slip counted where U passes 20 mm/s;
each sample standing for the time until the next, so that a record sampled densely in slip and
sparsely in stick is weighed by its own times). A velocity-dependent friction law shows
as μ changing with U; where a bin's time per slip is a few samples, the record's anti-alias filter
and the breakaway's and re-attachment's jumps decide what it shows there.

With --truth (a `tribo gap generate` truth.json of the independent generator's exponential Stribeck
lift), the lift's excess over its saturated level, μk f_max exp(−(U/U_s)^n), at 30, 50, 70 and
100 mm/s: what of the lift a slip shows away from its ends.
"""
import argparse
import csv
import json
import math
import sys
import tomllib
from pathlib import Path


def read_bundle_runs(bundle):
    runs = []
    with open(bundle / "runs.csv", newline="") as f:
        for row in csv.DictReader(f):
            runs.append((row["run_id"], float(row["v_m_per_s"]), bundle / row["file"]))
    with open(bundle / "experiment.toml", "rb") as f:
        load = tomllib.load(f).get("rig", {}).get("normal_load_N")
    return runs, load


def profile(trace, v, load_N):
    with open(trace, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "xdot_m_per_s" not in rows[0]:
        raise ValueError(f"{trace}: no xdot_m_per_s column")
    t = [float(r["t_s"]) for r in rows]
    if "mu" in rows[0]:
        mu = [float(r["mu"]) for r in rows]
    else:
        if not load_N:
            raise ValueError(f"{trace}: friction_N needs [rig] normal_load_N in experiment.toml")
        mu = [float(r["friction_N"]) / load_N for r in rows]
    speed = [v - float(r["xdot_m_per_s"]) for r in rows]
    # Each sample holds until the next (the last for as long as the interval before it).
    share = [t[i + 1] - t[i] for i in range(len(t) - 1)] + [t[-1] - t[-2] if len(t) > 1 else 0.0]
    # A slip starts where U passes 20 mm/s after it was below 5 mm/s: far outside the sensor noise
    # of ẋ (about 1 mm/s in the independent generator's records), which crosses a single level often.
    slips, stuck = 0, True
    for u in speed:
        if stuck and u > 0.02:
            slips, stuck = slips + 1, False
        elif u < 0.005:
            stuck = True
    bins = {}
    for u, m, dt in zip(speed, mu, share):
        if u <= 1e-4:
            continue
        k = math.floor(4 * math.log10(u))
        n, s, time = bins.get(k, (0, 0.0, 0.0))
        bins[k] = (n + 1, s + m, time + dt)
    return bins, max(slips, 1)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bundle", type=Path)
    parser.add_argument("--run", help="one run_id (default: every run)")
    parser.add_argument("--truth", type=Path, help="truth.json of an exponential Stribeck lift")
    a = parser.parse_args(argv)
    try:
        runs, load = read_bundle_runs(a.bundle)
        if a.run is not None and a.run not in (r[0] for r in runs):
            raise ValueError(f"{a.bundle / 'runs.csv'}: no run_id {a.run}")
        for run_id, v, trace in runs:
            if a.run is not None and run_id != a.run:
                continue
            bins, slips = profile(trace, v, load)
            print(f"run {run_id}, v_drive = {v:g} m/s, {slips} slips")
            print("U_from_m_per_s,U_to_m_per_s,samples,mean_mu,ms_per_slip")
            for k in sorted(bins):
                n, s, time = bins[k]
                print(f"{10 ** (k / 4):.3g},{10 ** ((k + 1) / 4):.3g},{n},{s / n:.4f},{1e3 * time / slips:.2f}")
        if a.truth:
            p = json.loads(a.truth.read_text())["parameters"]
            mu_k, f_max = p["coulomb.mu_k"], p["lift.max_fraction"]
            u_s, n = p["lift.stribeck_speed_m_per_s"], p["lift.exponent"]
            print("U_m_per_s,lift_excess_mu")
            for u in (0.03, 0.05, 0.07, 0.1):
                print(f"{u:g},{mu_k * f_max * math.exp(-((u / u_s) ** n)):.5f}")
    except (OSError, KeyError, ValueError) as e:
        print(f"slip_speed_profile: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
