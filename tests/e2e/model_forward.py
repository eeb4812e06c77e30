"""Runs a haptex model file's network with the haptex Python package's numpy forward pass
(python/haptex/model.py, which follows schemas/hdf5-layout.md's "Model file" step by step) and
compares with what `haptex predict --json` printed.

Usage: /usr/bin/python3 model_forward.py MODEL.h5 PREDICT.json

For the unified model the latent is recomputed from the JSON's descriptor (an --image query: the
encoder's output, compared with the JSON's image_latent, then recognised through the classifier) or
taken from /material_latents (a --material query) and compared with the JSON's latent; every query's
spectrum is recomputed from its force and speed (held for the 10 samples, as `haptex predict
--normal-force F --speed V` does) and compared with the JSON's, as max |numpy - haptex| / max |haptex|
<= 1e-4; the saturation flag must agree too. Prints "model forward ok" and exits 0 when everything
agrees, prints "mismatch: ..." and exits 1 when not, exits 2 when the file does not follow the layout.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import haptex  # noqa: E402

TOLERANCE = 1e-4


def scaled_error(ours, theirs):
    ours, theirs = np.asarray(ours, np.float64), np.asarray(theirs, np.float64)
    if ours.shape != theirs.shape:
        return float("inf")
    return float(np.max(np.abs(ours - theirs)) / max(np.max(np.abs(theirs)), 1e-30))


def main():
    model_path, json_path = sys.argv[1], sys.argv[2]
    result = json.load(open(json_path))
    model = haptex.read_model(model_path)
    problems = []
    if result["variant"] != model.variant:
        problems.append(f"variant: the JSON says {result['variant']}, the file {model.variant}")
    latent, latent_error, material = None, 0.0, None
    if model.variant == "unified":
        if "descriptor" in result:
            d = np.asarray(result["descriptor"], np.float64)
            if d.shape != model.descriptor_mean.shape:
                problems.append(f"descriptor: {d.size} values, /feature_spec@length is {model.descriptor_mean.size}")
                latent = np.zeros(model.material_latents.shape[1])
            else:
                image_latent = model.image_latent(d)
                image_error = scaled_error(image_latent, result.get("image_latent", []))
                if not image_error <= TOLERANCE:
                    problems.append(f"image_latent: scaled error {image_error:.3g} > {TOLERANCE:g}")
                latent = model.recognised(image_latent)
        else:
            latent = model.material_latents[model.material_index(result["material"])].astype(np.float64)
        latent_error = scaled_error(latent, result.get("latent", []))
        if not latent_error <= TOLERANCE:
            problems.append(f"latent: scaled error {latent_error:.3g} > {TOLERANCE:g}")
    else:
        material = result["material"]
        if "latent" in result:
            problems.append("latent: a per-material model has none, the JSON shows one")
    worst = 0.0
    for q, query in enumerate(result["queries"]):
        action = np.r_[np.full(10, query["force_n"]), np.full(10, query["speed_mm_s"])]
        spectrum, saturated = model.spectrum(action, material=material, latent=latent)
        error = scaled_error(spectrum, query["spectrum"])
        worst = max(worst, error)
        if not error <= TOLERANCE:
            problems.append(f"query {q}: spectrum scaled error {error:.3g} > {TOLERANCE:g}")
        if saturated != bool(query["out_of_range"]):
            problems.append(f"query {q}: out_of_range is {query['out_of_range']}, numpy saturated: {saturated}")
    if problems:
        for p in problems:
            print("mismatch:", p)
        return 1
    size = 0 if latent is None else np.size(latent)
    print(f"model forward ok: {model.variant}, {len(result['queries'])} queries, latent size {size} (scaled error "
          f"{latent_error:.2g}), worst spectrum scaled error {worst:.2g}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (haptex.HaptexFileError, KeyError, ValueError) as error:
        print(f"layout: {error}")
        sys.exit(2)
