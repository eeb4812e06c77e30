#!/usr/bin/python3
"""Reference values for tests/evaluate (spectral distance, Welch's t-test, percentiles), from
numpy/scipy; tests/golden/render_golden.py writes the render module's (reconstruction).

Run with Debian's python3 (python3-scipy 1.10, python3-numpy 1.24):
    /usr/bin/python3 tests/golden/evaluate_golden.py
Writes tests/golden/evaluate/*.npy (float64, C order). Every generator is seeded, so re-running
reproduces the committed files.
"""
import os
import warnings

import numpy as np
import scipy
import scipy.stats as stats
from scipy.stats._stats_py import _unequal_var_ttest_denom

from render_golden import texture_like

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "evaluate")
N, HOP = 1000, 100  # the distance's window and step


def save(name, array):
    array = np.ascontiguousarray(np.asarray(array, dtype=np.float64))
    np.save(os.path.join(OUT, name + ".npy"), array)


# --- spectral distance ---------------------------------------------------------------------

def amplitude_spectra(x):
    starts = range(0, len(x) - N + 1, HOP)
    return np.array([2 * np.abs(np.fft.rfft(x[s:s + N]))[1:101] / N for s in starts])


def distance_cases(rng):
    for tag, n in (("10000", 10000), ("12345", 12345), ("1000", 1000)):
        truth = texture_like(rng, n)
        rendered = 0.8 * texture_like(rng, n) + 0.1 * rng.standard_normal(n)
        save(f"distance_truth_{tag}", truth)
        save(f"distance_rendered_{tag}", rendered)
        save(f"distance_windows_{tag}", np.linalg.norm(amplitude_spectra(rendered) - amplitude_spectra(truth), axis=1))
    a = np.abs(rng.standard_normal((5, 100)))
    b = np.abs(rng.standard_normal((5, 100)))
    save("spectra_a", a)
    save("spectra_b", b)
    save("spectra_distance", np.linalg.norm(a - b, axis=1))
    # The model's float32 predictions: the values are float32, the distance is taken in double.
    a32 = a.astype(np.float32).astype(np.float64)
    b32 = (b * 1.7).astype(np.float32).astype(np.float64)
    save("spectra_a_f32", a32)
    save("spectra_b_f32", b32)
    save("spectra_distance_f32", np.linalg.norm(a32 - b32, axis=1))


# --- Welch's t-test and percentiles ---------------------------------------------------------

SLEEP_1 = [0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0]  # R's sleep data, t.test(extra ~ group)
SLEEP_2 = [1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4]


def welch_cases(rng):
    return {
        "sleep": (SLEEP_1, SLEEP_2),
        "docs_equal": (rng.normal(5, 10, 500), rng.normal(5, 10, 500)),
        "docs_unequal": (rng.normal(5, 10, 500), rng.normal(8, 20, 100)),
        "one_zero_variance": ([3.0, 3.0, 3.0, 3.0], [1.0, 2.0, 3.0, 4.0, 6.0]),
        "both_zero_equal": ([2.0, 2.0, 2.0], [2.0, 2.0, 2.0, 2.0]),
        "both_zero_unequal": ([2.0, 2.0, 2.0], [3.0, 3.0, 3.0, 3.0]),
        "tiny": ([1.0, 2.0], [3.0, 5.0]),
        "unequal_n": (rng.normal(0.3, 1, 3), rng.normal(0, 2, 2000)),
        "huge_t": (rng.standard_normal(101) + 62.0, rng.standard_normal(101)),  # p near 1e-300
        "identical": ([1.5, 2.5, -0.5, 4.0], [1.5, 2.5, -0.5, 4.0]),
    }


def welch_reference(a, b):
    """[t, df, p, mean_a, mean_b] as scipy computes them (df: scipy's Welch-Satterthwaite, 1 for 0/0)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # scipy's note on the zero-variance cases
        result = stats.ttest_ind(a, b, equal_var=False)
        df, _ = _unequal_var_ttest_denom(np.var(a, ddof=1), len(a), np.var(b, ddof=1), len(b))
    return [result.statistic, df, result.pvalue, np.mean(a), np.mean(b)]


def statistics_cases(rng):
    for name, (a, b) in welch_cases(rng).items():
        save(f"welch_{name}_a", a)
        save(f"welch_{name}_b", b)
        save(f"welch_{name}_expected", welch_reference(a, b))
    q = [0, 25, 50, 75, 100, 10, 33.3, 90, 99.9, 12.5]
    save("percentile_q", q)
    samples = {
        "one": [4.2],
        "two": [3.0, -1.0],
        "ties": [5.0, 1.0, 5.0, 2.0, 2.0, 5.0, 9.0],
        "ten": rng.standard_normal(10),
        "many": rng.standard_normal(1001) * 3 + 2,
    }
    for name, x in samples.items():
        save(f"percentile_{name}_x", x)
        save(f"percentile_{name}_expected", np.percentile(x, q))
        save(f"quartiles_{name}_expected", np.percentile(x, [25, 50, 75]))
        save(f"mean_{name}_expected", [np.mean(x)])


# Each group draws from its own seeded generator, so adding a case to one group leaves the
# others' files unchanged (seed 3 is render_golden.py's).
GROUPS = ((distance_cases, 1), (statistics_cases, 2))

if __name__ == "__main__":
    assert scipy.__version__.startswith("1.10"), scipy.__version__
    os.makedirs(OUT, exist_ok=True)
    for group, seed in GROUPS:
        group(np.random.default_rng(seed))
