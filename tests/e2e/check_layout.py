"""Checks a haptex HDF5 file against the tables of schemas/hdf5-layout.md, with h5py.

Usage: check_layout.py LAYOUT.md FILE.h5 SECTION-KEYWORD [--own]
--own: the section's table alone, without 'Every file' (for files haptex reads but never writes).
Prints one line per violation and exits 1 when there is any; 0 and 'layout ok' otherwise.
"""
import re
import sys

import h5py
import numpy as np


def table_rows(markdown, keyword, common=True):
    """Rows of the 'Every file' table (when common) and of the table under the heading that contains keyword."""
    rows, section = [], None
    for line in markdown.splitlines():
        if line.startswith("## "):
            section = line
        elif line.startswith("| `") and section and ((common and "Every file" in section) or keyword in section):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            rows.append(dict(path=cells[0].strip("`"), dtype=cells[1], shape=cells[2], units=cells[3],
                             required=cells[4] == "always"))
    return rows


def objects(f, pattern):
    """Concrete paths of the groups or datasets matching a path with {placeholders}."""
    found = ["/"]
    for part in [p for p in pattern.strip("/").split("/") if p]:
        nxt = []
        for base in found:
            group = f[base]
            if not isinstance(group, h5py.Group):
                continue
            names = list(group) if part.startswith("{") else [part] if part in group else []
            nxt += [base.rstrip("/") + "/" + name for name in names]
        found = nxt
    return found


def dtype_name(value):
    if isinstance(value, (str, bytes)) or (hasattr(value, "dtype") and value.dtype.kind in "OSU"):
        return "string"
    return np.asarray(value).dtype.name


def check_dataset(obj, row, problems):
    if not isinstance(obj, h5py.Dataset):
        problems.append(f"{obj.name}: not a dataset")
        return
    name = "string" if h5py.check_string_dtype(obj.dtype) else obj.dtype.name
    if name != row["dtype"]:
        problems.append(f"{obj.name}: dtype {name}, expected {row['dtype']}")
    if row["units"] and obj.attrs.get("units") != row["units"]:
        problems.append(f"{obj.name}: units {obj.attrs.get('units')!r}, expected {row['units']!r}")
    # Symbolic extents: N is the recording's `samples` attribute; other letters are the length of
    # the sibling dataset they abbreviate (S: speeds, F: forces).
    siblings = {"S": "speeds", "F": "forces", "M": "materials", "W": "start"}
    def extent(d):
        if d == "N":
            return int(obj.parent.attrs.get("samples", -1))
        if d in siblings:
            return len(obj.parent[siblings[d]]) if siblings[d] in obj.parent else -1
        return int(d) if d.isdigit() else None  # other letters: any extent
    dims = [d for d in row["shape"].strip("()").replace(" ", "").split(",") if d]
    want = tuple(extent(d) for d in dims)
    if len(obj.shape) != len(want) or any(w is not None and w != got for w, got in zip(want, obj.shape)):
        problems.append(f"{obj.name}: shape {obj.shape}, expected {want}")


def check(f, row, problems):
    owner_pattern, _, attr = row["path"].partition("@")
    if attr:
        for owner in objects(f, owner_pattern):
            attrs = f[owner].attrs
            if attr not in attrs:
                if row["required"]:
                    problems.append(f"missing attribute: {owner}@{attr}")
            elif dtype_name(attrs[attr]) != row["dtype"]:
                problems.append(f"{owner}@{attr}: dtype {dtype_name(attrs[attr])}, expected {row['dtype']}")
        return
    parent, name = owner_pattern.rsplit("/", 1)
    for owner in objects(f, parent or "/"):
        if name not in f[owner]:
            if row["required"]:
                problems.append(f"missing: {owner}/{name}")
        else:
            check_dataset(f[owner][name], row, problems)


def main():
    layout, h5_path, keyword = sys.argv[1:4]
    rows = table_rows(open(layout, encoding="utf-8").read(), keyword, common="--own" not in sys.argv[4:])
    if not rows:
        print(f"no layout rows for {keyword!r}")
        return 1
    problems = []
    with h5py.File(h5_path, "r") as f:
        for row in rows:
            check(f, row, problems)
    for p in problems:
        print(p)
    print("layout ok" if not problems else f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
