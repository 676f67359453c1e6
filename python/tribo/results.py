"""Reading `tribo sweep` results (results.csv) into NumPy arrays."""

import csv
import math
import os

import numpy as np


def _column(values):
    """A column as float64 (empty fields NaN) when every non-empty field is a number, else str."""
    numbers = []
    for v in values:
        if v == "":
            numbers.append(math.nan)
            continue
        try:
            numbers.append(float(v))
        except ValueError:
            return np.array(values, dtype=str)
    return np.array(numbers, dtype=np.float64)


def read_sweep_results(path):
    """Read a sweep's results.csv (or the sweep's --out folder) into a dict of NumPy arrays.

    Leading lines starting with '#' (the provenance of CSVs written before 2026-11-27) are skipped.

    One array per column, in the file's column order, one entry per point (sorted by point id as
    the finished sweep writes it): point_id as int64; axis columns (named by their dotted config
    key, e.g. "rig.drive_speed_m_per_s") and output columns as float64, with NaN where the field is
    empty (an observable that does not exist, or a failed point); text columns (status "ok" /
    "failed", error, regime) as str. Units are those in the column names (SI).
    """
    if os.path.isdir(path):
        path = os.path.join(path, "results.csv")
    with open(path, newline="") as f:
        # Older CSVs began with "# key: value" provenance lines (README "Provenance of outputs").
        reader = csv.reader(line for line in f if not line.startswith("#"))
        try:
            header = next(reader)
        except StopIteration:
            raise ValueError(f"{path}: empty file, no header") from None
        rows = [r for r in reader if r]
    for k, r in enumerate(rows):
        if len(r) != len(header):
            raise ValueError(f"{path}: row {k + 2} has {len(r)} fields, the header {len(header)}")
    out = {}
    for c, name in enumerate(header):
        col = _column([r[c] for r in rows])
        if name == "point_id" and col.dtype == np.float64:
            col = col.astype(np.int64)
        out[name] = col
    return out
