#!/usr/bin/python3
"""Reference values for core/ar/expected_spectrum (expected amplitude spectrum of an AR process).

Run with Debian's python3 (python3-numpy 1.24, python3-scipy 1.10):
    /usr/bin/python3 tests/golden/expected_spectrum_golden.py
Writes tests/golden/ar/expected_*.npy (float64, C order). Everything is seeded.

The C++ code takes the autocorrelation from the coefficients (step-down, Levinson) and weights it
with (N - |m|). Here every value comes from the power spectrum P(w) = v / |A(e^jw)|^2 sampled on a
2^20-point grid instead:
  r[m]       inverse FFT of P (aliasing is below 1e-600 for a pole at radius 0.9986), checked
             against v * sum_n h[n] h[n+m] over scipy's impulse response;
  E|X_k|^2   (1/M) sum_j P(w_j) F_N(w_k - w_j), the Fejer kernel F_N = |D_N|^2 of the rectangular
             window: exact on the grid because F_N is a trigonometric polynomial of degree N-1 < M,
             and checked against the (N - m)-weighted cosine sum of r;
  E|X_k|     the mean of a Rayleigh variable (scipy.stats) with E|X_k|^2 = 2 scale^2, times 2/N.
"""
import os

import numpy as np
from scipy.signal import lfilter
from scipy.stats import rayleigh

from ar_golden import random_stable_poly

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ar")
N = 1000            # window samples
BINS = 100          # bins 1..100: 10..1000 Hz at 10 kHz
GRID = 2 ** 20      # frequency grid of the independent route
IMPULSE = 60000     # impulse-response length: 0.9986^60000 ~ 1e-37


def save(name, array):
    np.save(os.path.join(OUT, name), np.ascontiguousarray(array, dtype=np.float64))


def with_pole_pair(a, radius, angle):
    """a times (1 - 2 r cos(w) z^-1 + r^2 z^-2): one more conjugate pole pair."""
    return np.convolve(a, [1.0, -2.0 * radius * np.cos(angle), radius * radius])


def cases(rng):
    """(order, a, v): orders 2, 8, 20; the sharpest pole pairs are HaTT-like (0.99 and 0.9986)."""
    variance = lambda: 10.0 ** rng.uniform(-4.0, 0.0)
    yield 2, with_pole_pair(np.array([1.0]), 0.95, rng.uniform(0.1, 1.0)), variance()
    yield 8, with_pole_pair(random_stable_poly(rng, 6, r_min=0.3, r_max=0.9), 0.99, 2 * np.pi * 0.0213), variance()
    # 373 Hz: between two 10 Hz bins, where the window's leakage matters most.
    yield 20, with_pole_pair(random_stable_poly(rng, 18, r_min=0.3, r_max=0.97), 0.9986, 2 * np.pi * 0.0373), variance()


def power_spectrum_on_grid(a, v):
    return v / np.abs(np.fft.fft(a, GRID)) ** 2


def autocorrelation(a, v, p_grid):
    r = np.fft.ifft(p_grid).real[:N]
    h = lfilter([1.0], a, np.r_[1.0, np.zeros(IMPULSE - 1)])
    r_impulse = v * np.array([h[: IMPULSE - m] @ h[m:] for m in range(N)])
    assert np.max(np.abs(r - r_impulse)) < 1e-11 * r[0], "inverse FFT and impulse response disagree"
    return r


def windowed_power(p_grid):
    w = 2 * np.pi * np.arange(GRID) / GRID
    out = np.empty(BINS)
    for k in range(1, BINS + 1):
        half = 0.5 * (2 * np.pi * k / N - w)
        out[k - 1] = np.sum(p_grid * (np.sin(N * half) / np.sin(half)) ** 2) / GRID
    return out


def cosine_sum(r):
    m = np.arange(1, N)
    return np.array([N * r[0] + 2 * np.sum((N - m) * r[1:] * np.cos(2 * np.pi * k * m / N))
                     for k in range(1, BINS + 1)])


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = np.random.default_rng(20240907)
    for order, a, v in cases(rng):
        assert len(a) == order + 1 and np.max(np.abs(np.roots(a))) < 1.0
        p_grid = power_spectrum_on_grid(a, v)
        r = autocorrelation(a, v, p_grid)
        power = windowed_power(p_grid)
        assert np.max(np.abs(cosine_sum(r) / power - 1.0)) < 1e-10, "Fejer route and cosine sum disagree"
        amplitude = 2.0 / N * rayleigh(scale=np.sqrt(power / 2.0)).mean()
        print(f"order {order}: v {v:.4g}, max pole {np.max(np.abs(np.roots(a))):.4f}, r[0] {r[0]:.4g}, "
              f"power {power.min():.3g}..{power.max():.3g}")
        save(f"expected_model_order{order:02d}.npy", np.r_[a, v])  # coefficients, then variance
        save(f"expected_r_order{order:02d}.npy", r)
        save(f"expected_power_order{order:02d}.npy", power)
        save(f"expected_amplitude_order{order:02d}.npy", amplitude)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
