#!/usr/bin/python3
"""Reference values for tests/core/signal_resample_test.cpp, from numpy/scipy.

Run with Debian's python3 (python3-scipy 1.10, python3-numpy 1.24):
    /usr/bin/python3 tests/golden/resample_golden.py
Writes tests/golden/resample/*.npy (float64). Seeded: re-running reproduces the committed files to the
last bit of the machine's libm.
"""
import os

import numpy as np
import scipy.signal as sig

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "resample")
# (up, down): 6 kHz -> 10 kHz (the Cluster database), 10 kHz -> 6 kHz, 44.1 kHz -> 10 kHz, 2x, and a
# ratio that is not in lowest terms.
RATIOS = [(5, 3), (3, 5), (100, 441), (2, 1), (10, 6)]


def save(name, array):
    array = np.ascontiguousarray(array, dtype=np.float64)
    np.save(os.path.join(OUT, name + ".npy"), array)


def vibration(rng, t):
    """An accelerometer-like trace: gravity on the axis (DC), tones up to near Nyquist, noise."""
    return (-0.96 + 0.3 * np.sin(2 * np.pi * 180 * t) + 0.2 * np.sin(2 * np.pi * 1300 * t + 0.3)
            + 0.1 * np.sin(2 * np.pi * 2900 * t) + 0.05 * rng.standard_normal(t.size))


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = np.random.default_rng(20261126)
    x = vibration(rng, np.arange(997) / 6000.0)
    save("poly_x", x)
    for up, down in RATIOS:
        save(f"poly_{up}_{down}", sig.resample_poly(x, up, down, padtype="mean"))
    save("kaiser_101_0p2", sig.firwin(101, 0.2, window=("kaiser", 5.0)))
    # Irregular stamps as the Cluster database's logs: steps of 0.21 and 0.13 ms in turn, jittered.
    steps = np.where(np.arange(1500) % 2 == 0, 0.21e-3, 0.13e-3) * (1 + 0.05 * rng.standard_normal(1500))
    times = 0.000999 + np.concatenate(([0.0], np.cumsum(steps[:-1])))
    values = vibration(rng, times)
    save("irregular_t", times)
    save("irregular_x", values)
    grid = times[0] + np.arange(int(np.floor((times[-1] - times[0]) * 6000.0)) + 1) / 6000.0
    uniform = np.interp(grid, times, values)
    save("irregular_uniform_6000", uniform)
    save("irregular_10000", sig.resample_poly(uniform, 5, 3, padtype="mean"))
    # A CSV's stamps: the grid at their own mean rate, whole Hz (docs/convert.md).
    own = int(round((times.size - 1) / (times[-1] - times[0])))
    grid = times[0] + np.arange(int(np.floor((times[-1] - times[0]) * own)) + 1) / own
    save("irregular_own_rate", np.array([own], dtype=np.float64))
    save("irregular_own_rate_10000", sig.resample_poly(np.interp(grid, times, values), 10000, own, padtype="mean"))
    # A source at a prime rate near the 1 MHz limit: a 20-million-tap filter (review 9, F8). The input is
    # tones only, so the test computes it itself.
    t = np.arange(60000) / 999983.0
    save("poly_10000_999983", sig.resample_poly(-0.96 + 0.3 * np.sin(2 * np.pi * 180 * t) + 0.2 * np.sin(2 * np.pi * 1300 * t + 0.3),
                                                10000, 999983, padtype="mean"))


if __name__ == "__main__":
    main()
