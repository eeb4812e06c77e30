#!/usr/bin/python3
"""Reference values for haptex train's smoothed training targets (predict/target_smoothing.cpp,
docs/predict.md "Smoothed training targets"), from the documented definition with numpy, in float64.

Run with Debian's python3 (python3-numpy 1.24):
    /usr/bin/python3 tests/golden/target_smoothing_golden.py
Writes tests/golden/target_smoothing/*.npy (float64, C order):
  input.npy     (W, 100) spectra, one window a row as python's Windows.target holds them (haptex's
                Eigen matrix is its transpose, bins x windows); every value a float32, so C++ and
                Python start from the same numbers
  bins_N.npy    (W, 100) the input smoothed over N = 1, 3, 5, 7, 9 and 201 bins (wider
                than the band: every bin a weighted mean of all 100)
The definition, written independently of both implementations: each bin becomes the mean of the bins
within N // 2 of it weighted 1, 2, .., N // 2 + 1, .., 2, 1 (a triangle), over the bins that exist,
the weights renormalised at the band's ends: x @ K.T / K.sum(1), K[b, j] = max(0, N // 2 + 1 - |j - b|).
The generator is seeded, so re-running reproduces the committed files.
"""
import os

import numpy as np

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "target_smoothing")
BINS = (1, 3, 5, 7, 9, 201)


def save(name, array):
    array = np.ascontiguousarray(array, dtype=np.float64)
    np.save(os.path.join(OUT, name + ".npy"), array)


def spectra(rng):
    """Window-like amplitude spectra: a smooth level times Rayleigh scatter, a narrow resonance, a
    spectrum of zeros, one with a single non-zero bin at each end, and a large one."""
    f = np.arange(1, 101) * 10.0
    level = 0.5 + 2.0 * np.exp(-((f - 250.0) / 150.0) ** 2)
    rows = [level * rng.rayleigh(np.sqrt(2 / np.pi), 100) for _ in range(6)]
    resonance = level.copy()
    resonance[40] += 20.0
    edges = np.zeros(100)
    edges[0], edges[-1] = 3.0, 5.0
    rows += [resonance, np.zeros(100), edges, 1e4 * level]
    return np.asarray(rows, dtype=np.float32).astype(np.float64)


def smoothed(x, bins):
    b = np.arange(x.shape[1])
    kernel = np.maximum(0, bins // 2 + 1 - np.abs(b[None, :] - b[:, None])).astype(np.float64)
    return x @ kernel.T / kernel.sum(axis=1)


def main():
    os.makedirs(OUT, exist_ok=True)
    x = spectra(np.random.default_rng(20240607))
    save("input", x)
    for bins in BINS:
        save(f"bins_{bins}", smoothed(x, bins))


if __name__ == "__main__":
    main()
