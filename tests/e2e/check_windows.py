"""Checks a windows file (haptex windows) and the kNN example's predictions for it, with h5py and numpy.

Usage: check_windows.py PYTHON_DIR DATASET.h5 SPLIT.json WINDOWS.h5 PREDS.h5
Prints one line per failed check and exits 1 when there is any; 0 and 'windows ok' otherwise.
"""
import sys

import h5py
import numpy as np

python_dir, dataset, split_path, windows_path, preds_path = sys.argv[1:6]
sys.path.insert(0, python_dir)
import haptex_data  # noqa: E402

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


split = haptex_data.read_split(split_path)
grid = haptex_data.read_windows(windows_path)
check(grid.dataset_sha256 == haptex_data.sha256_file(dataset), "dataset_sha256 is not the dataset's SHA-256")
check(grid.split_sha256 == haptex_data.sha256_file(split_path), "split_sha256 is not the split's SHA-256")
with h5py.File(windows_path, "r") as f:
    check(f.attrs["haptex_format"] == "windows/2", "haptex_format")
    check("haptex windows" in f.attrs["source"], "source does not name the command")

# The grid rule, from the split alone: per test section, windows every 100 samples from its first
# sample while 1000 fit, in order; nothing else.
expected = []
with h5py.File(dataset, "r") as f:
    for m, mid in enumerate(grid.materials):
        recordings = sorted(f[f"materials/{mid}/recordings"], key=str)
        for k in recordings:
            n = int(f[f"materials/{mid}/recordings/{k}"].attrs["samples"])
            for s in split.material_sections[mid]["test"]:
                begin, end = s * n // split.sections, (s + 1) * n // split.sections
                expected += [(m, int(k), s, t) for t in range(begin, end - 999, 100)]
got = sorted(zip(grid.material.tolist(), grid.recording.tolist(), grid.section.tolist(), grid.start.tolist()))
check(got == sorted(expected), f"the grid has {len(got)} windows, the rule gives {len(expected)}")
order = list(zip(grid.material.tolist(), grid.recording.tolist(), grid.section.tolist(), grid.start.tolist()))
check(all(a[0] <= b[0] for a, b in zip(order, order[1:])), "materials are not in the split's order")
for m, mid in enumerate(grid.materials):
    check(set(grid.press[grid.material == m].tolist()) == set(split.material_presses[mid]["test"]), f"{mid}: press is not the test press")

# Where a grid window is also one of align's windows, both carry the same action and spectrum.
table = haptex_data.read_set_windows(dataset, split, ("test",))
index = {(int(m), int(r), int(t)): i for i, (m, r, t) in enumerate(zip(table.material, table.recording, table.start))}
shared = [(i, index[key]) for i, key in enumerate(zip(grid.material.tolist(), grid.recording.tolist(), grid.start.tolist())) if key in index]
check(len(shared) > 0, "no grid window coincides with a dataset window")
for i, j in shared:
    check(np.array_equal(grid.action[i], table.action[j]), f"window {i}: action differs from the dataset's")
    check(np.allclose(grid.target[i], table.target[j], rtol=1e-4, atol=1e-6), f"window {i}: target differs from the dataset's")

# The predictions: one float32 row of 100 per window, in the windows file's order, its hashes.
with h5py.File(preds_path, "r") as f:
    spectra = f["spectra"][()]
    check(spectra.dtype == np.float32 and spectra.shape == (len(grid), 100), f"spectra is {spectra.dtype} {spectra.shape}")
    check(f.attrs["dataset_sha256"] == grid.dataset_sha256 and f.attrs["split_sha256"] == grid.split_sha256, "hashes")
train = haptex_data.read_set_windows(dataset, split, ("train",))
for i in sorted({0, len(grid) // 3, len(grid) // 2, len(grid) - 1}):
    # Row i, the slow way: the 8 training windows of its material nearest in standardised action.
    rows = np.flatnonzero(train.material == train.materials.index(grid.materials[grid.material[i]]))
    a = train.action[rows].astype(np.float64)
    scale = np.repeat([a[:, :10].std(), a[:, 10:].std()], 10)
    d = [np.sum(((a[r] - grid.action[i]) / scale) ** 2) for r in range(len(rows))]
    mean = train.target[rows][np.argsort(d, kind="stable")[:8]].astype(np.float64).mean(axis=0)
    check(np.allclose(spectra[i], mean, rtol=1e-5, atol=1e-7), f"prediction {i} is not the mean of its 8 nearest training windows")
check(np.mean(np.linalg.norm(spectra - grid.target, axis=1)) < np.mean(np.linalg.norm(spectra - grid.target[::-1], axis=1)),
      "predictions are nearer to the reversed windows than to their own")

# The torch Dataset, where torch imports: one (material, action, target) per row, as the table holds them.
if hasattr(haptex_data, "WindowDataset"):
    data = haptex_data.WindowDataset(grid)
    check(len(data) == len(grid), "WindowDataset: length")
    for i in sorted({0, len(grid) - 1}):
        material, action, target = data[i]
        check(int(material) == int(grid.material[i]) and np.array_equal(action.numpy(), grid.action[i])
              and np.array_equal(target.numpy(), grid.target[i]), f"WindowDataset: row {i}")
    print("torch Dataset checked")

# The presses a model would see: the split's training presses, RGB peaks as the dataset holds them.
for mid in grid.materials:
    presses = haptex_data.read_presses(dataset, split, mid, ("train",))
    check([p.press for p in presses] == split.material_presses[mid]["train"], f"{mid}: read_presses numbers")
    with h5py.File(dataset, "r") as f:
        check(all(np.array_equal(p.peak, haptex_data.decode_image(f[f"materials/{mid}/presses/{p.press}/peak"][0]))
                  and p.peak.shape == (f[f"materials/{mid}/presses/{p.press}"].attrs["height"],
                                       f[f"materials/{mid}/presses/{p.press}"].attrs["width"], 3) for p in presses),
              f"{mid}: read_presses peaks")
        for p in presses:  # the peak is the frame of its index among the stored frames
            g = f[f"materials/{mid}/presses/{p.press}"]
            k = list(g["frame_indices"][()]).index(g["peak_index"][()])
            check(np.array_equal(p.peak, haptex_data.decode_image(g["frames"][k])), f"{mid}: press {p.press}'s peak among its frames")

# grid_sections: the grid's test sections, each its consecutive rows of one material, recording and section.
sections = haptex_data.grid_sections(grid)
check(sum(rows for _, rows, _, _ in sections) == len(grid), "grid_sections: rows")
for first, rows, start, covered in sections:
    key = {(int(grid.material[i]), int(grid.recording[i]), int(grid.section[i])) for i in range(first, first + rows)}
    check(len(key) == 1 and start == grid.start[first] and covered == grid.start[first + rows - 1] - start + 1000,
          f"grid_sections: section at row {first}")

for line in failures:
    print(line)
print("windows ok" if not failures else f"{len(failures)} failed")
sys.exit(1 if failures else 0)
