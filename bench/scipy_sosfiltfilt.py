"""Times scipy's sosfiltfilt on the same 1e5-sample input as bench/signal_bench.cpp; prints seconds per call."""
import json
import timeit

import numpy as np
from scipy import signal

rng = np.random.default_rng(7)
x = 2.0 + 0.5 * np.sin(np.arange(100000) * 1e-3) + rng.normal(0, 0.05, 100000)
sos = signal.butter(4, 0.004, output="sos")
runs = 50
best = min(timeit.repeat(lambda: signal.sosfiltfilt(sos, x), number=runs, repeat=5)) / runs
print(json.dumps({"scipy_sosfiltfilt_1e5_seconds": best, "scipy": signal.__name__ and __import__("scipy").__version__}))
