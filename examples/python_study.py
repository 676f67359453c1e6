"""A notebook-style tour of tribo from Python: surface → contact → film → rig → sweep results.

Run from the repository root after building (the module lives in the build tree):

    PYTHONPATH=build/python /usr/bin/python3 examples/python_study.py

or with the package installed by `pip install .` (README, Python): `.venv/bin/python examples/python_study.py`.

Each cell prints what a notebook would show; the optional plot needs python3-matplotlib and is
written to out/python_study.png.
"""

import os

import numpy as np

import tribo

HERE = os.path.dirname(os.path.abspath(__file__))

# %% 1. A rough surface: the thesis disc (Rq 0.43 µm), self-affine, 1 mm periodic patch at 128².
n, size_m = 128, 1e-3
heights_m = tribo.self_affine_surface(n, size_m, hurst=0.8, rms_height_m=4.3e-7, seed=1,
                                      rolloff_wavelength_m=6.25e-5, cutoff_wavelength_m=1.5625e-5)
stats = tribo.surface_statistics(heights_m, size_m)
print(f"surface: {heights_m.shape} array, Rq {stats['rq_m'] * 1e6:.3f} µm, rms slope {stats['rms_slope']:.4f}")

# %% 2. Real contact area against load: elastic-plastic BEM (E* steel on steel, hardness 1.18 GPa).
gap0_m = tribo.gap_from_heights(heights_m)
print("load (N)  area fraction  iterations  converged")
for load_N in (0.1, 0.3, 1.0, 3.0):
    r = tribo.solve_contact(gap0_m, size_m, e_star_Pa=1.137e11, normal_load_N=load_N, hardness_Pa=1.18e9)
    s = r["summary"]
    print(f"{load_N:7.2f}  {r['area_fraction']:13.4f}  {s['iterations']:10d}  {s['converged']}")
pressure_Pa = r["pressure_Pa"]  # (n, n) array at the last load; pressure_Pa[i, j] at x = i·L/n, y = j·L/n

# %% 3. The lubricated rough pair at 0.1 m/s: a film pressed by 0.5 N of solid load, JFO cavitation.
lower = tribo.gaussian_acf_surface(64, size_m, correlation_length_m=6.25e-5, rms_height_m=4.3e-7, seed=1)
upper = tribo.gaussian_acf_surface(64, size_m, correlation_length_m=6.25e-5, rms_height_m=6.4e-8, seed=2)
film = tribo.rough_pair_film(upper, lower, size_m, normal_load_N=0.5, contact_gap_fraction=0.1)
problem = film["problem"]
problem.viscosity_Pa_s = 0.021
problem.sliding_speed_m_per_s = 0.1
problem.cavitation = "mass_conserving"  # the cell comes with nothing but the film set
sol = tribo.solve_reynolds(problem)
print(f"film: mean {film['mean_film_m'] * 1e6:.3f} µm, fluid load {sol['load_N']:.4g} N on the patch, "
      f"cavitated {sol['cavitated_fraction']:.3f}, Newton {sol['summary']['iterations']}, "
      f"converged {sol['summary']['converged']}")

# %% 4. The same through a CLI config (identical numbers to `tribo reynolds`).
squeeze = tribo.run_reynolds(os.path.join(HERE, "reynolds-parallel-discs.toml"), overrides={"grid.n": 96})
print(f"squeeze film: {squeeze['summary']['load_N']:.4g} N, Appendix III {squeeze['summary']['reference_load_N']:.4g} N")

# %% 5. The rig: regime and amplitude against driven speed (each run is `tribo rig` with one key changed).
print("speed (m/s)  regime            peak-to-peak (mm)  mean mu_s")
speeds = np.logspace(-3, 0, 7)
amplitude_m = []
for v in speeds:
    run = tribo.run_rig(os.path.join(HERE, "rig-coulomb.toml"), overrides={"rig.drive_speed_m_per_s": float(v)})
    s = run["summary"]
    amplitude_m.append(s["peak_to_peak_m"])
    mu = "" if s["mu_s_mean"] is None else f"{s['mu_s_mean']:.3f}"
    print(f"{v:11.4g}  {s['regime']:16s}  {s['peak_to_peak_m'] * 1e3:17.4f}  {mu}")
trace = run["trace"]  # time series of the last run: t_s, x_m, xdot_m_per_s, friction_N, ...

# %% 6. Sweep results written by `tribo sweep` (if one has been run): one NumPy array per column.
results_csv = os.path.join(HERE, "..", "out", "sweep-rig", "results.csv")
if os.path.exists(results_csv):
    table = tribo.read_sweep_results(results_csv)
    ok = table["status"] == "ok"
    print(f"sweep: {len(table['point_id'])} points, {ok.sum()} ok; columns {list(table)}")

# %% 7. A figure, when matplotlib is there.
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    plt = None
if plt is not None:
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    im = ax[0].imshow(pressure_Pa.T / 1e9, origin="lower", extent=[0, size_m * 1e3, 0, size_m * 1e3])
    ax[0].set(title="contact pressure (GPa), 3 N", xlabel="x (mm)", ylabel="y (mm)")
    fig.colorbar(im, ax=ax[0])
    ax[1].plot(trace["t_s"], trace["x_m"] * 1e3)
    ax[1].set(title=f"rig at {speeds[-1]:.3g} m/s", xlabel="t (s)", ylabel="x (mm)")
    ax[2].loglog(speeds, amplitude_m, "o-")
    ax[2].set(title="peak-to-peak against speed", xlabel="drive speed (m/s)", ylabel="x p-p (m)")
    fig.tight_layout()
    os.makedirs(os.path.join(HERE, "..", "out"), exist_ok=True)
    png = os.path.join(HERE, "..", "out", "python_study.png")
    fig.savefig(png, dpi=110)
    print(f"figure -> {os.path.normpath(png)}")
