"""Runs a haptex model file's network in numpy, as schemas/hdf5-layout.md ("Model file") describes it,
and compares with what `haptex predict --json` printed.

Usage: /usr/bin/python3 model_forward.py MODEL.h5 PREDICT.json

Reads the file with h5py and numpy only, nothing from haptex. For the unified model the latent is
recomputed from the JSON's descriptor (an --image query: the encoder's output, compared with the JSON's
image_latent, then recognised through the classifier) or taken from /material_latents (a --material
query) and compared with the JSON's latent; every query's spectrum is recomputed from its force and
speed (held for the 10 samples, as `haptex predict --normal-force F --speed V` does) and compared with the
JSON's, as max |numpy - haptex| / max |haptex| <= 1e-4; the saturation flag must agree too.
Prints "model forward ok" and exits 0 when everything agrees, prints "mismatch: ..." and exits 1 when
not, exits 2 when the file does not follow the layout.
"""
import json
import sys

import h5py
import numpy as np

TOLERANCE = 1e-4


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def layers(group, path):
    """The layers {i} = 0, 1, ... of GROUP/layers in the order they apply."""
    out = []
    g = group[path + "/layers"]
    while str(len(out)) in g:
        layer = g[str(len(out))]
        weight, bias = np.asarray(layer["weight"]), np.asarray(layer["bias"])
        if weight.dtype != np.float32 or bias.dtype != np.float32:
            raise LayoutError(f"{layer.name}: weight and bias must be float32")
        if weight.ndim != 2 or bias.shape != (weight.shape[0],):
            raise LayoutError(f"{layer.name}: weight (O, I) {weight.shape} and bias (O) {bias.shape} do not fit")
        out.append((weight.astype(np.float64), bias.astype(np.float64), text(layer.attrs["activation"])))
    if not out or len(out) != len(g):
        raise LayoutError(f"{g.name}: expected layers numbered 0, 1, ...; found {sorted(g.keys())}")
    return out


def run(net, x):
    """A layer computes activation(weight @ x + bias)."""
    for weight, bias, activation in net:
        z = weight @ x + bias
        if activation == "relu":
            x = np.maximum(z, 0.0)
        elif activation == "softplus":
            x = np.logaddexp(0.0, z)  # log(1 + e^z)
        elif activation == "linear":
            x = z
        else:
            raise LayoutError(f"unknown activation '{activation}'")
    return x


class LayoutError(Exception):
    pass


def scaled_error(ours, theirs):
    ours, theirs = np.asarray(ours, np.float64), np.asarray(theirs, np.float64)
    if ours.shape != theirs.shape:
        return float("inf")
    return float(np.max(np.abs(ours - theirs)) / max(np.max(np.abs(theirs)), 1e-30))


def main():
    model_path, json_path = sys.argv[1], sys.argv[2]
    result = json.load(open(json_path))
    problems = []
    with h5py.File(model_path, "r") as f:
        if text(f.attrs["haptex_format"]) != "model/3":
            raise LayoutError("not a model/3 file")
        variant = text(f.attrs["variant"])
        ids = [text(s) for s in f["materials/ids"][()]]
        n = f["normalisation"]
        action_mean = np.asarray(n["action_mean"], np.float64)
        action_scale = np.asarray(n["action_scale"], np.float64)
        target_scale = np.asarray(n["target_scale"], np.float64)
        if action_mean.shape != (20,) or action_scale.shape != (20,) or target_scale.shape != (100,):
            raise LayoutError("/normalisation: action_mean and action_scale must be (20), target_scale (100)")
        low = np.r_[np.full(10, n.attrs["force_min"]), np.full(10, n.attrs["speed_min"])].astype(np.float64)
        high = np.r_[np.full(10, n.attrs["force_max"]), np.full(10, n.attrs["speed_max"])].astype(np.float64)
        if text(result["variant"]) != variant:
            problems.append(f"variant: the JSON says {result['variant']}, the file {variant}")

        # 3. The texture: the unified model's latent; per-material, the material's own network.
        net = 0
        latent, latent_error = np.zeros(0), 0.0
        if variant == "unified":
            if "descriptor" in result:
                d = np.asarray(result["descriptor"], np.float64)
                length = int(f["feature_spec"].attrs["length"])
                if d.shape != (length,):
                    problems.append(f"descriptor: {d.size} values, /feature_spec@length is {length}")
                else:
                    x = (d - np.asarray(n["descriptor_mean"], np.float64)) / np.asarray(n["descriptor_scale"], np.float64)
                    image_latent = run(layers(f, "texture_encoder"), x)
                    image_error = scaled_error(image_latent, result.get("image_latent", []))
                    if not image_error <= TOLERANCE:
                        problems.append(f"image_latent: scaled error {image_error:.3g} > {TOLERANCE:g}")
                    logits = run(layers(f, "classifier"), image_latent)
                    p = np.exp(logits - logits.max())
                    latent = np.asarray(f["material_latents"], np.float64).T @ (p / p.sum())
            else:
                latent = np.asarray(f["material_latents"], np.float64)[ids.index(result["material"])]
            latent_error = scaled_error(latent, result.get("latent", []))
            if not latent_error <= TOLERANCE:
                problems.append(f"latent: scaled error {latent_error:.3g} > {TOLERANCE:g}")
        else:
            net = ids.index(result["material"])
            if "latent" in result:
                problems.append("latent: a per-material model has none, the JSON shows one")
        action_encoder = layers(f, f"nets/{net}/action_encoder")
        predictor = layers(f, f"nets/{net}/predictor")

        worst = 0.0
        for q, query in enumerate(result["queries"]):
            a = np.r_[np.full(10, query["force_n"]), np.full(10, query["speed_mm_s"])].astype(np.float32).astype(np.float64)
            saturated = np.clip(a, low, high)  # 1. saturate
            x = (saturated - action_mean) / action_scale  # 2. standardise, then the action encoder
            code = run(action_encoder, x)
            spectrum = target_scale * run(predictor, np.concatenate([latent, code]))  # 4.
            error = scaled_error(spectrum, query["spectrum"])
            worst = max(worst, error)
            if not error <= TOLERANCE:
                problems.append(f"query {q}: spectrum scaled error {error:.3g} > {TOLERANCE:g}")
            if bool(np.any(saturated != a)) != bool(query["out_of_range"]):
                problems.append(f"query {q}: out_of_range is {query['out_of_range']}, numpy saturated: {bool(np.any(saturated != a))}")
    if problems:
        for p in problems:
            print("mismatch:", p)
        return 1
    print(f"model forward ok: {variant}, {len(result['queries'])} queries, latent size {latent.size} (scaled error "
          f"{latent_error:.2g}), worst spectrum scaled error {worst:.2g}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (LayoutError, KeyError, ValueError) as error:
        print(f"layout: {error}")
        sys.exit(2)
