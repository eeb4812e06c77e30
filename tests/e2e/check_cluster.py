#!/usr/bin/python3
"""Recomputes a converted Cluster take with numpy/scipy and compares it with haptex's recordings file.

    check_cluster.py RECORDINGS.h5 MATERIAL_ID K ACCEL.csv FORCE.csv
The acceleration and the force go through numpy.interp onto a 6 kHz grid from the first stamp all
files share, then scipy.signal.resample_poly(x, 5, 3, padtype='mean'); acceleration in g times
9.80665. Prints "cluster ok" or what differs, exit code 1.
"""
import sys

import h5py
import numpy as np
import scipy.signal as sig


def load(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def to_10k(t, x, start, end, n):
    grid = start + np.arange(int(np.floor((end - start) * 6000.0)) + 1) / 6000.0
    return sig.resample_poly(np.interp(grid, t, x), 5, 3, padtype="mean")[:n]


path, material, k, accel_csv, force_csv = sys.argv[1:6]
accel, force = load(accel_csv), load(force_csv)
with h5py.File(path, "r") as f:
    g = f[f"materials/{material}/recordings/{k}"]
    xyz, fn = g["accel_xyz"][...].astype(np.float64), g["force_normal"][...].astype(np.float64)
    problems = []
    if g.attrs["sample_rate_hz"] != 10000.0:
        problems.append(f"sample rate {g.attrs['sample_rate_hz']}")
    position_start = float(np.genfromtxt(g.attrs["position_source_file"], delimiter=",", names=True)["time"][0])
    position_end = float(np.genfromtxt(g.attrs["position_source_file"], delimiter=",", names=True)["time"][-1])
start = max(accel["time"][0], force["time"][0], position_start)
end = min(accel["time"][-1], force["time"][-1], position_end)
n = xyz.shape[0]
for c, axis in enumerate("XYZ"):
    expected = to_10k(accel["time"], accel[axis], start, end, n) * 9.80665
    error = np.max(np.abs(xyz[:, c] - expected)) / max(1e-9, np.max(np.abs(expected)))
    if expected.size != n or error > 1e-6:
        problems.append(f"accel {axis}: scaled error {error:.3g}")
expected = to_10k(force["time"], force["force"], start, end, n)
error = np.max(np.abs(fn - expected)) / np.max(np.abs(expected))
if error > 1e-6:
    problems.append(f"force: scaled error {error:.3g}")
print("\n".join(problems) if problems else "cluster ok")
sys.exit(1 if problems else 0)
