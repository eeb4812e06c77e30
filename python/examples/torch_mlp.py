#!/usr/bin/env python3
"""Runs haptex.examples.torch_mlp from the source tree, as `python3 -m haptex.examples.torch_mlp`
does once the package is installed (pip install ./python); python/haptex/examples/torch_mlp.py holds it."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from haptex.examples import torch_mlp  # noqa: E402

if __name__ == "__main__":
    torch_mlp.run()
