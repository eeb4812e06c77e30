#!/usr/bin/python3
"""Reference values for tests/core/signal_*_test.cpp, from numpy/scipy.

Run with Debian's python3 (python3-scipy 1.10, python3-numpy 1.24):
    /usr/bin/python3 tests/golden/signal_golden.py
Writes tests/golden/signal/*.npy (float64 or complex128, C order). Every generator is seeded,
so re-running reproduces the committed files.
"""
import os

import numpy as np
import scipy
import scipy.signal as sig

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "signal")
FS = 10000.0
BUTTER_ORDERS = range(1, 9)
BUTTER_WN = {"0p004": 0.004, "0p35": 0.35}


def save(name, array):
    array = np.ascontiguousarray(array)
    assert array.dtype in (np.float64, np.complex128), (name, array.dtype)
    np.save(os.path.join(OUT, name + ".npy"), array)


def force_like(rng, n):
    """A positive normal-force trace: 2 N, slow wander, noise and 100-300 Hz ripple."""
    t = np.arange(n) / FS
    wander = np.cumsum(rng.standard_normal(n)) * 2e-3
    wander -= np.linspace(wander[0], wander[-1], n)  # keep it bounded
    ripple = 0.08 * np.sin(2 * np.pi * 150 * t) + 0.05 * np.sin(2 * np.pi * 270 * t + 0.4)
    return 2.0 + 0.5 * np.sin(2 * np.pi * 0.7 * t) + wander + ripple + 0.05 * rng.standard_normal(n)


def fft_cases(rng):
    for tag, n in (("even", 1000), ("odd", 999)):
        x = rng.standard_normal(n)
        save(f"fft_x_{tag}", x)
        save(f"fft_rfft_{tag}", np.fft.rfft(x))
        spectrum = rng.standard_normal(n // 2 + 1) + 1j * rng.standard_normal(n // 2 + 1)
        save(f"fft_spectrum_{tag}", spectrum)
        save(f"fft_irfft_{tag}", np.fft.irfft(spectrum, n))


def butter_cases(rng):
    x = force_like(rng, 2000)
    save("filt_x", x)
    for tag, wn in BUTTER_WN.items():
        filtered = []
        for order in BUTTER_ORDERS:
            sos = sig.butter(order, wn, output="sos")
            save(f"butter_{order}_{tag}", sos)
            save(f"sosfilt_zi_{order}_{tag}", sig.sosfilt_zi(sos))
            filtered.append(sig.sosfiltfilt(sos, x))
        save(f"sosfiltfilt_{tag}", np.array(filtered))  # row order-1
    # One plain forward pass with a steady-state start, as sosfiltfilt's first pass does.
    sos = sig.butter(4, 0.35, output="sos")
    y, _ = sig.sosfilt(sos, x, zi=sig.sosfilt_zi(sos) * x[0])
    save("sosfilt_4_0p35", y)
    # The design's action filter on a 10 s recording.
    long_x = force_like(rng, 100000)
    save("force_long_x", long_x)
    save("force_long_filtered", sig.sosfiltfilt(sig.butter(4, 20, fs=FS, output="sos"), long_x))


def combine(spectra):
    """DFT321 of one spectrum per axis (axis 0): the axes' energy, the phase of their sum."""
    magnitude = np.sqrt(np.sum(np.abs(spectra) ** 2, axis=0))
    return magnitude * np.exp(1j * np.angle(np.sum(spectra, axis=0)))


def dft321_whole_recording(axes):
    return np.fft.irfft(combine(np.fft.rfft(axes, axis=1)), axes.shape[1])


def phase_weights(spectra):
    """Per frame: weights that start as the plain sum of the axes and move toward the frame's principal
    direction as far as it stands out ((l1 - l2) / l1 of the covariance's eigenvalues), the direction's
    sign the one closer to the weights before, as core/signal/dft321.cpp does."""
    covariance = np.einsum("ibm,jbm->mij", spectra, spectra.conj()).real  # frame, axis, axis
    w = np.ones(3) / np.sqrt(3)
    weights = []
    for c in covariance:
        eigenvalues, vectors = np.linalg.eigh(c)
        v = vectors[:, -1]
        if v @ w < 0:
            v = -v
        clarity = (eigenvalues[2] - eigenvalues[1]) / eigenvalues[2] if eigenvalues[2] > 0 else 0.0
        w = (1 - clarity) * w + clarity * v
        w /= np.linalg.norm(w)
        weights.append(w)
    return np.array(weights)  # frame, axis


def dft321_framewise(axes, window=1024, hop=256):
    """Frame by frame with scipy's STFT (periodic Hann, frames centred by zero padding) and its
    weighted overlap-add inverse: an implementation independent of haptex's core/signal/stft."""
    n = axes.shape[1]
    spectra = np.array([sig.stft(a, window="hann", nperseg=window, noverlap=window - hop, boundary="zeros",
                                 padded=True)[2] for a in axes])  # axis, bin, frame
    magnitude = np.sqrt(np.sum(np.abs(spectra) ** 2, axis=0))
    phase = np.angle(np.einsum("mi,ibm->bm", phase_weights(spectra), spectra))
    _, y = sig.istft(magnitude * np.exp(1j * phase), window="hann", nperseg=window, noverlap=window - hop, boundary=True)
    return y[:n]


def dft321_cases(rng):
    for tag, n in (("even", 2000), ("odd", 1999)):
        t = np.arange(n) / FS
        axes = rng.standard_normal((3, n))
        axes[0] += 3 * np.sin(2 * np.pi * 200 * t)
        axes[1] -= 2 * np.sin(2 * np.pi * 200 * t)  # partly cancels x in the plain sum
        axes[2] += 0.5
        save(f"dft321_axes_{tag}", axes)
        save(f"dft321_{tag}", dft321_whole_recording(axes))
        save(f"dft321_framewise_{tag}", dft321_framewise(axes))
    # A tool turning twice in 2 s: one vibration seen through axis weights that change sign.
    n = 20000
    t = np.arange(n) / FS
    source = rng.standard_normal(n) + 2 * np.sin(2 * np.pi * 230 * t)
    angle = 2 * np.pi * t  # one turn per second
    axes = np.array([np.cos(angle) * source, np.sin(angle) * source, 0.3 * source]) + 0.05 * rng.standard_normal((3, n))
    save("dft321_axes_turning", axes)
    save("dft321_framewise_turning", dft321_framewise(axes))


def spectrum_cases(rng):
    t = np.arange(1000) / FS
    window = rng.standard_normal(1000) + 2 * np.sin(2 * np.pi * 230 * t) + 0.3
    save("spectrum_window", window)
    save("spectrum_bins", 2 * np.abs(np.fft.rfft(window))[1:101] / 1000)


def stft_reference(x, window, hop, centered):
    w = sig.get_window("hann", window)
    n = len(x)
    if centered:
        frames = 1 + -(-n // hop)
        padded = np.concatenate([np.zeros(window // 2), x, np.zeros(window + frames * hop)])
        starts = np.arange(frames) * hop  # frame m is centred on sample m*hop
    else:
        frames = 1 + (n - window) // hop
        padded = x
        starts = np.arange(frames) * hop
    return np.array([np.fft.rfft(w * padded[s:s + window]) for s in starts])


def stft_cases(rng):
    for n in (64, 63, 1000):
        save(f"hann_{n}", sig.get_window("hann", n))
    x = rng.standard_normal(500)
    save("stft_x", x)
    save("stft_centered", stft_reference(x, 64, 16, True))
    save("stft_uncentered", stft_reference(x, 64, 16, False))


def main():
    assert scipy.__version__.startswith("1.10"), scipy.__version__
    os.makedirs(OUT, exist_ok=True)
    # One generator per group, so adding a case to one group leaves the others' files unchanged.
    fft_cases(np.random.default_rng(1))
    butter_cases(np.random.default_rng(2))
    dft321_cases(np.random.default_rng(3))
    spectrum_cases(np.random.default_rng(4))
    stft_cases(np.random.default_rng(5))


if __name__ == "__main__":
    main()
