"""torchaudio's Griffin-Lim at haptex's settings, on one thread; prints JSON.

Usage: /usr/bin/python3 bench/torchaudio_griffinlim.py [SIGNAL.f64]
SIGNAL.f64 is the 10 s texture signal `bench_evaluate --export-signal` writes (raw float64); without
it a seeded white-noise signal of the same length is used. Settings as bench/evaluate_bench.cpp's
BM_GriffinLim_10s/100/99: n_fft = win_length = 1000, hop 100, periodic Hann, power 1, 100
iterations, momentum 0.99, random initial phase, output length fixed at 100000 samples. The one
difference torchaudio does not let us remove: its frames are centred (reflect-padded by 500 samples
at both ends, 1001 frames) where haptex's start at the signal (991 frames). The magnitudes are
torchaudio's own STFT of the signal, so each method starts from exact magnitudes in its framing.
Timed in float64 (as haptex computes) and float32 (torchaudio's default): CPU time of the process
(one thread, so it is the time on one core, robust to other load on the machine), best of 3.
"""
import json
import sys
import time

try:
    import torch
    import torchaudio
except ImportError as error:  # run_bench.sh prints the note and carries on
    print(json.dumps({"note": f"torchaudio is not installed ({error}); no comparison"}))
    sys.exit(0)

import numpy as np

N_FFT, HOP, LENGTH, ITERATIONS, MOMENTUM = 1000, 100, 100000, 100, 0.99


def load_signal():
    if len(sys.argv) > 1:
        return np.fromfile(sys.argv[1], dtype="<f8")
    return np.random.default_rng(7).standard_normal(LENGTH)


def spectral_convergence_db(x, s, window):
    rebuilt = torch.stft(x, N_FFT, HOP, N_FFT, window, center=True, pad_mode="reflect", return_complex=True).abs()
    return float(20 * torch.log10(torch.linalg.norm(rebuilt - s) / torch.linalg.norm(s)))


def run(signal, dtype):
    x = torch.from_numpy(signal).to(dtype)
    window = torch.hann_window(N_FFT, periodic=True, dtype=dtype)
    s = torch.stft(x, N_FFT, HOP, N_FFT, window, center=True, pad_mode="reflect", return_complex=True).abs()
    griffin_lim = torchaudio.transforms.GriffinLim(
        n_fft=N_FFT, n_iter=ITERATIONS, win_length=N_FFT, hop_length=HOP, window_fn=torch.hann_window,
        power=1.0, momentum=MOMENTUM, length=LENGTH, rand_init=True).to(dtype)
    best, y = float("inf"), None
    for _ in range(3):
        torch.manual_seed(0)
        start = time.process_time()
        with torch.no_grad():
            y = griffin_lim(s)
        best = min(best, time.process_time() - start)
    return {"seconds": best, "sc_db": spectral_convergence_db(y, s, window), "frames": s.shape[-1]}


def main():
    torch.set_num_threads(1)
    signal = load_signal()
    print(json.dumps({
        "torch": torch.__version__,
        "torchaudio": torchaudio.__version__,
        "float64": run(signal, torch.float64),
        "float32": run(signal, torch.float32),
    }))


if __name__ == "__main__":
    main()
