#!/usr/bin/python3
"""Reference values for tests/evaluate (spectral distance, Welch's t-test, percentiles, the
reconstruction frames, spectral convergence, fast Griffin-Lim and RTISI-LA), from numpy/scipy.

Run with Debian's python3 (python3-scipy 1.10, python3-numpy 1.24):
    /usr/bin/python3 tests/golden/evaluate_golden.py
Writes tests/golden/evaluate/*.npy (float64, C order). Every generator is seeded, so re-running
reproduces the committed files.

The reconstruction references are written from the algorithms' definitions over whole-signal
arrays (every frame kept, frames placed by index), a different route from the C++ code's
buffers and slots.
"""
import os
import warnings

import numpy as np
import scipy
import scipy.signal as sig
import scipy.stats as stats
from scipy.stats._stats_py import _unequal_var_ttest_denom

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "evaluate")
FS = 10000.0
N, HOP, BINS = 1000, 100, 501
FLOOR = 0.375  # evaluate/target_magnitudes.hpp kSynthesisWeightFloor
WINDOW = sig.get_window("hann", N)


def save(name, array):
    array = np.ascontiguousarray(np.asarray(array, dtype=np.float64))
    np.save(os.path.join(OUT, name + ".npy"), array)


def texture_like(rng, n):
    """AR-filtered noise (8 resonators, 80..1500 Hz) whose variance follows a stroke's speed."""
    t = np.arange(n) / FS
    sos = []
    for f, r in zip((80, 150, 230, 310, 420, 600, 900, 1500), (0.995, 0.99, 0.99, 0.985, 0.98, 0.98, 0.97, 0.96)):
        sos.append([1, 0, 0, 1, -2 * r * np.cos(2 * np.pi * f / FS), r * r])
    speed = 70 + 50 * np.sin(2 * np.pi * 0.7 * t)
    y = sig.sosfilt(np.array(sos), rng.standard_normal(n) * np.sqrt(speed / 70))
    return y / np.std(y)


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


# --- reconstruction frames ------------------------------------------------------------------

def stft_magnitudes(x):
    frames = 1 + (len(x) - N) // HOP
    return np.abs(np.array([np.fft.rfft(WINDOW * x[m * HOP:m * HOP + N]) for m in range(frames)]))


def gains(frames, length):
    weight = np.zeros(length)
    for m in range(frames):
        weight[m * HOP:m * HOP + N] += WINDOW ** 2
    return 1 / np.maximum(weight, FLOOR)


def with_magnitude(c, s):
    mag = np.abs(c)
    return np.where(mag > 0, c * (s / np.where(mag > 0, mag, 1)), s)


def overlap_add(windowed_frames, length):
    x = np.zeros(length)
    for m, frame in enumerate(windowed_frames):
        x[m * HOP:m * HOP + N] += frame
    return x


def fast_griffin_lim(s, iterations, alpha, length):
    """FGLA from zero phase: t = c_n - alpha/(1+alpha) c_{n-1}, c_0 = 0; least-squares inverse."""
    frames = s.shape[0]
    covered = (frames - 1) * HOP + N
    g = gains(frames, covered)

    def synthesize(t):
        return overlap_add(np.fft.irfft(with_magnitude(t, s), N, axis=1) * WINDOW, covered) * g

    t, previous = s.astype(complex), np.zeros(s.shape, complex)
    for _ in range(iterations):
        x = synthesize(t)
        c = np.array([np.fft.rfft(WINDOW * x[m * HOP:m * HOP + N]) for m in range(frames)])
        t, previous = c - alpha / (1 + alpha) * previous, c
    out = np.zeros(length)
    x = synthesize(t)
    out[:min(length, covered)] = x[:min(length, covered)]
    return out


def rtisi_la(s, look_ahead, iterations):
    """RTISI-LA over whole-signal arrays; returns every emitted sample in order (pushes, then flush)."""
    frames = s.shape[0]
    covered = (frames - 1) * HOP + N
    stored = np.zeros((frames, N))  # Hann-windowed frame estimates
    successors = np.zeros(N)
    for i in range(1, N // HOP):
        successors[i * HOP:] += WINDOW[:N - i * HOP]

    def overlay(f):
        out = np.zeros(N)
        for g in range(max(0, f - N // HOP + 1), min(frames, f + N // HOP)):
            d = (g - f) * HOP
            if d >= 0:
                out[d:] += stored[g][:N - d]
            else:
                out[:N + d] += stored[g][-d:]
        return out

    def finished(n, last_frame):
        total = sum(stored[g][n - g * HOP] for g in range(last_frame + 1) if 0 <= n - g * HOP < N)
        weight = sum(WINDOW[n - g * HOP] ** 2 for g in range(last_frame + 1) if 0 <= n - g * HOP < N)
        return total / max(weight, FLOOR)

    out = []
    for m in range(frames + look_ahead):  # steps from frames on: flush, no new frame
        for it in range(iterations):
            for f in range(m, m - look_ahead - 1, -1):
                if f < 0 or f >= frames:
                    continue
                window = WINDOW
                if f == m and m < frames:
                    window = successors if it == 0 else successors + WINDOW
                c = np.fft.rfft(overlay(f) * window)
                stored[f] = np.fft.irfft(with_magnitude(c, s[f]), N) * WINDOW
        done = m - look_ahead
        if done >= 0:
            out.extend(finished(n, done) for n in range(done * HOP, done * HOP + HOP))
    out.extend(finished(n, frames - 1) for n in range(frames * HOP, covered))
    return np.array(out)


def reconstruction_cases(rng):
    amplitudes = np.abs(rng.standard_normal((4, 100)))
    save("target_amplitudes", amplitudes)
    magnitudes = np.zeros((4, BINS))
    magnitudes[:, 1:101] = np.sqrt(np.mean(WINDOW ** 2)) * N / 2 * amplitudes
    save("target_magnitudes", magnitudes)

    x = texture_like(rng, 3000)  # 21 frames
    s = stft_magnitudes(x)
    save("reconstruction_x", x)
    save("reconstruction_s", s)
    y = x + 0.05 * rng.standard_normal(len(x))
    save("convergence_y", y)
    save("convergence_db", [20 * np.log10(np.linalg.norm(stft_magnitudes(y) - s) / np.linalg.norm(s))])
    save("fgla_0p99_5", fast_griffin_lim(s, 5, 0.99, 3000))
    save("fgla_0_5", fast_griffin_lim(s, 5, 0.0, 3000))
    save("fgla_0p99_3_short", fast_griffin_lim(s, 3, 0.99, 2500))
    save("fgla_0p99_3_long", fast_griffin_lim(s, 3, 0.99, 3400))
    for look_ahead, iterations in ((2, 2), (0, 3), (3, 1)):
        save(f"rtisila_{look_ahead}_{iterations}", rtisi_la(s, look_ahead, iterations))
    short = s[:2]  # a stream shorter than the look-ahead
    save("rtisila_short_s", short)
    save("rtisila_3_2_short", rtisi_la(short, 3, 2))


# Each group draws from its own seeded generator, so adding a case to one group leaves the
# others' files unchanged.
GROUPS = ((distance_cases, 1), (statistics_cases, 2), (reconstruction_cases, 3))

if __name__ == "__main__":
    assert scipy.__version__.startswith("1.10"), scipy.__version__
    os.makedirs(OUT, exist_ok=True)
    for group, seed in GROUPS:
        group(np.random.default_rng(seed))
