#!/usr/bin/env python3
"""Plots for tribo outputs (matplotlib, Agg backend).

    tribo_plots.py demo DIR   phase_plane.png, regime_map.png, mu_s_vs_phidot.png, thesis_friction.png
                              from a demo run
    tribo_plots.py rig DIR    phase_plane.png, trace.png from a `tribo rig` run
    tribo_plots.py gap DIR    gap_by_observable.png, items.png, overlay.png from `tribo gap diagnose`
    tribo_plots.py homogenise DIR   stribeck.png, area.png from `tribo homogenise`
    tribo_plots.py ehl DIR [REF]   ehl.png from `tribo ehl`: pressure and film along the contact;
                              with REF, a published solution's centre lines beside them (a folder
                              with pressure_centre_line.csv and film_centre_line.csv, columns x_m and
                              pressure_Pa / film_m, and film_centre_line_measured.csv if measured:
                              tests/lubrication/data/mourier-2006)
    tribo_plots.py sweep DIR  DIR/plots/<column>.png from `tribo sweep`: each output column against
                              the axes (a line for one varying axis, a heat map for two)
    tribo_plots.py stribecks DIR   DIR/plots/stribeck_curves.png from a `tribo sweep` of homogenise
                              points: every point's Stribeck curve (mu, and the film's share of the
                              load) on one plot, labelled by the axes that vary
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REGIME_COLOURS = {
    "stick_slip": "tab:red",
    "multi_cycle_slip": "tab:purple",
    "quasi_harmonic": "tab:green",
    "steady_sliding": "tab:blue",
    "stuck": "tab:gray",
}


def read_csv(path):
    """Rows of a tribo CSV as dicts; leading "# key: value" lines (older CSVs' provenance) are skipped."""
    with open(path, newline="") as f:
        lines = f.readlines()
    start = 0
    while start < len(lines) and lines[start].startswith("#"):
        start += 1
    return list(csv.DictReader(lines[start:]))


def column(rows, name):
    return [float(r[name]) if r[name] != "" else float("nan") for r in rows]


def omega_n(summary_dir):
    """Natural frequency from summary.json when present, else the thesis rig's 101.9 rad/s."""
    import json

    path = os.path.join(summary_dir, "summary.json")
    if os.path.exists(path):
        with open(path) as f:
            return json.load(f)["rig"]["natural_frequency_rad_per_s"]
    return (10367.5 / 0.99822) ** 0.5


def phase_plane(ax, rows, wn, label, t_from=None):
    """Displacement against velocity/omega_n over the last part of a trace (thesis Appendix II)."""
    t = column(rows, "t_s")
    start = t_from if t_from is not None else t[-1] * 0.6
    sel = [i for i, ti in enumerate(t) if ti >= start]
    x = [float(rows[i]["x_m"]) * 1e3 for i in sel]
    v = [float(rows[i]["xdot_m_per_s"]) / wn * 1e3 for i in sel]
    f = [float(rows[i]["friction_N"]) for i in sel]
    ax.plot(x, v, lw=0.8, label="trajectory")
    return x, v, f


def plot_demo(d):
    wn = omega_n(d)
    traces = [
        ("stick_slip_0.028in_per_s.csv", "stick-slip, v = 0.028 in/s (Fig 5.2.1)"),
        ("multi_cycle_1e-4in_per_s.csv", "multi-cycle slip, v = 1e-4 in/s (Fig 5.2.2)"),
        ("quasi_harmonic_5.3in_per_s.csv", "v = 5.3 in/s (Fig 5.2.8)"),
    ]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for ax, (name, title) in zip(axes, traces):
        rows = read_csv(os.path.join(d, "traces", name))
        phase_plane(ax, rows, wn, title)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("displacement x (mm)")
        ax.set_ylabel("velocity / omega_n (mm)")
        ax.grid(alpha=0.3)
    fig.suptitle("Phase-plane traces of the thesis rig (last 40 % of each run)")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "phase_plane.png"), dpi=110)
    plt.close(fig)

    sweep = read_csv(os.path.join(d, "sweep.csv"))
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.6))
    for regime, colour in REGIME_COLOURS.items():
        rs = [r for r in sweep if r["regime"] == regime]
        if not rs:
            continue
        v = column(rs, "v_in_per_s")
        a1.scatter(v, [max(p, 1e-12) * 1e3 for p in column(rs, "peak_to_peak_m")], c=colour, label=regime, s=30)
        a2.scatter(v, column(rs, "mean_mu"), c=colour, label=regime, s=30)
    a1.set_xscale("log")
    a1.set_yscale("log")
    a1.set_xlabel("driven speed v (in/s)")
    a1.set_ylabel("peak-to-peak displacement (mm)")
    a1.set_title("Regime map")
    a2.set_xscale("log")
    a2.set_xlabel("driven speed v (in/s)")
    a2.set_ylabel("mean friction coefficient F/W")
    a2.set_title("Mean friction")
    for a in (a1, a2):
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "regime_map.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6.5, 4.6))
    sf = read_csv(os.path.join(d, "static_friction.csv"))
    ax.scatter(column(sf, "phi_dot_per_s"), column(sf, "mu_s"), s=14, label="simulated breakaways")
    locus_path = os.path.join(d, "junction_locus.csv")
    if os.path.exists(locus_path):
        lc = read_csv(locus_path)
        ax.plot(column(lc, "phi_dot_per_s"), column(lc, "mu_s"), "k-", lw=1, label="locus (3.1.24)")
    ax.scatter([0.0785], [0.26], marker="*", s=140, c="tab:orange", label="thesis: 0.26 at 2.8e-2 in/s")
    ax.axhline(0.55, ls="--", c="gray", lw=0.8, label="upper asymptote 0.55")
    ax.set_xscale("log")
    ax.set_xlabel("load rate phi_dot = k v / W (1/s)")
    ax.set_ylabel("static friction mu_s")
    ax.set_title("Static friction against load rate (thesis Fig 5.1.2)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "mu_s_vs_phidot.png"), dpi=110)
    plt.close(fig)
    plot_thesis_friction(d)


def plot_thesis_friction(d):
    """Friction against speed beside the thesis' chapter-V values: the rig's time-averaged mu at each
    driven speed and, for a homogenised law, its steady-sliding (Stribeck) curve from law/stribeck.csv."""
    inch = 0.0254
    sweep = read_csv(os.path.join(d, "sweep.csv"))
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for regime, colour in REGIME_COLOURS.items():
        rs = [r for r in sweep if r["regime"] == regime]
        if rs:
            ax.scatter(column(rs, "v_m_per_s"), column(rs, "mean_mu"), c=colour, s=22,
                       label="rig mean mu, " + regime.replace("_", " "))
    stribeck = os.path.join(d, "law", "stribeck.csv")
    if os.path.exists(stribeck):
        st = read_csv(stribeck)
        ax.plot(column(st, "U_m_per_s"), column(st, "mu"), "k-", lw=1.2, label="homogenised law, steady sliding")
    ax.scatter([5.3 * inch], [0.15], marker="*", s=160, c="tab:green", edgecolors="k", zorder=5,
               label="thesis: mu_k 0.15 at 5.3 in/s (Fig 5.2.8)")
    ax.scatter([2.8e-2 * inch], [0.26], marker="*", s=160, c="tab:red", edgecolors="k", zorder=5,
               label="thesis: mu_s 0.26 at 2.8e-2 in/s (Fig 5.2.1)")
    ax.axhline(0.03, color="tab:blue", ls=":", lw=1, label="thesis: 0.03 at zero relative speed (5.2a)")
    ax.axvline(1.0 * inch, color="gray", ls="--", lw=0.8, label="thesis: friction maximum at 1 in/s (Fig 5.2.8)")
    ax.set_xscale("log")
    ax.set_xlabel("speed (m/s): driven speed v for the rig, sliding speed U for the law")
    ax.set_ylabel("friction coefficient")
    ax.set_ylim(bottom=0)
    ax.set_title("Friction against speed beside the thesis' observations", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "thesis_friction.png"), dpi=110)
    plt.close(fig)


def plot_rig(d):
    wn = omega_n(d)
    rows = read_csv(os.path.join(d, "trace.csv"))
    fig, (ax, af) = plt.subplots(1, 2, figsize=(11, 4.8))
    phase_plane(ax, rows, wn, "")
    ax.set_xlabel("displacement x (mm)")
    ax.set_ylabel("velocity / omega_n (mm)")
    ax.set_title("Phase plane (last 40 % of the run)")
    ax.grid(alpha=0.3)
    t = column(rows, "t_s")
    late = [i for i, ti in enumerate(t) if ti >= 0.6 * t[-1]]
    af.plot([float(rows[i]["relative_velocity_m_per_s"]) for i in late],
            [float(rows[i]["friction_N"]) for i in late], lw=0.8)
    af.set_xlabel("relative velocity U = v - xdot (m/s)")
    af.set_ylabel("measured friction (N)")
    af.set_title("Friction against relative velocity")
    af.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "phase_plane.png"), dpi=110)
    plt.close(fig)

    t = column(rows, "t_s")
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    a1.plot(t, [x * 1e3 for x in column(rows, "x_m")], lw=0.8)
    a1.set_ylabel("x (mm)")
    a2.plot(t, column(rows, "friction_N"), lw=0.8, label="measured (4.2.3)")
    a2.plot(t, column(rows, "friction_true_N"), lw=0.6, alpha=0.7, label="true")
    a2.set_ylabel("friction (N)")
    a2.set_xlabel("t (s)")
    a2.legend(fontsize=8)
    for a in (a1, a2):
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "trace.png"), dpi=110)
    plt.close(fig)


def plot_gap(d):
    import json

    with open(os.path.join(d, "gap_report.json")) as f:
        rep = json.load(f)
    verdict = rep["verdict"]["effect"]
    verdict = verdict if isinstance(verdict, str) else "+".join(verdict)
    before = rep["baseline"]["by_observable"]
    after = {}
    for c in rep["candidates"]:
        name = c["effect"] if isinstance(c["effect"], str) else "+".join(c["effect"])
        if name == verdict:
            after = c["heldout_after_by_observable"]
    held = rep["baseline"]["heldout"]["by_observable"]
    names = sorted(before)
    fig, ax = plt.subplots(figsize=(max(6, 0.9 * len(names) + 2), 4.5))
    xs = range(len(names))
    ax.bar([x - 0.27 for x in xs], [before[n] for n in names], 0.27, label="baseline, all items")
    ax.bar(list(xs), [held.get(n, float("nan")) for n in names], 0.27, label="baseline, held-out")
    if after:
        ax.bar([x + 0.27 for x in xs], [after.get(n, float("nan")) for n in names], 0.27, label="with " + verdict + ", held-out")
    ax.set_xticks(list(xs))
    ax.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("gap (normalised RMS residual)")
    ax.set_title("Gap by observable (verdict: %s)" % verdict)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "gap_by_observable.png"), dpi=110)
    plt.close(fig)

    items = rep["items"]
    groups = sorted({it["observable"] for it in items})
    fig, axes = plt.subplots(1, len(groups), figsize=(3.2 * len(groups), 3.4), squeeze=False)
    for ax, g in zip(axes[0], groups):
        sel = [it for it in items if it["observable"] == g]
        m = [it["measured"] for it in sel]
        for key, style, label in (("baseline", "o", "baseline"), ("best", "x", "with " + verdict)):
            pts = [(a, it[key]) for a, it in zip(m, sel) if it[key] is not None]
            if pts and not (key == "best" and verdict == "none"):
                ax.plot([p[0] for p in pts], [p[1] for p in pts], style, ms=4, label=label)
        lo, hi = min(m), max(m)
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.6)
        ax.set_title(g, fontsize=9)
        ax.set_xlabel("measured", fontsize=8)
        ax.tick_params(labelsize=7)
    axes[0][0].set_ylabel("simulated")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "items.png"), dpi=110)
    plt.close(fig)

    path = os.path.join(d, "overlay.csv")
    if os.path.exists(path):
        rows = read_csv(path)
        runs = []
        for r in rows:
            if r["run"] not in runs:
                runs.append(r["run"])
        runs = runs[:3]
        effect = "with effect"
        report_path = os.path.join(d, "gap_report.json")
        if os.path.exists(report_path):
            with open(report_path) as f:
                verdict = json.load(f).get("verdict", {})
            name = verdict.get("effect") if isinstance(verdict, dict) else None
            if name and name not in ("none", "unexplained"):
                effect = "with " + name
        if runs:
            # Left: the whole record; right: its last few stick-slip cycles, where the shapes can be
            # compared (a long record at 2 kHz is a solid band at full width).
            fig, axes = plt.subplots(len(runs), 2, figsize=(12, 2.8 * len(runs)), squeeze=False,
                                     gridspec_kw={"width_ratios": [1, 2]})
            for (ax_all, ax_zoom), run in zip(axes, runs):
                traces = {}
                for source in ("measured", "baseline", "with effect"):
                    sel = [r for r in rows if r["run"] == run and r["source"] == source]
                    if sel:
                        traces[source] = (column(sel, "t_s"), column(sel, "mu"))
                if not traces:
                    continue
                ref = traces.get("with effect") or traces.get("baseline") or traces["measured"]
                start = last_cycles_start(*ref, cycles=6)
                for source, lw in (("measured", 0.9), ("baseline", 0.8), ("with effect", 0.8)):
                    if source not in traces:
                        continue
                    t, mu = traces[source]
                    label = effect if source == "with effect" else source
                    ax_all.plot(t, mu, lw=0.5, label=label)
                    keep = [i for i, ti in enumerate(t) if ti >= start]
                    ax_zoom.plot([t[i] for i in keep], [mu[i] for i in keep], lw=lw, label=label)
                ax_all.set_title(run + ", whole record", fontsize=9)
                ax_zoom.set_title(run + ", last cycles", fontsize=9)
                for ax in (ax_all, ax_zoom):
                    ax.set_ylabel("mu")
                    ax.grid(alpha=0.3)
            for ax in axes[-1]:
                ax.set_xlabel("t (s)")
            axes[0][1].legend(fontsize=8)
            fig.tight_layout()
            fig.savefig(os.path.join(d, "overlay.png"), dpi=110)
            plt.close(fig)


def last_cycles_start(t, mu, cycles):
    """Start time of the last `cycles` periods of a trace, the period from its upward crossings of
    the mean over the second half; the whole trace if it has fewer than two crossings."""
    half = [i for i, ti in enumerate(t) if ti >= t[0] + 0.5 * (t[-1] - t[0])]
    if len(half) < 3:
        return t[0]
    mean = sum(mu[i] for i in half) / len(half)
    ups = [t[i] for i, j in zip(half, half[1:]) if mu[i] < mean <= mu[j]]
    if len(ups) < 2:
        return t[0]
    period = (ups[-1] - ups[0]) / (len(ups) - 1)
    return max(t[0], t[-1] - cycles * period)


REGIME_SHADES = {"boundary": "tab:red", "mixed": "tab:orange", "full_film": "tab:blue"}


def plot_homogenise(d):
    """Stribeck curve (mu, the fluid's share of the load and, with asperity-top films, the share of the
    real contact area they separate, against U; regimes shaded) and the load-separation curve."""
    import json

    with open(os.path.join(d, "law.json")) as f:
        law = json.load(f)
    pts = law["stribeck"]
    if pts:
        u = [p["U_m_per_s"] for p in pts]
        # Beside it, μ against the film parameter Λ = h̄/σ where law.json gives it (since 2026-12-03).
        by_film = all("film_parameter" in p for p in pts)
        if by_film:
            fig, (ax, ax_film) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={"width_ratios": [3, 2]})
        else:
            fig, ax = plt.subplots(figsize=(7, 4.5))
        for i, p in enumerate(pts):
            lo = (u[i - 1] * u[i]) ** 0.5 if i > 0 else u[0]
            hi = (u[i] * u[i + 1]) ** 0.5 if i + 1 < len(u) else u[-1]
            ax.axvspan(lo, hi, color=REGIME_SHADES[p["regime"]], alpha=0.08, lw=0)
        ax.semilogx(u, [p["mu"] for p in pts], "k-o", ms=3, label="friction coefficient $\\mu$")
        ax.set_xlabel("sliding speed U (m/s)")
        ax.set_ylabel("$\\mu$")
        ax2 = ax.twinx()
        ax2.semilogx(u, [p["fluid_share"] for p in pts], "b--", label="share of W on the film")
        if any(p.get("film_share_of_contact", 0) > 0 for p in pts):
            ax2.semilogx(u, [p.get("film_share_of_contact", 0) for p in pts], "g:", label="share of $A_r$ the films separate")
            ax2.legend(loc="center left", fontsize=8)
        ax2.set_ylabel("fluid share (load; contact area)", color="b")
        ax2.set_ylim(0, 1.05)
        for name, colour in REGIME_SHADES.items():
            ax.axvspan(0, 0, color=colour, alpha=0.25, label=name.replace("_", " "))
        ax.legend(loc="upper left", fontsize=8)
        pin = law["pin"]
        ax.set_title("Stribeck curve at W = %.4g N, %s pin R = %.4g mm" % (pin["normal_load_N"], pin["shape"],
                                                                        pin["radius_m"] * 1e3), fontsize=10)
        ax.grid(alpha=0.3, which="both")
        if by_film:
            lam = [p["film_parameter"] for p in pts]
            ax_film.plot(lam, [p["mu"] for p in pts], "k-", lw=0.8)
            for p in pts:
                ax_film.plot(p["film_parameter"], p["mu"], "o", ms=4, color=REGIME_SHADES[p["regime"]])
            if max(lam) > 3 * min(lam):  # a log axis where Λ spans more than a factor 3
                ax_film.set_xscale("log")
            ax_film.set_xlabel("film parameter $\\Lambda = \\bar h/\\sigma$")
            ax_film.set_ylabel("$\\mu$")
            ax_film.set_title("against the film parameter (colour: regime)", fontsize=10)
            ax_film.grid(alpha=0.3, which="both")
        fig.tight_layout()
        fig.savefig(os.path.join(d, "stribeck.png"), dpi=110)
        plt.close(fig)
    rows = read_csv(os.path.join(d, "area.csv"))
    h = column(rows, "separation_over_sigma")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogy(h, [max(a, 1e-12) for a in column(rows, "real_area_fraction")], "r-o", ms=3, label="$A_r/A_0$")
    ax.set_xlabel("separation $\\bar h/\\sigma$")
    ax.set_ylabel("real area fraction", color="r")
    ax2 = ax.twinx()
    ax2.semilogy(h, [max(n, 1e-12) for n in column(rows, "solid_load_N")], "k-s", ms=3, label="$N_s$ (N)")
    ax2.set_ylabel("solid load $N_s$ (N)")
    ax2.axhline(law["pin"]["normal_load_N"], color="gray", ls=":", lw=1)
    # the rows' film at the face centre lies a crowned or tilted face's drop above the cells' separation
    sigma = law["cells"]["sigma_m"]
    drop = law["table"]["separation_m"][0] / sigma - law["cells"]["separation_m"][0] / sigma
    ax.set_xlim(drop, min(max(h), drop + 2 * law["cells"]["first_contact_separation_m"] / sigma))
    ax.grid(alpha=0.3, which="both")
    ax.set_title("BEM load and real area against separation (dotted: the pin load)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "area.png"), dpi=110)
    plt.close(fig)


def _number(text):
    try:
        return float(text)
    except ValueError:
        return None


def _file_name(column):
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in column) + ".png"


def plot_sweep(d):
    """One PNG per output column of a sweep against its axes. Axes with a single value are constants
    (shown in the title); one varying axis gives a line (log x when it spans two decades or more), two
    on a full grid of more than three values each give a heat map with the values written in;
    otherwise lines against the varying axis with the most values, one per combination of the others
    (a curve per value of a short axis reads better than a heat map of two or three rows), with error
    bars where the sweep has NAME_standard_error and NAME_discretisation_error columns beside NAME (in
    quadrature). Text columns (the rig's regime) are coloured by category; failed points are blank."""
    import json

    with open(os.path.join(d, "sweep.json")) as f:
        meta = json.load(f)
    with open(os.path.join(d, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    axes = [a["key"] for a in meta["axes"]]
    fields = list(rows[0].keys()) if rows else []
    outputs = [o["column"] for o in meta.get("outputs", [])] or fields[fields.index("wall_s") + 1:]
    outputs.append("wall_s")
    varying = [a for a in meta["axes"] if len(set(a["values"])) > 1]
    constants = ", ".join("%s = %g" % (a["key"], a["values"][0]) for a in meta["axes"] if len(set(a["values"])) == 1)
    ok = [r for r in rows if r["status"] == "ok"]
    out_dir = os.path.join(d, "plots")
    os.makedirs(out_dir, exist_ok=True)
    written = []

    def log_scale(values):
        v = [x for x in values if x > 0]
        return len(v) == len(values) and max(v) / min(v) >= 100

    for col in outputs:
        values = [r[col] for r in ok]
        numeric = all(_number(v) is not None for v in values if v != "")
        fig, ax = plt.subplots(figsize=(7, 4.8))
        import textwrap

        title = col + ("\n" + "\n".join(textwrap.wrap(constants, 80)) if constants else "")
        if not varying:
            ax.text(0.5, 0.5, "\n".join("%s" % v for v in values), ha="center", va="center")
        elif len(varying) == 2 and meta.get("combine", "product") == "product" and min(len(set(a["values"])) for a in varying) > 3:
            xa, ya = varying[0]["key"], varying[1]["key"]
            xs = sorted(set(float(r[xa]) for r in rows))
            ys = sorted(set(float(r[ya]) for r in rows))
            cats = sorted(set(v for v in values if v != "")) if not numeric else []
            grid = [[float("nan")] * len(xs) for _ in ys]
            text = [[""] * len(xs) for _ in ys]
            for r in rows:
                i, j = ys.index(float(r[ya])), xs.index(float(r[xa]))
                v = r[col] if r["status"] == "ok" else ""
                if v == "":
                    text[i][j] = "failed" if r["status"] != "ok" else ""
                elif numeric:
                    grid[i][j] = float(v)
                    text[i][j] = "%.3g" % float(v)
                else:
                    grid[i][j] = cats.index(v)
                    text[i][j] = v.replace("_", "\n")
            if numeric:
                im = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis")
                fig.colorbar(im, ax=ax, label=col)
            else:
                from matplotlib.colors import ListedColormap

                colours = [REGIME_COLOURS.get(c, "C%d" % k) for k, c in enumerate(cats)]
                ax.imshow(grid, origin="lower", aspect="auto", cmap=ListedColormap(colours or ["white"]),
                          vmin=-0.5, vmax=max(len(cats), 1) - 0.5, alpha=0.6)
            finite = [v for line in grid for v in line if v == v]
            lo, hi = (min(finite), max(finite)) if finite else (0.0, 1.0)
            for i in range(len(ys)):
                for j in range(len(xs)):
                    # white on viridis' dark lower half, black on its light upper half
                    dark = numeric and grid[i][j] == grid[i][j] and hi > lo and (grid[i][j] - lo) / (hi - lo) < 0.5
                    ax.text(j, i, text[i][j], ha="center", va="center", fontsize=8, color="white" if dark else "black")
            ax.set_xticks(range(len(xs)))
            ax.set_xticklabels(["%g" % x for x in xs])
            ax.set_yticks(range(len(ys)))
            ax.set_yticklabels(["%g" % y for y in ys])
            ax.set_xlabel(xa)
            ax.set_ylabel(ya)
        else:
            longest = max(varying, key=lambda a: len(set(a["values"])))
            xa = longest["key"]
            others = [a["key"] for a in varying if a is not longest]
            groups = {}
            for r in ok:
                groups.setdefault(tuple(r[o] for o in others), []).append(r)
            cats = sorted(set(v for v in values if v != "")) if not numeric else []
            for key, rs in sorted(groups.items()):
                rs.sort(key=lambda r: float(r[xa]))
                x = [float(r[xa]) for r in rs]
                y = [(float(r[col]) if r[col] != "" else float("nan")) if numeric else cats.index(r[col]) for r in rs]
                label = ", ".join("%s = %s" % (o, "%g" % _number(k) if _number(k) is not None else k) for o, k in zip(others, key)) or None
                errors = [c for c in (col + "_standard_error", col + "_discretisation_error") if c in fields]
                if numeric and errors:
                    # error bar: the ensemble's standard error and the discretisation error in quadrature
                    # (an unknown one, empty in the CSV, counts 0)
                    yerr = [sum((_number(r[c]) or 0.0) ** 2 for c in errors) ** 0.5 for r in rs]
                    ax.errorbar(x, y, yerr=yerr, fmt="o-", capsize=3, label=label)
                else:
                    ax.plot(x, y, "o-" if numeric else "o", label=label)
            if not numeric:
                ax.set_yticks(range(len(cats)))
                ax.set_yticklabels(cats)
            if log_scale([float(r[xa]) for r in rows]):
                ax.set_xscale("log")
            ax.set_xlabel(xa)
            ax.set_ylabel(col)
            if others:
                ax.legend(fontsize=7)
            ax.grid(alpha=0.3, which="both")
        ax.set_title(title, fontsize=9)
        fig.tight_layout()
        path = os.path.join(out_dir, _file_name(col))
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    print("\n".join(written))


def plot_stribecks(d):
    """The Stribeck curves of a sweep's homogenise points (points/NNNNN/law.json, or
    points/NNNNN/homogenise/law.json of a homogenise → rig chain) over each other: mu
    (solid, left axis) and the film's share of the load (dashed, right axis) against U, one colour per
    point, labelled by the axes whose values vary. Points that failed are left out."""
    with open(os.path.join(d, "sweep.json")) as f:
        meta = json.load(f)
    with open(os.path.join(d, "results.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    varying = [a["key"] for a in meta["axes"] if len(set(a["values"])) > 1]
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    ax2 = ax.twinx()
    # one colour per point, in the order of the axes' values (viridis: dark for the smallest)
    colours = [plt.cm.viridis(k / max(len(rows) - 1, 1) * 0.9) for k in range(len(rows))]
    for k, r in enumerate(sorted(rows, key=lambda r: [_number(r[a]) or 0.0 for a in varying])):
        point = os.path.join(d, "points", "%05d" % int(r["point_id"]))
        chained = os.path.join(point, "homogenise", "law.json")  # a homogenise → rig chain's first link
        with open(chained if os.path.exists(chained) else os.path.join(point, "law.json")) as f:
            pts = json.load(f)["stribeck"]
        u = [p["U_m_per_s"] for p in pts]
        label = ", ".join("%s = %s" % (a, "%g" % _number(r[a]) if _number(r[a]) is not None else r[a]) for a in varying) or None
        ax.semilogx(u, [p["mu"] for p in pts], "-", color=colours[k], label=label)
        ax2.semilogx(u, [p["fluid_share"] for p in pts], "--", color=colours[k], lw=1)
    ax.set_xlabel("sliding speed U (m/s)")
    ax.set_ylabel("$\\mu$ (solid)")
    ax2.set_ylabel("share of W on the film (dashed)")
    ax2.set_ylim(0, 1.05)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3, which="both")
    if varying:
        ax.legend(fontsize=8, loc="lower left")
    ax.set_title("Stribeck curves of %s" % os.path.basename(os.path.normpath(d)), fontsize=10)
    fig.tight_layout()
    out_dir = os.path.join(d, "plots")
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "stribeck_curves.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(path)


def plot_ehl(d, reference=None):
    """Pressure (GPa) and film (um) along the contact, x over the Hertz half-width (a point contact:
    its radius, along the centre line y = 0, beside a map of the film), with the dry Hertz pressure
    and the published central-film fits for comparison — and, given a reference folder, a published
    solution's centre lines (and a measured film, where the folder has one) as points."""
    import numpy as np

    with open(os.path.join(d, "ehl.json")) as f:
        s = json.load(f)
    point = s.get("geometry") == "point"
    b, p_h = (s["hertz_radius_m"] if point else s["hertz_half_width_m"]), s["hertz_pressure_Pa"]
    x = np.load(os.path.join(d, "x_m.npy")) / b
    p = np.load(os.path.join(d, "pressure_Pa.npy"))
    h = np.load(os.path.join(d, "film_m.npy"))
    if point:
        y = np.load(os.path.join(d, "y_m.npy")) / b
        centre = int(np.argmin(np.abs(y)))
        fig, (ax, ax_map) = plt.subplots(1, 2, figsize=(12, 4.2), gridspec_kw={"width_ratios": [1.4, 1]})
        # levels up to 3 h_c, so the horseshoe of the constriction shows (the rim's film is far thicker)
        im = ax_map.contourf(x, y, (h * 1e6).T, levels=np.linspace(0, 3 * s["central_film_m"] * 1e6, 25), cmap="viridis", extend="max")
        ax_map.contour(x, y, p.T, levels=[1e-3 * p_h], colors="white", linewidths=0.8)
        fig.colorbar(im, ax=ax_map, label="film (um)")
        ax_map.set_aspect("equal")
        ax_map.set_xlabel("x / a (rolling direction)")
        ax_map.set_ylabel("y / a")
        ax_map.set_title("film; white: the pressurised zone's edge", fontsize=9)
        p, h = p[:, centre], h[:, centre]
    else:
        fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(x, p / 1e9, color="tab:red", label="pressure")
    inside = np.abs(x) <= 1
    ax.plot(x[inside], p_h * np.sqrt(1 - x[inside] ** 2) / 1e9, "--", color="tab:red", lw=0.8, label="dry Hertz")
    ax.set_xlabel(("x / a (Hertz radius %.3g um), y = 0" if point else "x / b (Hertz half-width %.3g um)") % (b * 1e6))
    ax.set_ylabel("pressure (GPa)", color="tab:red")
    film = ax.twinx()
    film.plot(x, h * 1e6, color="tab:blue", label="film")
    fits = (("hamrock_dowson_central_film_m", ":"),) if point else (("pan_hamrock_central_film_m", ":"), ("dowson_toyoda_central_film_m", "-."))
    for key, style in fits:
        film.axhline(s["fits"][key] * 1e6, color="tab:blue", ls=style, lw=0.8, label=key.replace("_central_film_m", " h_c"))
    if reference is not None:
        name = os.path.basename(os.path.normpath(reference))
        # (file, column, scale, axis, marker, colour, label, required)
        curves = (("pressure_centre_line.csv", "pressure_Pa", 1e-9, ax, "o", "tab:red", "pressure", True),
                  ("film_centre_line.csv", "film_m", 1e6, film, "s", "tab:blue", "film", True),
                  ("film_centre_line_measured.csv", "film_m", 1e6, film, "x", "tab:green", "film measured", False))
        for file, col, scale, axis, marker, colour, label, required in curves:
            path = os.path.join(reference, file)
            if not required and not os.path.exists(path):
                continue
            rows = read_csv(path)
            axis.plot([float(r["x_m"]) / b for r in rows], [float(r[col]) * scale for r in rows], marker, ms=3.5,
                      mfc="none", color=colour, label="%s, %s" % (label, name))
    film.set_ylabel("film (um)", color="tab:blue")
    film.set_ylim(0, 4 * s["central_film_m"] * 1e6)
    mu = s.get("friction_coefficient")
    ax.set_title("EHL %s contact: h_c %.3g um, h_min %.3g um, p_max %.3g GPa%s" % (
        "point" if point else "line", s["central_film_m"] * 1e6, s["minimum_film_m"] * 1e6, s["max_pressure_Pa"] / 1e9,
        "" if mu is None else ", mu %.3g" % mu), fontsize=9)
    lines = ax.get_legend_handles_labels()[0] + film.get_legend_handles_labels()[0]
    ax.legend(lines, [ln.get_label() for ln in lines], fontsize=8, loc="upper left")
    fig.tight_layout()
    path = os.path.join(d, "ehl.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(path)


def main(argv):
    modes = {"demo": plot_demo, "rig": plot_rig, "gap": plot_gap, "homogenise": plot_homogenise, "sweep": plot_sweep,
             "stribecks": plot_stribecks, "ehl": plot_ehl}
    if not (len(argv) == 3 and argv[1] in modes or len(argv) == 4 and argv[1] == "ehl"):
        sys.stderr.write(__doc__)
        return 2
    modes[argv[1]](*argv[2:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
