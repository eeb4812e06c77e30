"""A plain python3-opencv contact-score loop (absdiff, threshold, sum) on the JPEGs bench_capture
exports, for the ratio bench/run_bench.sh prints. One thread, like the C++ figures.

Usage: opencv_peak_loop.py FRAMES_DIR  -> JSON {"<W>x<H>": {"decoded_fps": .., "mjpg_fps": ..}, "opencv": ..}
"""
import glob
import json
import os
import sys
import time

import cv2
import numpy as np

cv2.setNumThreads(1)


def score(grey, reference_grey):
    d = cv2.absdiff(grey, reference_grey)
    _, d = cv2.threshold(d, 6, 255, cv2.THRESH_TOZERO)
    return float(d.sum())


def frames_per_second(work, items, seconds=3.0):
    done, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        for item in items:
            work(item)
        done += len(items)
    return done / (time.perf_counter() - start)


def main():
    results = {"opencv": cv2.__version__}
    for sub in sorted(glob.glob(os.path.join(sys.argv[1], "*x*"))):
        jpegs = [np.fromfile(p, np.uint8) for p in sorted(glob.glob(os.path.join(sub, "frame_*.jpg")))]
        reference = cv2.cvtColor(cv2.imread(os.path.join(sub, "reference.png")), cv2.COLOR_BGR2GRAY)
        decoded = [cv2.imdecode(j, cv2.IMREAD_COLOR) for j in jpegs]
        results[os.path.basename(sub)] = {
            "decoded_fps": frames_per_second(lambda f: score(cv2.cvtColor(f, cv2.COLOR_BGR2GRAY), reference), decoded),
            "mjpg_fps": frames_per_second(
                lambda j: score(cv2.cvtColor(cv2.imdecode(j, cv2.IMREAD_COLOR), cv2.COLOR_BGR2GRAY), reference), jpegs),
        }
    print(json.dumps(results))


if __name__ == "__main__":
    main()
