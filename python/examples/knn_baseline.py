#!/usr/bin/env python3
"""A k-nearest-neighbour baseline in action space, scored on haptex's evaluation grid.

Per material, each window of windows.h5 is predicted as the mean target spectrum of the k = 8 training
windows whose 20 action values are nearest (Euclidean), force and speed values each divided by their
standard deviation over the material's training windows so that newtons and mm/s weigh alike.

Usage: knn_baseline.py DATASET.h5 SPLIT.json WINDOWS.h5 -o PREDS.h5 [-k 8]

Writes PREDS.h5: `spectra`, (N, 100) float32, row i the prediction for window i of WINDOWS.h5, with the
windows file's `dataset_sha256` and `split_sha256` as root attributes (what haptex checks predictions
against). Written to PREDS.h5.partial and renamed, so a failed run leaves no half file.
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import haptex_data  # noqa: E402

S = haptex_data.ACTION_SAMPLES


def standardised(actions, scale):
    """Force values (the first 10) and speed values (the last 10) divided by their scales."""
    return np.concatenate([actions[:, :S] / scale[0], actions[:, S:] / scale[1]], axis=1)


def action_scales(actions):
    """Standard deviation of the force values and of the speed values; 1 where one is constant."""
    sd = np.array([actions[:, :S].std(), actions[:, S:].std()])
    return np.where(sd > 0, sd, 1.0)


def knn_spectra(train_actions, train_targets, queries, k):
    """Mean target of the k nearest training windows of each query (ties: the earlier window)."""
    scale = action_scales(train_actions)
    a, q = standardised(train_actions, scale), standardised(queries, scale)
    d2 = (q * q).sum(1)[:, None] - 2 * q @ a.T + (a * a).sum(1)[None, :]
    k = min(k, len(a))
    nearest = np.argsort(d2, axis=1, kind="stable")[:, :k]
    return train_targets[nearest].mean(axis=1)


def predict(train, grid, k):
    out = np.zeros((len(grid), haptex_data.TARGET_BINS), dtype=np.float32)
    for m, material_id in enumerate(grid.materials):
        queries = grid.material == m
        if not queries.any():
            continue
        rows = train.material == train.materials.index(material_id)
        if not rows.any():
            raise haptex_data.HaptexFileError(f"material {material_id} has no training windows")
        out[queries] = knn_spectra(train.action[rows].astype(np.float64), train.target[rows].astype(np.float64),
                                   grid.action[queries].astype(np.float64), k)
    return out


def write_predictions(path, spectra, grid):
    partial = path + ".partial"
    try:
        with h5py.File(partial, "w") as f:
            f.create_dataset("spectra", data=spectra, dtype=np.float32)
            f.attrs["dataset_sha256"] = grid.dataset_sha256
            f.attrs["split_sha256"] = grid.split_sha256
            f.attrs["source"] = "python/examples/knn_baseline.py " + " ".join(sys.argv[1:])
        os.replace(partial, path)
    finally:
        if os.path.exists(partial):
            os.remove(partial)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("dataset")
    p.add_argument("split")
    p.add_argument("windows")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("-k", type=int, default=8)
    args = p.parse_args()
    try:
        split = haptex_data.read_split(args.split)
        grid = haptex_data.read_windows(args.windows)
        if (grid.dataset_sha256, grid.split_sha256) != (split.dataset_sha256, split.sha256):
            raise haptex_data.HaptexFileError(f"{args.windows} was made from another dataset or split than {args.split}")
        train = haptex_data.read_set_windows(args.dataset, split, ("train",))
        write_predictions(args.output, predict(train, grid, args.k), grid)
    except (haptex_data.HaptexFileError, OSError, KeyError) as e:
        print(f"knn_baseline: {e}", file=sys.stderr)
        return 2
    print(f"wrote {args.output} ({len(grid)} windows, k = {args.k})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
