"""tribo from Python: rough surfaces, BEM contact, Reynolds films, homogenised friction laws,
the friction rig and sweep results, with NumPy arrays in and out.

Conventions
  fields   float64 arrays of shape (nx, ny), a[i, j] = f(x_i, y_j), i along x (the sliding
           direction) — tribo's Eigen layout (contact/grid.h); returned arrays are Fortran-ordered.
  units    SI, named in every argument and key: _m, _Pa, _N, _m_per_s, _s, _per_s, ...
  errors   bad input raises ValueError with tribo's one-line message; a solve that does not
           converge is reported in its summary (converged = False, message), not raised.

Configs: every *_from_toml / run_* function reads a `tribo` config with the CLI's own reader, so
it gives the numbers the CLI writes. The run_* forms also take a dict, and overrides by dotted
key for parameter studies:

    import tribo
    r = tribo.run_rig("examples/rig-coulomb.toml", overrides={"rig.drive_speed_m_per_s": 0.01})
    r["summary"]["regime"], r["summary"]["peak_to_peak_m"], r["trace"]["x_m"]
"""

from ._tribo import (  # noqa: F401  (the compiled module's API, re-exported)
    Grid,
    ReynoldsProblem,
    composite_modulus_Pa,
    contact_from_toml,
    effect_catalogue,
    gap_from_heights,
    gaussian_surface,
    homogenise_from_toml,
    homogenise_patch_from_toml,
    parallel_discs_problem,
    periodic_film_cell,
    radial_psd,
    read_law,
    read_topography,
    reynolds_from_toml,
    reynolds_problem,
    rig_from_toml,
    rough_pair_film,
    solve_contact,
    solve_reynolds,
    sphere_gap,
    surface_statistics,
)
from ._toml_runs import config_file as _config_file
from ._toml_runs import dumps as toml_dumps  # noqa: F401
from .results import read_sweep_results  # noqa: F401


def self_affine_surface(grid, size_m, hurst, rms_height_m=None, rms_slope=None, seed=1,
                        rolloff_wavelength_m=0.0, cutoff_wavelength_m=0.0):
    """Self-affine Gaussian rough surface (m), array (grid, grid) on a periodic square of side size_m:
    PSD flat below the roll-off wavevector, (q/q_r)^(-2(1+H)) up to the cut-off (wavelengths in m,
    0 = none). Give rms_height_m (m) or rms_slope (1)."""
    return gaussian_surface(grid=grid, size_m=size_m, spectrum="self_affine", rms_height_m=rms_height_m,
                            rms_slope=rms_slope, seed=seed, hurst=hurst,
                            rolloff_wavelength_m=rolloff_wavelength_m, cutoff_wavelength_m=cutoff_wavelength_m)


def gaussian_acf_surface(grid, size_m, correlation_length_m, rms_height_m=None, rms_slope=None, seed=1,
                         correlation_length_across_m=0.0):
    """Rough surface (m) with a Gaussian autocorrelation exp(-x²/lx² - y²/ly²): correlation length
    correlation_length_m along x (the lay), correlation_length_across_m along y (0 = isotropic).
    Array (grid, grid) on a periodic square of side size_m. Give rms_height_m (m) or rms_slope (1)."""
    return gaussian_surface(grid=grid, size_m=size_m, spectrum="gaussian_acf", rms_height_m=rms_height_m,
                            rms_slope=rms_slope, seed=seed, correlation_length_m=correlation_length_m,
                            correlation_length_across_m=correlation_length_across_m)


def run_rig(config, overrides=None):
    """One rig run (see rig_from_toml for the returned dict) from a config path or dict, with
    optional overrides by dotted key, e.g. {"rig.drive_speed_m_per_s": 0.01, "friction.mu_s": 0.4}."""
    with _config_file(config, overrides) as (path, _):
        return rig_from_toml(path)


def run_contact(config, overrides=None):
    """`tribo contact` on a config path or dict with optional dotted overrides (see contact_from_toml)."""
    with _config_file(config, overrides) as (path, _):
        return contact_from_toml(path)


def run_reynolds(config, overrides=None):
    """`tribo reynolds` on a config path or dict with optional dotted overrides (see reynolds_from_toml)."""
    with _config_file(config, overrides) as (path, _):
        return reynolds_from_toml(path)


def homogenise_patch(config, realisation=0, overrides=None):
    """One realisation's micro solves of a `tribo homogenise` config (see homogenise_patch_from_toml),
    the per-separation lists returned as float64 arrays."""
    import numpy as np

    with _config_file(config, overrides) as (path, _):
        p = homogenise_patch_from_toml(path, realisation)
    for k, v in p.items():
        if isinstance(v, list) and all(isinstance(x, (int, float)) or x is None for x in v):
            p[k] = np.array([np.nan if x is None else x for x in v], dtype=np.float64)
    return p


def homogenise(config, out_dir, overrides=None, plots=False):
    """`tribo homogenise CONFIG --out out_dir` in-process (resumable through out_dir/patches);
    returns law.json as a dict. With overrides, the patch cache is keyed by the overridden config."""
    with _config_file(config, overrides) as (path, _):
        return homogenise_from_toml(path, out_dir, plots)


# Everything public: the compiled functions and classes and the Python helpers above (not the
# submodules they come from).
__all__ = sorted(name for name, value in globals().items()
                 if not name.startswith("_") and type(value).__name__ != "module")
