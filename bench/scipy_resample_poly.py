"""Times scipy's resample_poly on the input of bench/signal_bench.cpp's BM_ResamplePoly_999983Hz; prints seconds per call."""
import json
import timeit

import numpy as np
import scipy
from scipy import signal

x = 0.3 * np.sin(2 * np.pi * 180 * np.arange(60000) / 999983.0)
best = min(timeit.repeat(lambda: signal.resample_poly(x, 10000, 999983, padtype="mean"), number=1, repeat=2))
print(json.dumps({"scipy_resample_poly_999983_seconds": best, "scipy": scipy.__version__}))
