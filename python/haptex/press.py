"""A press's texture descriptor and latent, and any `haptex predict --json` result, from Python.

The texture descriptor of a GelSight image (57 values; predict/texture_descriptor.cpp) is computed by
haptex itself, so these functions run the haptex binary: from an argv list, never through a shell,
and parse what it prints with --json (docs/predict.md, "haptex predict"). The binary is the one
`binary=` names, else the HAPTEX_BINARY environment variable, else `haptex` on PATH.

    code = haptex.press_latent("model.h5", "peak.png", reference="reference.png")
    code.descriptor, code.image_latent, code.latent    # numpy float64 arrays
"""
import json
import os
import shutil
import subprocess
from dataclasses import dataclass

import numpy as np


class HaptexCommandError(RuntimeError):
    """haptex could not be found, or ended with an error (its message and exit code are kept)."""

    def __init__(self, message, exit_code=None, stderr=""):
        super().__init__(message)
        self.exit_code, self.stderr = exit_code, stderr


def haptex_binary(binary=None):
    """The haptex binary to run: `binary`, else $HAPTEX_BINARY, else `haptex` on PATH."""
    chosen = binary or os.environ.get("HAPTEX_BINARY") or shutil.which("haptex")
    if not chosen:
        raise HaptexCommandError("cannot find the haptex binary: put it on PATH, set HAPTEX_BINARY=/path/to/haptex, "
                                 "or pass binary=")
    chosen = os.fspath(chosen)
    if not (os.path.isfile(chosen) and os.access(chosen, os.X_OK)):
        raise HaptexCommandError(f"{chosen}: is not an executable file (the haptex binary: build/haptex after make build)")
    return chosen


def _path(p):
    """A path as an argument: one starting with '-' is not taken for an option."""
    p = os.fspath(p)
    return os.path.join(".", p) if p.startswith("-") else p


def predict_json(model, *, image=None, reference=None, material=None, force=1.0, speed=100.0, csv=None,
                 binary=None, timeout=None):
    """`haptex predict MODEL ... --json` parsed: a dict with `variant`, `frequencies_hz`, `queries`
    (each `force_n`, `speed_mm_s`, `spectrum`, `out_of_range`) and, for an image of a unified model,
    `descriptor`, `image_latent` and `latent` (for --material: `latent`). One of image and material;
    force (N) and speed (mm/s) for one query, or csv, a 10 kHz trajectory file (`--csv`)."""
    if (image is None) == (material is None):
        raise ValueError("give an image or a material")
    argv = [haptex_binary(binary), "predict", _path(model)]
    if image is not None:
        argv += ["--image", _path(image)] + (["--reference", _path(reference)] if reference is not None else [])
    else:
        argv += ["--material", str(material)]
    argv += ["--csv", _path(csv)] if csv is not None else ["--normal-force", _number(force), "--speed", _number(speed)]
    run = subprocess.run(argv + ["--json", "-q"], stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
    if run.returncode != 0:
        message = run.stderr.decode("utf-8", "replace").strip()
        raise HaptexCommandError(message or f"haptex predict ended with exit code {run.returncode}", run.returncode, message)
    return json.loads(run.stdout.decode("utf-8"))


def _number(x):
    """A plain decimal, as haptex's command line takes numbers (no exponent)."""
    return np.format_float_positional(float(x), trim="-")


@dataclass
class PressCode:
    """What a unified model makes of a press: its texture descriptor, the texture encoder's output
    (`image_latent`) and the latent the predictor sees once the press is recognised (`latent`)."""
    descriptor: np.ndarray
    image_latent: np.ndarray
    latent: np.ndarray
    self_reference: bool  # no reference given: haptex used the image blurred at 1/16 of its size


def press_latent(model, image, reference=None, binary=None, timeout=None):
    """The descriptor and latents of a press image (PNG or JPEG; its no-contact `reference` frame if
    you have it, which makes the lowest radial bins reliable) under a unified model, as haptex
    computes them."""
    out = predict_json(model, image=image, reference=reference, binary=binary, timeout=timeout)
    if "latent" not in out:
        raise HaptexCommandError(f"{model}: a {out.get('variant')} model has no texture encoder, so no latent")
    return PressCode(np.asarray(out["descriptor"], np.float64), np.asarray(out["image_latent"], np.float64),
                     np.asarray(out["latent"], np.float64), out.get("reference") is None)
