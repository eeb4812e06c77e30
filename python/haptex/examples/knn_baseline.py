"""A k-nearest-neighbour baseline in action space, scored on haptex's evaluation grid.

Per material, each window of windows.h5 is predicted as the mean target spectrum of the k = 8 training
windows whose 20 action values are nearest (Euclidean), force and speed values each divided by their
standard deviation over the material's training windows so that newtons and mm/s weigh alike.

Usage: python3 -m haptex.examples.knn_baseline DATASET.h5 SPLIT.json WINDOWS.h5 -o PREDS.h5 [-k 8]
(or python/examples/knn_baseline.py from the source tree; k of 1 or more, more than a material's
training windows averages them all)

Writes PREDS.h5 (schemas/hdf5-layout.md, "Predictions file"; haptex.write_predictions): `spectra`,
(N, 100) float32, row i the prediction for window i of WINDOWS.h5, with the windows file's hashes and
the mean CPU time of one query (each window is predicted on its own, as a haptic loop would ask), for
`haptex evaluate ... --predictions knn=PREDS.h5`.
"""
import sys
import time

import numpy as np

from haptex import data as haptex_data

S = haptex_data.ACTION_SAMPLES


def standardised(actions, scale):
    """Force values (the first 10) and speed values (the last 10) divided by their scales."""
    return np.concatenate([actions[:, :S] / scale[0], actions[:, S:] / scale[1]], axis=1)


def action_scales(actions):
    """Standard deviation of the force values and of the speed values; 1 where one is constant."""
    sd = np.array([actions[:, :S].std(), actions[:, S:].std()])
    return np.where(sd > 0, sd, 1.0)


class Knn:
    """One material's training windows; query() predicts one window at a time, as a haptic loop asks."""

    def __init__(self, actions, targets, k):
        self.scale = action_scales(actions)
        self.actions = standardised(actions, self.scale)
        self.targets = targets
        self.k = min(k, len(actions))

    def query(self, action):
        """Mean target of the k nearest training windows (ties: the earlier window)."""
        q = standardised(action[None, :], self.scale)[0]
        d2 = ((self.actions - q) ** 2).sum(axis=1)
        kth = np.partition(d2, self.k - 1)[self.k - 1]
        candidates = np.flatnonzero(d2 <= kth)
        nearest = candidates[np.argsort(d2[candidates], kind="stable")[:self.k]]
        return self.targets[nearest].mean(axis=0)


def predict(train, grid, k):
    """The spectra of every grid window and the mean CPU time of one query."""
    out = np.zeros((len(grid), haptex_data.TARGET_BINS), dtype=np.float32)
    seconds = 0.0
    actions = grid.action.astype(np.float64)
    for m, material_id in enumerate(grid.materials):
        queries = np.flatnonzero(grid.material == m)
        if len(queries) == 0:
            continue
        rows = train.material == train.materials.index(material_id)
        if not rows.any():
            raise haptex_data.HaptexFileError(f"material {material_id} has no training windows")
        model = Knn(train.action[rows].astype(np.float64), train.target[rows].astype(np.float64), k)
        start = time.process_time()
        for i in queries:
            out[i] = model.query(actions[i])
        seconds += time.process_time() - start
    return out, seconds / max(len(grid), 1)


def main():
    p = haptex_data.example_arguments(__doc__.splitlines()[0])
    p.add_argument("-k", type=int, default=8, help="neighbours averaged (1 or more)")
    args = p.parse_args()
    if args.k < 1:  # review 10, F7: -k -1 took all but one neighbour, -k 0 ended in numpy warnings
        print(f"knn_baseline: -k {args.k}: give 1 or more neighbours", file=sys.stderr)
        return 2
    try:
        haptex_data.check_output(args.output, (args.dataset, args.split, args.windows), args.force)
        split, grid = haptex_data.read_split_and_grid(args.split, args.windows)
        train = haptex_data.read_set_windows(args.dataset, split, ("train",))
        spectra, query_seconds = predict(train, grid, args.k)
        haptex_data.write_predictions(args.output, grid, spectra, f"knn_baseline.py, k = {args.k}, numpy, one query at a time",
                                      query_seconds, inputs=(args.dataset, args.split, args.windows),
                                      overwrite=args.force)
    except (haptex_data.HaptexFileError, OSError, KeyError) as e:
        print(f"knn_baseline: {haptex_data.printable(e)}", file=sys.stderr)
        return haptex_data.exit_code_for(e)
    print(f"wrote {haptex_data.printable(args.output)} ({len(grid)} windows, k = {args.k})")
    return 0


def run():
    """main() as a program: its exit code, without HDF5's exit handler (haptex_data.leave)."""
    haptex_data.leave(main())


if __name__ == "__main__":
    run()
