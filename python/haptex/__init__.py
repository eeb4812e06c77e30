"""haptex from Python: read a haptex dataset's windows, split and evaluation grid, write predictions for
`haptex evaluate --predictions`, smooth training targets as `haptex train` does, run a trained model in
numpy (or torch: haptex.torch_model), and get a press's texture descriptor and latent from the haptex
binary. python/README.md is the guide.

    import haptex
    split = haptex.read_split("split.json")
    train = haptex.read_set_windows("dataset.h5", split, ("train",))
    smoothed = haptex.smooth_targets(train.target)          # haptex train's stage-2 targets
    model = haptex.read_model("model.h5")
    code = haptex.press_latent("model.h5", "peak.png", reference="reference.png")

Needs numpy and h5py; torch only for haptex.torch_model and WindowDataset, python3-pil only for
decode_image and read_presses, the haptex binary only for press_latent and predict_json.
"""
import os
import re

from .data import (ACTION_SAMPLES, SETS, TARGET_BINS, WINDOW_SAMPLES, HaptexFileError, Press, Split, Windows,
                   check_output, decode_image, grid_sections, read_presses, read_set_windows, read_split,
                   read_split_and_grid, read_windows, section_of, sha256_file, write_predictions)
from .model import Model, read_model
from .press import HaptexCommandError, PressCode, haptex_binary, predict_json, press_latent
from .smoothing import smooth_targets, triangular_weights

__all__ = ["ACTION_SAMPLES", "SETS", "TARGET_BINS", "WINDOW_SAMPLES", "HaptexFileError", "Press", "Split", "Windows",
           "check_output", "decode_image", "grid_sections", "read_presses", "read_set_windows", "read_split",
           "read_split_and_grid", "read_windows", "section_of", "sha256_file", "write_predictions", "Model", "read_model",
           "HaptexCommandError", "PressCode", "haptex_binary", "predict_json", "press_latent", "smooth_targets",
           "triangular_weights"]


def _version():
    """The version the wheel was built with (haptex/_version.py, written by the build); from the
    source tree, CMakeLists.txt's project(haptex VERSION ...), the version's one home."""
    try:
        from ._version import version
        return version
    except ImportError:
        pass
    cmake = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "CMakeLists.txt")
    try:
        with open(cmake, encoding="utf-8") as f:
            found = re.search(r"^project\(haptex\s+VERSION\s+([0-9][0-9.]*)", f.read(), re.M)
    except OSError:
        found = None
    return found.group(1) if found else "unknown"


__version__ = _version()
