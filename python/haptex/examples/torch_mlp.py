"""A PyTorch MLP of the paper's predictor shape, trained on haptex's windows and scored on its grid.

The network is haptex's unified model with a learned texture latent per material in place of the
GelSight encoder (docs/predict.md, "The network"): the 20 normalised action values -> 32 ReLU -> 32
ReLU (the action code); [latent 64, code 32] -> 256 ReLU -> 100 softplus, times the training targets'
RMS per bin. Loss: squared Euclidean distance in units of the targets' RMS, every material weighing
alike. Adam (1e-3), mini-batches of 256, early stopping on the validation windows; the best epoch's
weights are kept. One thread, so the per-query time is one core's.

Usage: python3 -m haptex.examples.torch_mlp DATASET.h5 SPLIT.json WINDOWS.h5 -o PREDS.h5 [--epochs 200] [--patience 20] [--seed 0]
(or python/examples/torch_mlp.py from the source tree). Without PyTorch it says what to install and
exits with code 2.

Writes PREDS.h5 (schemas/hdf5-layout.md, "Predictions file") for
`haptex evaluate ... --predictions mlp=PREDS.h5`; prints the first and the best epoch's training and
validation losses.
"""
import sys
import time

import numpy as np

TORCH_ERROR = None
try:
    import torch
    from torch import nn
except Exception as e:  # noqa: BLE001 - absent (ImportError) or installed but broken (OSError from a missing
    # shared library, RuntimeError from an ABI mismatch): said in main(), once the arguments are read, so
    # --help and bad arguments work without torch (review 14, F7)
    torch = nn = None
    TORCH_ERROR = f"{type(e).__name__}: {e}"

from haptex import data as haptex_data

NO_TORCH = ("torch_mlp: needs PyTorch, which this Python cannot import: install python3-torch "
            "(Debian: apt-get install python3-torch; in a venv made with --system-site-packages it is seen too), "
            "or `pip install torch`")

LATENT, ACTION_HIDDEN, HIDDEN = 64, 32, 256


class Mlp(nn.Module if nn is not None else object):
    def __init__(self, materials, action_mean, action_scale, target_scale):
        super().__init__()
        self.latents = nn.Embedding(materials, LATENT)
        self.action = nn.Sequential(nn.Linear(2 * haptex_data.ACTION_SAMPLES, ACTION_HIDDEN), nn.ReLU(),
                                    nn.Linear(ACTION_HIDDEN, ACTION_HIDDEN), nn.ReLU())
        self.predictor = nn.Sequential(nn.Linear(LATENT + ACTION_HIDDEN, HIDDEN), nn.ReLU(),
                                       nn.Linear(HIDDEN, haptex_data.TARGET_BINS), nn.Softplus())
        self.register_buffer("action_mean", torch.as_tensor(action_mean))
        self.register_buffer("action_scale", torch.as_tensor(action_scale))
        self.register_buffer("target_scale", torch.as_tensor(target_scale))

    def forward(self, material, action):
        code = self.action((action - self.action_mean) / self.action_scale)
        return self.target_scale * self.predictor(torch.cat([self.latents(material), code], dim=1))


def material_weights(train_windows, target_scale):
    """Per material: 1 / its mean squared training target norm (in RMS units), scaled so that the
    training windows' weights average 1. The same weights score the validation windows."""
    norm = ((train_windows.target / target_scale) ** 2).sum(axis=1)
    per_material = np.array([norm[train_windows.material == m].mean() if (train_windows.material == m).any() else 1.0
                             for m in range(len(train_windows.materials))])
    return (1.0 / per_material / (1.0 / per_material[train_windows.material]).mean()).astype(np.float32)


def mean_loss(model, loader, target_scale):
    total, count = 0.0, 0
    with torch.no_grad():
        for material, action, target, weight in loader:
            d2 = (((model(material, action) - target) / target_scale) ** 2).sum(dim=1)
            total += float((weight * d2).sum())
            count += len(weight)
    return total / max(count, 1)


def loader(windows, material_weight, shuffle, seed):
    """haptex_data's torch Dataset of the windows, with each window's material weight."""
    data = haptex_data.WindowDataset(windows)
    tensors = [torch.stack(column) for column in zip(*[data[i] for i in range(len(data))])]
    dataset = torch.utils.data.TensorDataset(*tensors, torch.as_tensor(material_weight[windows.material]))
    return torch.utils.data.DataLoader(dataset, batch_size=256, shuffle=shuffle, generator=torch.Generator().manual_seed(seed))


def train(train_windows, val_windows, epochs, patience, seed):
    torch.manual_seed(seed)
    action_mean = train_windows.action.mean(axis=0).astype(np.float32)
    action_scale = np.maximum(train_windows.action.std(axis=0), 1e-6).astype(np.float32)
    target_scale = np.maximum(np.sqrt((train_windows.target.astype(np.float64) ** 2).mean(axis=0)), 1e-9).astype(np.float32)
    model = Mlp(len(train_windows.materials), action_mean, action_scale, target_scale)
    scale = torch.as_tensor(target_scale)
    weight = material_weights(train_windows, target_scale)
    training = loader(train_windows, weight, True, seed)
    validation = loader(val_windows, weight, False, seed)
    optimiser = torch.optim.Adam(model.parameters(), lr=1e-3)
    best, best_state, since, history = np.inf, None, 0, []
    for epoch in range(epochs):
        model.train()
        for material, action, target, weight in training:
            optimiser.zero_grad()
            loss = (weight * (((model(material, action) - target) / scale) ** 2).sum(dim=1)).mean()
            loss.backward()
            optimiser.step()
        model.eval()
        history.append((mean_loss(model, training, scale), mean_loss(model, validation, scale)))
        if history[-1][1] < best:
            best, best_state, since = history[-1][1], {k: v.clone() for k, v in model.state_dict().items()}, 0
        else:
            since += 1
            if since >= patience:
                break
    model.load_state_dict(best_state)
    return model, history


def predict(model, grid, train_materials):
    """One window at a time, as a haptic loop asks; the mean CPU time of one query."""
    index = [train_materials.index(m) for m in grid.materials]
    out = np.zeros((len(grid), haptex_data.TARGET_BINS), dtype=np.float32)
    actions = torch.as_tensor(grid.action.astype(np.float32))
    with torch.no_grad():
        start = time.process_time()
        for i in range(len(grid)):
            material = torch.tensor([index[grid.material[i]]])
            out[i] = model(material, actions[i:i + 1])[0].numpy()
        seconds = time.process_time() - start
    return out, seconds / max(len(grid), 1)


def main():
    p = haptex_data.example_arguments(__doc__.splitlines()[0])
    p.add_argument("--epochs", type=int, default=200)
    p.add_argument("--patience", type=int, default=20)
    p.add_argument("--seed", type=int, default=0)
    args = p.parse_args()
    try:
        haptex_data.check_output(args.output, (args.dataset, args.split, args.windows), args.force)
        if torch is None:
            print(NO_TORCH + (f" (import torch said {TORCH_ERROR})" if TORCH_ERROR else ""), file=sys.stderr)
            return 2
        torch.set_num_threads(1)
        split, grid = haptex_data.read_split_and_grid(args.split, args.windows)
        train_windows = haptex_data.read_set_windows(args.dataset, split, ("train",))
        val_windows = haptex_data.read_set_windows(args.dataset, split, ("val",))
        model, history = train(train_windows, val_windows, args.epochs, args.patience, args.seed)
        spectra, query_seconds = predict(model, grid, train_windows.materials)
        haptex_data.write_predictions(args.output, grid, spectra,
                                      f"torch_mlp.py, {len(history)} epochs, seed {args.seed}, torch {torch.__version__}, one thread",
                                      query_seconds, inputs=(args.dataset, args.split, args.windows),
                                      overwrite=args.force)
    except (haptex_data.HaptexFileError, OSError, KeyError) as e:
        print(f"torch_mlp: {haptex_data.printable(e)}", file=sys.stderr)
        return haptex_data.exit_code_for(e)
    best = int(np.argmin([v for _, v in history]))
    print(f"losses (training, validation): epoch 1 {history[0][0]:.6g} {history[0][1]:.6g}; "
          f"best epoch {best + 1} {history[best][0]:.6g} {history[best][1]:.6g}")
    print(f"wrote {haptex_data.printable(args.output)} ({len(grid)} windows, {query_seconds * 1e6:.1f} us per query)")
    return 0


def run():
    """main() as a program: its exit code, without HDF5's exit handler (haptex_data.leave)."""
    haptex_data.leave(main())


if __name__ == "__main__":
    run()
