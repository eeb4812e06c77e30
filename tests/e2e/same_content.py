"""Compares two haptex HDF5 files with h5py, leaving their provenance aside: the same groups and
datasets, each dataset's dtype, shape, chunks, compression and values byte for byte, and every
attribute with its dtype and value; the root's attributes named after the files, and /shards (what a
merged file keeps of its inputs), are left out.

Usage: same_content.py A.h5 B.h5 [ROOT-ATTRIBUTE...]
Prints one line per difference and exits 1 when there is any; 0 and 'same content' otherwise.
"""
import sys

import h5py
import numpy as np


def objects(f):
    found = {}
    def visit(name, obj):
        if name != "shards" and not name.startswith("shards/"):
            found[name] = obj
    f.visititems(visit)
    return found


def same_value(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    if a.dtype.kind == "O":  # variable-length strings or bytes
        return all(np.array_equal(np.asarray(x), np.asarray(y)) for x, y in zip(a.ravel(), b.ravel()))
    return a.tobytes() == b.tobytes()


def compare_attributes(name, a, b, skip, problems):
    names_a, names_b = sorted(set(a.attrs) - skip), sorted(set(b.attrs) - skip)
    if names_a != names_b:
        problems.append(f"{name}: attributes {names_a} vs {names_b}")
    for key in set(names_a) & set(names_b):
        if a.attrs.get_id(key).dtype != b.attrs.get_id(key).dtype or not same_value(a.attrs[key], b.attrs[key]):
            problems.append(f"{name}@{key}: {a.attrs[key]!r} vs {b.attrs[key]!r}")


def compare_dataset(name, a, b, problems):
    for what in ("dtype", "shape", "chunks", "compression", "compression_opts", "shuffle"):
        if getattr(a, what) != getattr(b, what):
            problems.append(f"{name}: {what} {getattr(a, what)} vs {getattr(b, what)}")
            return
    if not same_value(a[()], b[()]):
        problems.append(f"{name}: values differ")


def main():
    path_a, path_b, skip = sys.argv[1], sys.argv[2], set(sys.argv[3:])
    problems = []
    with h5py.File(path_a, "r") as fa, h5py.File(path_b, "r") as fb:
        compare_attributes("/", fa, fb, skip, problems)
        a, b = objects(fa), objects(fb)
        if sorted(a) != sorted(b):
            problems.append(f"objects only in {path_a}: {sorted(set(a) - set(b))}; only in {path_b}: {sorted(set(b) - set(a))}")
        for name in sorted(set(a) & set(b)):
            if type(a[name]) is not type(b[name]):
                problems.append(f"{name}: a {type(a[name]).__name__} vs a {type(b[name]).__name__}")
                continue
            compare_attributes(name, a[name], b[name], set(), problems)
            if isinstance(a[name], h5py.Dataset):
                compare_dataset(name, a[name], b[name], problems)
    print("\n".join(problems + [f"{len(problems)} differences" if problems else "same content"]))
    return int(bool(problems))


if __name__ == "__main__":
    sys.exit(main())
