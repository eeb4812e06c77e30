#!/usr/bin/env python3
"""Runs haptex.examples.knn_baseline from the source tree, as `python3 -m haptex.examples.knn_baseline`
does once the package is installed (pip install ./python); python/haptex/examples/knn_baseline.py holds it."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from haptex.examples import knn_baseline  # noqa: E402

if __name__ == "__main__":
    knn_baseline.run()
