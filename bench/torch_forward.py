"""The predictor's single query in PyTorch, on one thread; prints JSON.

Usage: /usr/bin/python3 bench/torch_forward.py [MODEL.h5]

MODEL.h5 is a haptex model file (`bench_predict --export-model FILE` writes the default-size unified
model bench_predict times); its network 0 and its material 7's latent are used. Without it, random
weights at train_options.hpp's default sizes (latent 64, action encoder 2 x 32, predictor 1 x 128).
The network is torch.nn Linear/ReLU/Softplus, float32, batch 1, torch.set_num_threads(1), under
torch.inference_mode(). A query does what predict::Predictor::predict does: saturate the 20 action
values into the training range, standardise them, run the action encoder and the predictor, scale the
output by target_scale. The input is a preallocated (1, 20) tensor, the result a new (1, 100) tensor;
converting from and to Python numbers is not timed.

Two forms are timed:
- "precomputed" (single_query_seconds): as haptex does, the latent's share of the predictor's first
  layer (W[:, :L] @ latent + bias) is computed once per texture; a query adds W[:, L:] @ code to it.
- "concatenated": the textbook form, predictor(cat(latent, code)) with the whole first layer.
Each is the best of 5 rounds of the mean CPU time over REPS queries (one thread: the time on one core
whatever else the machine runs, as bench/run_bench.sh reports haptex's).

Batched (batch_seconds, for batch_size queries): the precomputed form on a (1000, 20) tensor of actions spread over the
training range, as bench_predict's BM_PredictBatch/1000 times predict_batch; best of 5 rounds of the
mean CPU time over BATCH_REPS batches.
"""
import json
import sys
import time

try:
    import torch
except ImportError as error:  # run_bench.sh prints the note and carries on
    print(json.dumps({"note": f"PyTorch is not installed ({error}); no comparison"}))
    sys.exit(0)

import numpy as np

REPS, ROUNDS, MATERIAL = 20000, 5, 7
BATCH, BATCH_REPS = 1000, 50
ACTIVATIONS = {"linear": None, "relu": torch.nn.ReLU, "softplus": torch.nn.Softplus}


def read_layers(group):
    layers = group["layers"]
    out = []
    for i in range(len(layers)):
        layer = layers[str(i)]
        activation = layer.attrs["activation"]
        out.append((np.asarray(layer["weight"], np.float32), np.asarray(layer["bias"], np.float32),
                    activation.decode() if isinstance(activation, bytes) else activation))
    return out


def from_file(path):
    import h5py
    with h5py.File(path, "r") as f:
        n = f["normalisation"]
        norm = {name: np.asarray(n[name], np.float32) for name in ("action_mean", "action_scale", "target_scale")}
        norm.update({name: float(n.attrs[name]) for name in ("force_min", "force_max", "speed_min", "speed_max")})
        action, predictor = read_layers(f["nets/0/action_encoder"]), read_layers(f["nets/0/predictor"])
        latent = np.asarray(f["material_latents"][MATERIAL], np.float32) if "material_latents" in f else np.zeros(0, np.float32)
    return norm, action, predictor, latent


def random_model(latent_size=64, action_hidden=32, action_layers=2, predictor_hidden=128, predictor_layers=1):
    rng = np.random.default_rng(3)

    def mlp(sizes, hidden, output):
        return [(rng.standard_normal((o, i)).astype(np.float32) * np.float32(np.sqrt(2.0 / i)), np.zeros(o, np.float32),
                 output if k == len(sizes) - 2 else hidden) for k, (i, o) in enumerate(zip(sizes[:-1], sizes[1:]))]

    action = mlp([20] + [action_hidden] * action_layers, "relu", "relu")
    predictor = mlp([latent_size + action_hidden] + [predictor_hidden] * predictor_layers + [100], "relu", "softplus")
    norm = {"action_mean": np.r_[np.full(10, 1.0), np.full(10, 120.0)].astype(np.float32),
            "action_scale": np.r_[np.full(10, 0.6), np.full(10, 70.0)].astype(np.float32),
            "target_scale": np.linspace(0.05, 0.01, 100).astype(np.float32),
            "force_min": 0.05, "force_max": 4.0, "speed_min": 1.0, "speed_max": 400.0}
    return norm, action, predictor, rng.uniform(-1, 1, latent_size).astype(np.float32)


def sequential(layers):
    """torch.nn.Sequential of (weight, bias, activation) layers."""
    modules = []
    for weight, bias, activation in layers:
        linear = torch.nn.Linear(weight.shape[1], weight.shape[0])
        with torch.no_grad():
            linear.weight.copy_(torch.from_numpy(np.ascontiguousarray(weight)))
            linear.bias.copy_(torch.from_numpy(bias))
        modules.append(linear)
        if ACTIVATIONS[activation] is not None:
            modules.append(ACTIVATIONS[activation]())
    return torch.nn.Sequential(*modules).eval()


def build(norm, action_layers, predictor_layers, latent):
    t = lambda a: torch.from_numpy(np.asarray(a, np.float32)).reshape(1, -1)  # noqa: E731
    low = t(np.r_[np.full(10, norm["force_min"]), np.full(10, norm["speed_min"])])
    high = t(np.r_[np.full(10, norm["force_max"]), np.full(10, norm["speed_max"])])
    mean, scale, target_scale = t(norm["action_mean"]), t(norm["action_scale"]), t(norm["target_scale"])
    action_encoder = sequential(action_layers)
    predictor = sequential(predictor_layers)
    size = latent.size
    latent_t = t(latent)
    # The latent's share of the first layer, once per texture (haptex's TextureCode::first_layer).
    w0, b0, first_activation = predictor_layers[0]
    first_layer = t(w0[:, :size] @ latent + b0)
    code_part = sequential([(w0[:, size:], np.zeros_like(b0), first_activation)] + predictor_layers[1:])
    code_part[0].bias = None  # no bias: it is in first_layer
    code_linear, rest = code_part[0], code_part[1:]

    def standardise(a):
        return (torch.clamp(a, low, high) - mean) / scale

    def precomputed(a):
        h = code_linear(action_encoder(standardise(a))) + first_layer
        return rest(h) * target_scale

    def concatenated(a):
        return predictor(torch.cat((latent_t, action_encoder(standardise(a))), dim=1)) * target_scale

    return precomputed, concatenated


def best_mean_seconds(forward, action, reps=REPS):
    for _ in range(max(10, reps // 20)):  # warm-up
        forward(action)
    best = float("inf")
    for _ in range(ROUNDS):
        start = time.process_time()
        for _ in range(reps):
            forward(action)
        best = min(best, (time.process_time() - start) / reps)
    return best


def main():
    torch.set_num_threads(1)
    norm, action_layers, predictor_layers, latent = from_file(sys.argv[1]) if len(sys.argv) > 1 else random_model()
    precomputed, concatenated = build(norm, action_layers, predictor_layers, latent)
    action = torch.tensor([[1.2 + 0.001 * i for i in range(10)] + [150.0 + 0.1 * i for i in range(10)]], dtype=torch.float32)
    forces = torch.linspace(norm["force_min"], norm["force_max"], BATCH).reshape(-1, 1).repeat(1, 10)
    speeds = torch.linspace(norm["speed_min"], norm["speed_max"], BATCH).flip(0).reshape(-1, 1).repeat(1, 10)
    batch = torch.cat((forces, speeds), dim=1).contiguous()
    with torch.inference_mode():
        a, b = precomputed(action), concatenated(action)
        if not torch.allclose(a, b, rtol=1e-4, atol=1e-6 * float(b.abs().max())):
            raise SystemExit(f"torch_forward.py: the two forms disagree: max difference {float((a - b).abs().max())}")
        print(json.dumps({
            "torch": torch.__version__,
            "weights": sys.argv[1] if len(sys.argv) > 1 else "random, default sizes",
            "latent": int(latent.size),
            "single_query_seconds": best_mean_seconds(precomputed, action),
            "latent_part": "precomputed once per texture, as haptex does",
            "single_query_seconds_concatenated": best_mean_seconds(concatenated, action),
            "batch_size": BATCH,
            "batch_seconds": best_mean_seconds(precomputed, batch, BATCH_REPS),
            "repetitions": f"best of {ROUNDS} rounds of the mean CPU time over {REPS} queries ({BATCH_REPS} batches)",
        }))


if __name__ == "__main__":
    main()
