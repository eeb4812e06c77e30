"""Checks the installed haptex Python package (pip install ./python) against the haptex binary.

Usage: VENV/bin/python python_package_check.py --source REPO --haptex BINARY --dataset D.h5 --split S.json
           --model UNIFIED.h5 --per-material-model PM.h5 --work DIR [--part package|torch]

Run by tests/e2e/python_package_test.cpp with the venv's python, from a folder that is not the
repository. Part `package`: haptex imports from the venv (not the source tree) with CMakeLists.txt's
version and the binary's; `import haptex_data` is haptex.data; haptex.smooth_targets agrees with
tests/golden/target_smoothing; `python -m haptex.examples.knn_baseline` writes predictions for
the grid of `haptex windows`; haptex.read_model's numpy forward pass and haptex.press_latent agree with
`haptex predict --json`; without torch, haptex.torch_model and the torch example say what to install.
Part `torch`: haptex.torch_model.load gives haptex predict's spectra and latents (skipped, with a
message, where torch does not import). Prints what it checked; exits 0 when all agrees, 1 when not.
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

TOLERANCE = 1e-4       # max |python - haptex| / max |haptex|, as tests/e2e/model_forward.py
SMOOTHING_TOLERANCE = 2e-6  # float32 sums against the float64 reference
problems = []


def check(condition, what):
    print(("ok: " if condition else "FAILED: ") + what)
    if not condition:
        problems.append(what)
    return condition


def scaled_error(ours, theirs):
    ours, theirs = np.asarray(ours, np.float64), np.asarray(theirs, np.float64)
    if ours.shape != theirs.shape:
        return float("inf")
    return float(np.max(np.abs(ours - theirs)) / max(np.max(np.abs(theirs)), 1e-30))


def run(argv, **kw):
    return subprocess.run(argv, capture_output=True, text=True, stdin=subprocess.DEVNULL, **kw)


def press_images(dataset, work):
    """The last material's press 4 peak and reference, written as the encoded files they are."""
    import h5py
    paths = []
    with h5py.File(dataset, "r") as f:
        material = sorted(f["materials"].keys())[-1]
        press = f[f"materials/{material}/presses"]
        g = press[sorted(press.keys(), key=int)[-1]]
        for name in ("peak", "reference"):
            data = np.asarray(g[name][0], np.uint8).tobytes()
            path = os.path.join(work, name + (".png" if data[:4] == b"\x89PNG" else ".jpg"))
            with open(path, "wb") as out:
                out.write(data)
            paths.append(path)
    return paths


def queries(model):
    """(material, force, speed) points: the middle and two corners of the training range (at least 0,
    as haptex predict takes them), one far outside it (saturated), for every material."""
    fmin, fmax, smin, smax = (max(0.0, float(v)) for v in (model.low[0], model.high[0], model.low[-1], model.high[-1]))
    points = [(0.5 * (fmin + fmax), 0.5 * (smin + smax)), (fmin, smax), (fmax, smin), (1000.0, 100000.0)]
    return [(m, round(f, 4), round(s, 3)) for m in model.ids for f, s in points]


def package_part(args):
    import haptex

    # Installed, imported from the venv, not from the source tree.
    source = os.path.realpath(args.source)
    where = os.path.realpath(haptex.__file__)
    check(sys.prefix != sys.base_prefix and where.startswith(os.path.realpath(sys.prefix) + os.sep),
          f"import haptex from {os.getcwd()} finds the installed package ({where})")
    check(not where.startswith(source + os.sep), "not the source tree's python/haptex")
    with open(os.path.join(source, "CMakeLists.txt"), encoding="utf-8") as f:
        cmake = re.search(r"^project\(haptex\s+VERSION\s+([0-9.]+)", f.read(), re.M).group(1)
    binary = run([args.haptex, "--version"]).stdout.split()
    check(haptex.__version__ == cmake == binary[-1],
          f"haptex.__version__ {haptex.__version__}, CMakeLists.txt {cmake}, haptex --version {binary[-1]}")
    import haptex_data
    check(haptex_data is haptex.data, "import haptex_data gives haptex.data (the old module's name)")

    # The target smoothing against the golden reference.
    golden = os.path.join(source, "tests", "golden", "target_smoothing")
    x = np.load(os.path.join(golden, "input.npy"))
    names = sorted(n for n in os.listdir(golden) if re.fullmatch(r"bins_[0-9]+\.npy", n))
    worst = 0.0
    for name in names:
        bins = int(name[5:-4])
        ours = haptex.smooth_targets(x.astype(np.float32), bins)
        error = scaled_error(ours, np.load(os.path.join(golden, name)))
        worst = max(worst, error)
        check(ours.dtype == np.float32 and error <= SMOOTHING_TOLERANCE, f"smooth_targets over {bins} bins: scaled error {error:.2g}")
    check(len(names) >= 5, f"{len(names)} golden smoothing widths")
    check(np.array_equal(haptex.smooth_targets(x.T.astype(np.float32), 7, axis=0).T, haptex.smooth_targets(x.astype(np.float32), 7)),
          "smooth_targets along axis 0 is the transpose's")
    for bad in (0, 2, -3):
        try:
            haptex.smooth_targets(x, bad)
            check(False, f"smooth_targets refuses {bad} bins")
        except ValueError as e:
            check("odd number of bins" in str(e), f"smooth_targets refuses {bad} bins: {e}")

    # The kNN example as a module, on haptex windows' grid.
    windows, preds = os.path.join(args.work, "windows.h5"), os.path.join(args.work, "knn.h5")
    r = run([args.haptex, "windows", args.dataset, "--split", args.split, "-o", windows, "-q", "--force"])
    check(r.returncode == 0, f"haptex windows ({r.stderr.strip()})")
    r = run([sys.executable, "-m", "haptex.examples.knn_baseline", args.dataset, args.split, windows, "-o", preds, "--force"], cwd=args.work)
    if check(r.returncode == 0 and "wrote" in r.stdout, f"python -m haptex.examples.knn_baseline: {r.stdout.strip()} {r.stderr.strip()}"):
        import h5py
        split, grid = haptex.read_split_and_grid(args.split, windows)
        with h5py.File(preds, "r") as f:
            spectra = f["spectra"][()]
            check(spectra.shape == (len(grid), haptex.TARGET_BINS) and np.all(np.isfinite(spectra)) and spectra.min() >= 0,
                  f"its predictions: {spectra.shape} for {len(grid)} windows")
            check(f.attrs["dataset_sha256"] == grid.dataset_sha256 and f.attrs["split_sha256"] == grid.split_sha256,
                  "its predictions carry the grid's dataset and split hashes")

    # The numpy forward pass against haptex predict, for training materials.
    worst = {}
    for path in (args.model, args.per_material_model):
        model = haptex.read_model(path)
        worst[model.variant] = 0.0
        for material, force, speed in queries(model):
            out = haptex.predict_json(path, material=material, force=force, speed=speed, binary=args.haptex)
            q = out["queries"][0]
            spectrum, saturated = model.spectrum(np.r_[np.full(10, q["force_n"]), np.full(10, q["speed_mm_s"])], material=material)
            worst[model.variant] = max(worst[model.variant], scaled_error(spectrum, q["spectrum"]))
            if saturated != q["out_of_range"]:
                check(False, f"{model.variant} {material} {force} N {speed} mm/s: out_of_range {q['out_of_range']}, numpy {saturated}")
            if model.variant == "unified":
                worst[model.variant] = max(worst[model.variant], scaled_error(model.material_latents[model.material_index(material)], out["latent"]))
        check(worst[model.variant] <= TOLERANCE, f"numpy forward ({model.variant}) against haptex predict --json: worst scaled error "
                                                 f"{worst[model.variant]:.2g} over {len(queries(model))} queries")

    # A press's descriptor and latent, through the binary (argument and HAPTEX_BINARY).
    peak, reference = press_images(args.dataset, args.work)
    model = haptex.read_model(args.model)
    code = haptex.press_latent(args.model, peak, reference, binary=args.haptex)
    check(code.descriptor.shape == model.descriptor_mean.shape and not code.self_reference,
          f"press_latent: descriptor of {code.descriptor.size} values, latent of {code.latent.size}")
    image_latent = model.image_latent(code.descriptor)
    check(scaled_error(image_latent, code.image_latent) <= TOLERANCE and scaled_error(model.recognised(image_latent), code.latent) <= TOLERANCE,
          "numpy's encoder and recognition of the descriptor give haptex's image_latent and latent")
    os.environ["HAPTEX_BINARY"] = args.haptex
    out = haptex.predict_json(args.model, image=peak, force=2.0, speed=50.0)
    del os.environ["HAPTEX_BINARY"]
    check(out.get("reference") is None and len(out["latent"]) == code.latent.size, "predict_json finds the binary through HAPTEX_BINARY")
    spectrum, _ = model.spectrum(np.r_[np.full(10, 2.0), np.full(10, 50.0)], latent=model.recognised(model.image_latent(out["descriptor"])))
    check(scaled_error(spectrum, out["queries"][0]["spectrum"]) <= TOLERANCE, "numpy spectrum of a press image agrees with haptex predict")
    try:
        haptex.press_latent(args.per_material_model, peak, binary=args.haptex)
        check(False, "press_latent refuses a per-material model")
    except haptex.HaptexCommandError as e:
        check(e.exit_code == 2 and "per-material" in str(e), f"press_latent on a per-material model: {e}")

    # Without torch: a sentence saying what to install, no traceback from the example.
    no_torch = "import sys, runpy; sys.modules['torch'] = None; "
    r = run([sys.executable, "-c", no_torch + "import haptex.torch_model"], cwd=args.work)
    check(r.returncode != 0 and "install python3-torch" in r.stderr, "without torch, import haptex.torch_model says: install python3-torch")
    r = run([sys.executable, "-c", no_torch + "sys.argv = ['torch_mlp', *sys.argv[1:]]; runpy.run_module('haptex.examples.torch_mlp', run_name='__main__')",
             args.dataset, args.split, windows, "-o", os.path.join(args.work, "mlp.h5")], cwd=args.work)
    check(r.returncode == 2 and "python3-torch" in r.stderr and "Traceback" not in r.stderr,
          f"without torch, python -m haptex.examples.torch_mlp exits 2 saying: {r.stderr.strip()}")


def torch_part(args):
    try:
        import torch
    except ImportError:
        print("skipped: the torch loader (this Python cannot import torch; install python3-torch)")
        return
    import haptex
    import haptex.torch_model
    worst_abs, worst_scaled, count = 0.0, 0.0, 0
    for path in (args.model, args.per_material_model):
        net = haptex.torch_model.load(path)
        model = haptex.read_model(path)
        for material, force, speed in queries(model):
            q = haptex.predict_json(path, material=material, force=force, speed=speed, binary=args.haptex)["queries"][0]
            action = torch.tensor(np.r_[np.full(10, q["force_n"]), np.full(10, q["speed_mm_s"])], dtype=torch.float32)
            with torch.no_grad():
                spectrum = net(action[None, :], material=net.material_index(material))[0].numpy()
                saturated = bool(net.saturate(action[None, :])[1][0])
            worst_abs = max(worst_abs, float(np.max(np.abs(spectrum - np.asarray(q["spectrum"])))))
            worst_scaled = max(worst_scaled, scaled_error(spectrum, q["spectrum"]))
            count += 1
            if saturated != q["out_of_range"]:
                check(False, f"torch {material} {force} N {speed} mm/s: out_of_range {q['out_of_range']}, torch {saturated}")
        # A batch over every material at once gives the same as one at a time.
        actions = torch.tensor([[1.0] * 10 + [100.0] * 10] * len(model.ids))
        with torch.no_grad():
            batch = net(actions, material=torch.arange(len(model.ids)))
            single = torch.stack([net(actions[k], material=k) for k in range(len(model.ids))])
        check(torch.allclose(batch, single, rtol=1e-5, atol=1e-6), f"torch ({net.variant}): a batch of every material is each one's spectrum")
    peak, reference = press_images(args.dataset, args.work)
    out = haptex.predict_json(args.model, image=peak, reference=reference, force=2.0, speed=50.0, binary=args.haptex)
    net = haptex.torch_model.load(args.model)
    with torch.no_grad():
        image_latent = net.image_latent(torch.tensor(out["descriptor"]))
        latent = net.recognised(image_latent)
        spectrum = net(torch.tensor([2.0] * 10 + [50.0] * 10), latent=latent).numpy()
    latent_error = max(scaled_error(image_latent.numpy(), out["image_latent"]), scaled_error(latent.numpy(), out["latent"]))
    spectrum_error = scaled_error(spectrum, out["queries"][0]["spectrum"])
    worst_abs = max(worst_abs, float(np.max(np.abs(spectrum - np.asarray(out["queries"][0]["spectrum"])))))
    check(latent_error <= TOLERANCE and spectrum_error <= TOLERANCE,
          f"torch on a press image: latents scaled error {latent_error:.2g}, spectrum {spectrum_error:.2g}")
    check(worst_scaled <= TOLERANCE, f"torch vs haptex predict: max abs difference {worst_abs:.3g} m/s^2, worst scaled error "
                                     f"{worst_scaled:.2g} over {count + 1} spectra (torch {torch.__version__})")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name in ("--source", "--haptex", "--dataset", "--split", "--model", "--per-material-model", "--work"):
        p.add_argument(name, required=True)
    p.add_argument("--part", choices=("package", "torch"), help="one part only (default: both)")
    args = p.parse_args()
    if args.part in (None, "package"):
        package_part(args)
    if args.part in (None, "torch"):
        torch_part(args)
    if problems:
        print(f"{len(problems)} check(s) failed")
        return 1
    print("python package ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
