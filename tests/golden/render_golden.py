#!/usr/bin/python3
"""Reference values for tests/render (the reconstruction frames, spectral convergence, fast
Griffin-Lim and RTISI-LA), from numpy/scipy.

Run with Debian's python3 (python3-scipy 1.10, python3-numpy 1.24):
    /usr/bin/python3 tests/golden/render_golden.py
Writes tests/golden/render/*.npy (float64, C order). The generator is seeded, so re-running
reproduces the committed files.

The reconstruction references are written from the algorithms' definitions over whole-signal
arrays (every frame kept, frames placed by index), a different route from the C++ code's
buffers and slots.
"""
import os

import numpy as np
import scipy
import scipy.signal as sig

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render")
FS = 10000.0
N, HOP, BINS = 1000, 100, 501
FLOOR = 0.375  # render/target_magnitudes.hpp kSynthesisWeightFloor
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


if __name__ == "__main__":
    assert scipy.__version__.startswith("1.10"), scipy.__version__
    os.makedirs(OUT, exist_ok=True)
    # The seed this group had in evaluate_golden.py, before the render module: the files stay the same.
    reconstruction_cases(np.random.default_rng(3))
