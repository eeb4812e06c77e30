"""Read haptex's files from Python: a dataset's training windows as its split assigns them, and the
evaluation's grid (`haptex windows`), so a model trained in PyTorch learns from haptex's windows and
predicts for exactly the windows `haptex evaluate` scores; and write a predictions file for it.

Needs python3, numpy and h5py. `WindowDataset` (a torch.utils.data.Dataset) exists only when torch
imports (it is made on first use, so `import haptex` does not load torch). The file layouts are
schemas/hdf5-layout.md ("Dataset file", "Windows file", "Predictions file"); the split manifest is
schemas/split.schema.json. Until the package existed this was python/haptex_data.py, which still
imports as this module.
"""
import errno
import hashlib
import io
import json
import math
import os
import sys
from dataclasses import dataclass

import numpy as np

try:
    import h5py
except ImportError:
    raise ImportError("haptex needs h5py, which this Python cannot import: install python3-h5py "
                      "(Debian: apt-get install python3-h5py), or pip install h5py") from None

from .hdf5_probe import damage

WINDOW_SAMPLES = 1000  # dataset/window.hpp: a window uses samples [start, start + 1000)
ACTION_SAMPLES = 10    # the action: 10 force samples (N), then 10 speed samples (mm/s), 5 ms apart up to the middle
TARGET_BINS = 100      # 10, 20, ..., 1000 Hz
SETS = ("train", "val", "test")


class HaptexFileError(ValueError):
    """A file that is not what haptex wrote, or inputs that do not belong together."""


def sha256_file(path):
    digest = hashlib.sha256()
    with open(_regular_file(path), "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _regular_file(path):
    """path, after refusing what haptex refuses (core/input_file.hpp): a missing file, a folder, a FIFO,
    a socket, a device or a dangling link (a FIFO would block the reader forever)."""
    import stat
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        kind = "a symbolic link to a file that does not exist" if os.path.islink(path) else "missing"
        raise HaptexFileError(f"{path}: is {kind}: check the path") from None
    if not stat.S_ISREG(mode):
        raise HaptexFileError(f"{path}: is not a regular file (a folder, FIFO or device): give a regular file")
    return path


def open_hdf5(path, values=False):
    """The HDF5 file at path, read-only, once haptex-h5-probe has read it (hdf5_probe.py): its structure
    before h5py opens it, then the file h5py opened (a file renamed over the path meanwhile is probed
    too), with values its encoded images; a HaptexFileError naming the place where it finds damage."""
    with open(_regular_file(path), "rb") as before:
        _refuse_damage(path, before.fileno(), False, False)
    f = h5py.File(path, "r")
    try:
        for depth in (False, True) if values else (False,):
            _refuse_damage(path, f.id.get_vfd_handle(), depth, True)
    except HaptexFileError:
        f.close()
        raise
    return f


def _refuse_damage(path, fd, values, h5py_has_it):
    found = damage(fd, values=values, h5py_has_it=h5py_has_it)
    if found:
        place, finding, fix = found
        raise HaptexFileError(f"{path}: {place + ': ' if place else ''}{finding}; {fix[:1].lower() + fix[1:]}")


_MISSING = object()


def _attribute(obj, name, path, default=_MISSING):
    """obj.attrs[name] (`default` when it is missing and one is given); a HaptexFileError naming the file
    and the attribute when HDF5 cannot read it, as haptex names it (review 29, F1: h5py's bare text)."""
    try:
        if default is not _MISSING and name not in obj.attrs:
            return default
        return obj.attrs[name]
    except (KeyError, OSError, RuntimeError, ValueError) as e:
        raise HaptexFileError(f"{path}: {obj.name.rstrip('/')}/@{name}: HDF5 could not read it ({e}); the file is damaged: copy it "
                              f"again, or make it again with the haptex command that wrote it") from None


def _text(value, where=""):
    """A string attribute or element as text; a HaptexFileError naming `where` when it is no UTF-8
    text (review 15, R15: a traceback)."""
    if isinstance(value, bytes):
        try:
            return value.decode()
        except UnicodeDecodeError:
            raise HaptexFileError(f"{where or 'a text attribute'}: is not UTF-8 text; make the file again with the haptex command that wrote it") from None
    if not isinstance(value, str) and where:
        raise HaptexFileError(f"{where}: is {type(value).__name__}, not text; make the file again with the haptex command that wrote it")
    return str(value)


def _check_format(f, path, wanted):
    found = _text(_attribute(f, "haptex_format", path, ""))
    if found != wanted:
        raise HaptexFileError(f"{path}: /@haptex_format is '{found}', not {wanted}")


@dataclass
class Windows:
    """Rows of a /windows table. action is (W, 20) float32, target (W, 100) float32 in m/s^2;
    material indexes materials; section and press are -1 where the file does not say."""
    materials: list
    material: np.ndarray
    recording: np.ndarray
    section: np.ndarray
    start: np.ndarray
    press: np.ndarray
    action: np.ndarray
    target: np.ndarray
    dataset_sha256: str = ""
    split_sha256: str = ""

    def __len__(self):
        return len(self.start)

    def rows(self, keep):
        """The windows where the boolean mask `keep` holds, in order."""
        pick = lambda a: a[keep]
        return Windows(self.materials, pick(self.material), pick(self.recording), pick(self.section), pick(self.start),
                       pick(self.press), pick(self.action), pick(self.target), self.dataset_sha256, self.split_sha256)


def _read_table(group, path):
    def column(name, width=None):
        if name not in group:
            raise HaptexFileError(f"{path}: {group.name}/{name} is missing")
        a = group[name][()]
        if a.ndim != (1 if width is None else 2) or (width is not None and a.shape[1] != width):
            raise HaptexFileError(f"{path}: {group.name}/{name} has shape {a.shape}")
        return a
    n = len(column("start"))
    absent = np.full(n, -1, dtype=np.int32)
    w = Windows([_text(m, f"{path}: {group.name}/materials") for m in column("materials")], column("material"), column("recording"),
                column("section") if "section" in group else absent, column("start"),
                column("press") if "press" in group else absent,
                column("action", 2 * ACTION_SAMPLES), column("target", TARGET_BINS))
    if any(len(a) != n for a in (w.material, w.recording, w.section, w.press, w.action, w.target)):
        raise HaptexFileError(f"{path}: the columns of {group.name} differ in length")
    # The names the material column indexes: one material each, as haptex writes them (review 31, F3: an
    # empty or repeated name gave a traceback, or one material's predictions from another's windows).
    for i, name in enumerate(w.materials):
        if not name or name in w.materials[:i]:
            what = f"'{printable(name)}', named twice" if name else "empty"
            raise HaptexFileError(f"{path}: {group.name}/materials[{i}] is {what}; make the file again with the haptex "
                                  "command that wrote it")
    # Numbers that index something: a negative material index would pick another material from the
    # end of the list (review 15, R15).
    for name, values, least, most in (("material", w.material, 0, len(w.materials) - 1), ("recording", w.recording, 0, None),
                                      ("section", w.section, -1, None), ("press", w.press, -1, None), ("start", w.start, 0, None)):
        if values.dtype.kind not in "iu":
            raise HaptexFileError(f"{path}: {group.name}/{name} holds {values.dtype} values, not whole numbers; "
                                  "make the file again with the haptex command that wrote it")
        bad = np.flatnonzero((values < least) | (values > most if most is not None else False))
        if bad.size:
            allowed = f"{least} to {most}" if most is not None else f"{least} or more"
            raise HaptexFileError(f"{path}: {group.name}/{name} row {bad[0]} is {values[bad[0]]}, not {allowed}; "
                                  "make the file again with the haptex command that wrote it")
    # As haptex's own readers: a NaN or infinite action or target is a damaged file (review 10, F7).
    for name, values in (("action", w.action), ("target", w.target)):
        bad = np.flatnonzero(~np.isfinite(values).all(axis=1))
        if bad.size:
            raise HaptexFileError(f"{path}: {group.name}/{name} row {bad[0]} holds a value that is not finite; "
                                  "make the file again with the haptex command that wrote it")
    return w


def read_windows(path):
    """The evaluation's grid written by `haptex windows` (windows/2), in the order evaluate scores it."""
    try:
        f = open_hdf5(path)
    except OSError as e:
        raise HaptexFileError(f"{path}: not an HDF5 file haptex windows wrote ({e}); make it again with haptex windows") from None
    with f:
        _check_format(f, path, "windows/2")
        require_plain_objects(f, path)
        w = _read_table(f["windows"], path)
        w.dataset_sha256 = _text(_attribute(f, "dataset_sha256", path), f"{path}: /@dataset_sha256")
        w.split_sha256 = _text(_attribute(f, "split_sha256", path), f"{path}: /@split_sha256")
    return w


@dataclass
class Split:
    """A split manifest (split/1): per material id its section numbers and press numbers per set."""
    path: str
    sha256: str
    dataset_sha256: str
    sections: int
    material_sections: dict  # id -> {"train": [...], "val": [...], "test": [...]}
    material_presses: dict   # id -> {"train": [...], "val": [...], "test": [...]}


_LARGEST_JSON = 64 << 20  # README: JSON inputs over 64 MiB, deeper than 64 levels, ... are refused
_DEEPEST_JSON = 64


def _no_key_twice(pairs):
    out = {}
    for k, v in pairs:
        if k in out:
            raise HaptexFileError(f"the key '{k}' is given twice in one object (JSON readers differ in which they keep)")
        if "\0" in k or (isinstance(v, str) and "\0" in v):
            raise HaptexFileError(f"holds a NUL character at '{k}', which no name may hold")
        out[k] = v
    return out


def _whole(text):
    if len(text.lstrip("-")) > 300:  # beyond 64-bit floats, as haptex's reader says (and Python's 4300-digit limit)
        raise HaptexFileError(f"holds a number of {len(text)} digits, beyond 64-bit floats")
    return int(text)


def _no_constant(name):
    raise HaptexFileError(f"holds {name}, which is not a JSON number")


def _finite(text):
    value = float(text)
    if not math.isfinite(value):
        raise HaptexFileError(f"holds {text}, a number beyond 64-bit floats")
    return value


def _depth(value, deepest=_DEEPEST_JSON):
    """Nesting depth, refusing past `deepest` without recursing further."""
    stack, most = [(value, 1)], 0
    while stack:
        v, d = stack.pop()
        if isinstance(v, (dict, list)):
            if d > deepest:
                raise HaptexFileError(f"nests deeper than {deepest} levels")
            most = max(most, d)
            stack.extend((c, d + 1) for c in (v.values() if isinstance(v, dict) else v))
    return most


def _numbers(values, where, below):
    """A list of distinct whole numbers in [0, below)."""
    if not isinstance(values, list) or any(isinstance(v, bool) or not isinstance(v, int) or not 0 <= v < below for v in values):
        raise HaptexFileError(f"{where} must list whole numbers from 0 to {below - 1}")
    if len(set(values)) != len(values):
        raise HaptexFileError(f"{where} lists a number twice")
    return values


def _sets(entry, key, where, below):
    """{train, val, test} -> lists of numbers, no number in two sets: a number in two sets leaks."""
    sets = entry.get(key) if isinstance(entry, dict) else None
    if not isinstance(sets, dict) or sorted(sets) != sorted(SETS):
        raise HaptexFileError(f"{where}/{key} must hold train, val and test")
    seen = {}
    for name in SETS:
        for v in _numbers(sets[name], f"{where}/{key}/{name}", below):
            if v in seen:
                raise HaptexFileError(f"{where}/{key}: {v} is in {seen[v]} and {name}, so the split leaks between them")
            seen[v] = name
    return sets


def strict_json(text, where):
    """JSON as haptex's reader takes it (README): no key twice, no NaN, no number beyond 64-bit floats
    or of 300 digits, no NUL in a key or in an object's text value, at most 64 levels deep. Raises HaptexFileError
    ("WHERE: what")."""
    try:
        try:
            doc = json.loads(text, object_pairs_hook=_no_key_twice, parse_constant=_no_constant,
                             parse_float=_finite, parse_int=_whole)
        except RecursionError:
            raise HaptexFileError(f"nests deeper than {_DEEPEST_JSON} levels") from None
        except json.JSONDecodeError as e:
            raise HaptexFileError(f"is not JSON ({e})") from None
        _depth(doc)
        return doc
    except HaptexFileError as e:
        raise HaptexFileError(f"{where}: {e}") from None


_MOST_BYTES_READ = 4 << 30   # core/h5/node.hpp kMostBytesRead: no dataset haptex writes comes near it
_MOST_TEXTS = 1000000        # kMostTexts: the longest list of names


def _require_sensible_size(d, path):
    """Refuses, from the shape alone, a dataset declaring more than haptex reads (review 22, F4: a 340 KB
    file declaring 64 GiB or 3.5 million names in chunks never written)."""
    count = int(np.prod(d.shape, dtype=np.float64)) if d.shape else 1
    if count * d.dtype.itemsize > _MOST_BYTES_READ:
        raise HaptexFileError(f"{path}: {d.name}: declares {count} values ({count * d.dtype.itemsize / 2**30:.1f} GiB), "
                              f"more than haptex reads at once")
    if d.dtype.kind in "SOU" and count > _MOST_TEXTS:
        raise HaptexFileError(f"{path}: {d.name}: holds {count} strings, more than a list of names haptex writes ({_MOST_TEXTS} at most)")


_DEEPEST_GROUPS = 1024  # core/h5/link_rule.hpp's kDeepestGroups: 5 levels, plus 2 a round of merging merged files


def require_plain_objects(f, path):
    """README's rule for HDF5 inputs: no soft or external link, no dataset whose values are kept outside
    the file (external storage, virtual datasets), no group nested deeper than haptex's readers walk.
    Raises HaptexFileError naming the object. Each object is looked at once (hard links that loop
    included), soft and external links are refused without being followed, and the walk is a loop with
    its depth bounded: h5py's visititems builds each object's whole path, so a chain of 30 000 groups
    did not end in 100 s (review 23, F8)."""
    seen = {f.id}
    groups = [(f["/"], 1)]
    while groups:
        group, depth = groups.pop()
        for name in group:
            if isinstance(name, bytes):  # h5py hands over a name that is not UTF-8 as bytes, then refuses it back
                try:
                    name.decode("utf-8")
                    bad = len(name)
                except UnicodeDecodeError as e:
                    bad = e.start
                shown = printable(f"{group.name.rstrip('/')}/{name.decode('utf-8', 'surrogateescape')}")
                raise HaptexFileError(f"{path}: {shown}: is not valid UTF-8 (byte {bad} of the name); write it in UTF-8, "
                                      "as haptex names every object")
            member = f"{group.name.rstrip('/')}/{name}"
            link = group.get(name, getlink=True)
            if isinstance(link, (h5py.SoftLink, h5py.ExternalLink)):
                kind = "a soft" if isinstance(link, h5py.SoftLink) else "an external"
                raise HaptexFileError(f"{path}: {member}: is {kind} link; haptex reads only objects stored in the file itself")
            obj = group[name]
            if obj.id in seen:
                continue
            seen.add(obj.id)
            if isinstance(obj, h5py.Dataset):
                if obj.external or obj.is_virtual:
                    raise HaptexFileError(f"{path}: {member}: keeps its values outside the file")
                _require_sensible_size(obj, path)
            elif isinstance(obj, h5py.Group):
                if depth > _DEEPEST_GROUPS:  # the members of a group taken at `depth` are `depth` levels deep
                    raise HaptexFileError(f"{path}: {member}: is a group {depth} levels deep; no haptex file nests groups "
                                          f"beyond {_DEEPEST_GROUPS}")
                groups.append((obj, depth + 1))
            else:
                raise HaptexFileError(f"{path}: {member}: is neither a group nor a dataset (a named datatype?)")


def read_split(path):
    """A split manifest, held to what haptex's split reader holds it to (the JSON rules of README and the
    sets' rules of schemas/split.schema.json: no section or press in two sets)."""
    with open(_regular_file(path), "rb") as f:
        raw = f.read(_LARGEST_JSON + 1)
    try:
        if len(raw) > _LARGEST_JSON:
            raise HaptexFileError(f"is over {_LARGEST_JSON >> 20} MiB")
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as e:
            raise HaptexFileError(f"not a JSON split manifest ({e}); give the file haptex split wrote") from None
        doc = strict_json(text, "the manifest")
        if not isinstance(doc, dict) or doc.get("format") != "split/1":
            found = doc.get("format") if isinstance(doc, dict) else type(doc).__name__
            raise HaptexFileError(f"format is '{found}', not split/1 (haptex split writes it)")
        try:
            sections = doc["parameters"]["sections"]
            if isinstance(sections, bool) or not isinstance(sections, int) or not 3 <= sections <= 10000:
                raise HaptexFileError("/parameters/sections must be a whole number from 3 to 10000")
            materials = doc["materials"]
            ids = [m["id"] for m in materials]
            if len(set(ids)) != len(ids):
                raise HaptexFileError("/materials names one material twice")
            material_sections = {m["id"]: _sets(m, "sections", f"/materials/{i}", sections) for i, m in enumerate(materials)}
            material_presses = {m["id"]: _sets(m, "presses", f"/materials/{i}", 1 << 31) for i, m in enumerate(materials)}
            return Split(path, hashlib.sha256(raw).hexdigest(), doc["dataset"]["sha256"], sections, material_sections, material_presses)
        except (KeyError, TypeError) as e:
            raise HaptexFileError(f"not a split manifest as haptex split writes it (at {e!r}); schemas/split.schema.json") from None
    except HaptexFileError as e:
        message = str(e)
        raise HaptexFileError(message if message.startswith(str(path)) else f"{path}: {message}") from None


def _section_begin(s, samples, sections):
    return s * samples // sections


def section_of(start, samples, sections):
    """The section holding windows [start, start + 1000) of a recording, -1 for a window crossing a
    boundary: split/sections.cpp's rule (section_begin(s) = s * samples // sections), vectorised."""
    start = np.asarray(start, dtype=np.int64)
    s = start * sections // samples
    s = np.where((s + 1 < sections) & (_section_begin(s + 1, samples, sections) <= start), s + 1, s)
    s = np.where((s > 0) & (_section_begin(s, samples, sections) > start), s - 1, s)
    inside = (start >= 0) & (start + WINDOW_SAMPLES <= _section_begin(s + 1, samples, sections))
    return np.where(inside, s, -1)


def read_set_windows(dataset_path, split, sets=("train",)):
    """The dataset's /windows rows lying wholly inside a section of `sets` (as haptex train reads them),
    with their section numbers. Refuses a split made from another dataset file."""
    if sha256_file(dataset_path) != split.dataset_sha256:
        raise HaptexFileError(f"{split.path}: was made from another dataset than {dataset_path} (dataset.sha256)")
    with open_hdf5(dataset_path) as f:
        _check_format(f, dataset_path, "dataset/4")
        require_plain_objects(f, dataset_path)
        w = _read_table(f["windows"], dataset_path)
        keep = np.zeros(len(w), dtype=bool)
        for m, material_id in enumerate(w.materials):
            wanted = [s for name in sets for s in split.material_sections[material_id][name]]
            for k in np.unique(w.recording[w.material == m]):
                rows = (w.material == m) & (w.recording == k)
                samples = int(_attribute(f[f"materials/{material_id}/recordings/{k}"], "samples", dataset_path))
                w.section[rows] = section_of(w.start[rows], samples, split.sections)
                keep |= rows & np.isin(w.section, wanted)
    w.dataset_sha256, w.split_sha256 = split.dataset_sha256, split.sha256
    return w.rows(keep)


@dataclass
class Press:
    """One GelSight press of a material (/materials/{id}/presses/{press} of a dataset file): the peak
    frame and the no-contact reference, (H, W, 3) uint8 in RGB order."""
    material: str
    press: int
    peak: np.ndarray
    reference: np.ndarray


def decode_image(encoded, order="RGB"):
    """One encoded image of a dataset (a JPEG or PNG, as a uint8 array) as (H, W, 3) uint8 RGB; `order`
    is the press's channel_order (BGR: the stored pixels hold blue first)."""
    from PIL import Image  # python3-pil; only readers of images need it
    rgb = np.asarray(Image.open(io.BytesIO(np.asarray(encoded, dtype=np.uint8).tobytes())).convert("RGB"))
    return np.ascontiguousarray(rgb if order == "RGB" else rgb[..., ::-1])


def read_presses(dataset_path, split, material_id, sets=("train",)):
    """The presses of one material that `sets` of the split hold, in the split's order. A press stored
    in BGR order is turned to RGB; another order is refused."""
    if sha256_file(dataset_path) != split.dataset_sha256:
        raise HaptexFileError(f"{split.path}: was made from another dataset than {dataset_path} (dataset.sha256)")
    numbers = [p for name in sets for p in split.material_presses[material_id][name]]
    out = []
    with open_hdf5(dataset_path, values=True) as f:
        _check_format(f, dataset_path, "dataset/4")
        require_plain_objects(f, dataset_path)
        for j in numbers:
            g = f[f"materials/{material_id}/presses/{j}"]
            order = _text(_attribute(g, "channel_order", dataset_path, ""))
            if order not in ("RGB", "BGR"):
                raise HaptexFileError(f"{dataset_path}: {g.name}/@channel_order is '{order}', not RGB or BGR")
            out.append(Press(material_id, j, decode_image(g["peak"][0], order), decode_image(g["reference"][0], order)))
    return out


def read_split_and_grid(split_path, windows_path):
    """The split manifest and the windows file made with it; refuses a windows file made from another
    dataset or split."""
    split = read_split(split_path)
    grid = read_windows(windows_path)
    if (grid.dataset_sha256, grid.split_sha256) != (split.dataset_sha256, split.sha256):
        raise HaptexFileError(f"{windows_path} was made from another dataset or split than {split_path}")
    for i, name in enumerate(grid.materials):
        if name not in split.material_sections:
            raise HaptexFileError(f"{windows_path}: /windows/materials[{i}] is '{printable(name)}', a material {split_path} does not "
                                  "hold; make the windows file again with haptex windows")
    return split, grid


def leave(code):
    """Exits with code without running exit handlers: after a failed write (a full disk) HDF5's own
    handler crashes closing the file h5py left open (exit 139 instead of the error). Everything the
    examples wrote is flushed or already removed by then."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


def _acts_on_text(u):
    """core/text/utf8.hpp's acts_on_text: a control character (C0, DEL, C1) or an invisible format
    character that reorders or breaks the text around it (bidirectional overrides such as U+202E,
    zero-width characters, line separators, tag characters). tests/hostile/python_examples_test.cpp
    checks the two agree on every code point."""
    return (u < 0x20 or u == 0x7f or 0x80 <= u <= 0x9f or u in (0xad, 0x061c, 0x180e, 0xfeff) or 0x200b <= u <= 0x200f
            or 0x2028 <= u <= 0x202e or 0x2060 <= u <= 0x206f or 0xfff9 <= u <= 0xfffb or 0xe0000 <= u <= 0xe007f)


def printable(text):
    """text as a terminal may show it, as haptex prints names: each character _acts_on_text names as
    \\xHH (below U+0080), \\uHHHH or \\UHHHHHHHH; a byte that is not UTF-8 (a file name's surrogate
    escape) as \\xHH. An attribute holding ESC[2J would clear the screen if printed as it is."""
    out = []
    for c in str(text):
        u = ord(c)
        if 0xdc80 <= u <= 0xdcff:
            out.append(f"\\x{u - 0xdc00:02x}")
        elif 0xd800 <= u <= 0xdfff or _acts_on_text(u):
            out.append(f"\\x{u:02x}" if u < 0x80 else f"\\u{u:04x}" if u <= 0xffff else f"\\U{u:08x}")
        else:
            out.append(c)
    return "".join(out)


def exit_code_for(error):
    """1 when the work failed (a write: a full disk, a read-only folder), 2 for bad input."""
    return 1 if isinstance(error, OSError) and error.errno in (errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EIO) else 2


def example_arguments(description):
    """An argparse parser with what every example takes: DATASET SPLIT WINDOWS -o PREDS [--force]."""
    import argparse
    p = argparse.ArgumentParser(description=description)
    p.add_argument("dataset")
    p.add_argument("split")
    p.add_argument("windows")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--force", action="store_true", help="replace an earlier predictions file")
    return p


PREDICTIONS_FORMAT = "predictions/1"  # schemas/hdf5-layout.md, "Predictions file"


def grid_sections(grid):
    """The grid's test sections in its order: per section (first row, rows, first sample, samples
    covered), where a section's windows are rows [first row, first row + rows) and a signal of the
    section starts at its first sample and covers at least `samples covered` samples."""
    key = np.stack([grid.material, grid.recording, grid.section], axis=1)
    change = np.flatnonzero(np.any(key[1:] != key[:-1], axis=1)) + 1
    firsts = np.concatenate([[0], change]) if len(grid) else np.array([], dtype=np.int64)
    ends = np.concatenate([change, [len(grid)]]) if len(grid) else np.array([], dtype=np.int64)
    return [(int(a), int(b - a), int(grid.start[a]), int(grid.start[b - 1] - grid.start[a]) + WINDOW_SAMPLES)
            for a, b in zip(firsts, ends)]


def write_predictions(path, grid, spectra, source, query_seconds=None, signals=None, signal_seconds=None,
                      inputs=(), overwrite=False):
    """A predictions file for `haptex evaluate --predictions NAME=path`: spectra (W, 100), row i for
    window i of `grid`; optionally one signal per grid section (grid_sections) and the compute
    times. Refuses a path that is one of `inputs` (the same file by any name), an existing file
    unless `overwrite`, and with `overwrite` any file but an earlier predictions file. Written to a
    new temporary name beside path and renamed (docs/architecture.md, "Outputs are atomic"), so a
    failed run leaves no half file and touches nothing else."""
    check_output(path, inputs, overwrite)
    spectra = np.asarray(spectra, dtype=np.float32)
    if spectra.shape != (len(grid), TARGET_BINS):
        raise HaptexFileError(f"{path}: {spectra.shape} spectra for a grid of {len(grid)} windows")
    # What haptex evaluate would refuse, refused here before anything is written.
    if not np.all(np.isfinite(spectra)) or spectra.min(initial=0) < 0 or spectra.max(initial=0) > 1e6:
        raise HaptexFileError(f"{path}: spectra must be finite amplitudes of 0 to 1e6 m/s^2 (clamp the model's output at 0)")
    for name, seconds in (("query_seconds", query_seconds), ("signal_seconds", signal_seconds)):
        if seconds is not None and not (np.isfinite(seconds) and seconds > 0):
            raise HaptexFileError(f"{path}: {name} is {seconds}, expected a compute time in seconds above 0")
    if signals is not None:
        sections = grid_sections(grid)
        if len(signals) != len(sections) or any(len(x) < covered for x, (_, _, _, covered) in zip(signals, sections)):
            raise HaptexFileError(f"{path}: give one signal per grid section ({len(sections)}), each covering its windows (grid_sections)")
    image = _predictions_image(grid, spectra, source, query_seconds, signals, signal_seconds)
    partial, fd = _temporary_file(path)
    restore = _remove_on_signals(partial)
    try:
        _write_whole(fd, path, image)
        _put_in_place(partial, fd, path, inputs, overwrite)
        partial = None
    finally:
        os.close(fd)
        if partial is not None and os.path.lexists(partial):
            os.remove(partial)  # the name only: a link swapped in is removed, never what it points at
        restore()


def _predictions_image(grid, spectra, source, query_seconds, signals, signal_seconds):
    """The predictions file's bytes, made in memory: HDF5 never meets a full disk, where h5py fails
    inside close() and can then crash the interpreter (review 12, F5); the bytes are read back and
    compared with what was meant before they are written."""
    memory = io.BytesIO()
    with h5py.File(memory, "w") as f:
        f.attrs["predictions_format"] = PREDICTIONS_FORMAT
        f.attrs["dataset_sha256"] = grid.dataset_sha256
        f.attrs["split_sha256"] = grid.split_sha256
        f.attrs["source"] = source
        if query_seconds is not None:
            f.attrs["query_seconds"] = float(query_seconds)
        f.create_dataset("spectra", data=spectra)
        if signals is not None:
            g = f.create_group("signals")
            for k, x in enumerate(signals):
                g.create_dataset(str(k), data=np.asarray(x, dtype=np.float32))
            if signal_seconds is not None:
                g.attrs["seconds"] = float(signal_seconds)
    image = memory.getvalue()
    if not _holds(io.BytesIO(image), spectra, signals):
        raise HaptexFileError("the predictions file made in memory does not read back as written")
    return image


def _write_whole(fd, path, image):
    """Writes image through fd, the descriptor of the exclusive create (never the name again: another
    program writing the folder may have swapped it, review 15, R11), and syncs it; a full disk is one
    OSError naming path."""
    try:
        view = memoryview(image)
        while view:
            view = view[os.write(fd, view):]
        os.fsync(fd)
    except OSError as e:
        raise OSError(e.errno, f"{path}: could not be written completely ({e.strerror}; the disk is full?)") from None


def _still_names(name, fd):
    """Whether name is still the file fd was opened on (core/temporary_name.hpp, still_names)."""
    try:
        here, made = os.lstat(name), os.fstat(fd)
    except OSError:
        return False
    return (here.st_dev, here.st_ino) == (made.st_dev, made.st_ino)


def _require_still_named(name, fd, path):
    """An OSError (exit 1: the work failed) unless name is still the file this run made."""
    if not _still_names(name, fd):
        raise OSError(errno.EIO, f"{path}: its temporary {name} was replaced by another program writing the folder "
                                 "while this run wrote it; nothing was put in place. Find out what writes there, and run again")


def _holds(source, spectra, signals):
    """Whether the HDF5 file at source (a path or a file object) holds the format mark, the spectra and the signals written."""
    try:
        with h5py.File(source, "r") as f:
            if f.attrs["predictions_format"] != PREDICTIONS_FORMAT or not np.array_equal(f["spectra"][...], spectra):
                return False
            return signals is None or all(np.array_equal(f["signals"][str(k)][...], np.asarray(x, dtype=np.float32))
                                          for k, x in enumerate(signals))
    except (OSError, KeyError):
        return False


def _put_in_place(partial, fd, path, inputs, overwrite):
    """Renames partial to path, once it is sure partial is still the file this run wrote (fd), and
    checks path is that file afterwards. Without overwrite a file that appeared at path meanwhile is
    kept (a hard link never replaces, as RENAME_NOREPLACE); with it, path is checked again just before
    the swap."""
    _require_still_named(partial, fd, path)
    if not overwrite:
        try:
            os.link(partial, path)
        except FileExistsError:
            raise HaptexFileError(f"{path}: appeared while this run was writing it, and is kept: "
                                  "move it away and run again, or choose another output name") from None
        except OSError:  # a file system without hard links: the last look, then the rename
            check_output(path, inputs, overwrite)
            os.rename(partial, path)
            _take_back_unless_ours(path, fd)
            return
        if not _still_names(path, fd):  # the name was swapped between the look and the link
            os.remove(path)  # the link this run just made, not the file it names
            _require_still_named(partial, fd, path)
        os.remove(partial)
        return
    check_output(path, inputs, overwrite)
    os.replace(partial, path)
    _take_back_unless_ours(path, fd)


def _take_back_unless_ours(path, fd):
    """After a rename: when what reached path is not this run's file (the temporary was swapped in the
    instant between the last look and the rename), its name is taken away again (a link or a name of
    another's file, never the file it names), and the run fails."""
    if not _still_names(path, fd):
        os.remove(path)
        _require_still_named(path, fd, path)


def _remove_on_signals(partial):
    """Until the returned function is called, Ctrl-C, TERM and HUP remove partial and then end the
    process by the same signal (README: only kill -9 or a crash leaves a .partial behind). A signal
    the process ignores (nohup, `cmd &`) stays ignored. Python takes signals in its main thread only:
    called from another, it changes nothing."""
    import signal
    import threading
    before = {}
    if threading.current_thread() is not threading.main_thread():
        return lambda: None

    def end(number, _frame):
        try:
            os.remove(partial)
        except FileNotFoundError:
            pass
        signal.signal(number, signal.SIG_DFL)
        os.kill(os.getpid(), number)

    for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        if signal.getsignal(number) != signal.SIG_IGN:
            before[number] = signal.signal(number, end)

    def restore():
        for number, handler in before.items():
            signal.signal(number, handler)
    return restore


def check_output(path, inputs=(), overwrite=False):
    """Raises HaptexFileError when write_predictions would refuse path (call it before the work)."""
    if not path:
        raise HaptexFileError("the output name is empty: name a file with -o")
    try:
        path.encode("utf-8")
    except UnicodeEncodeError as e:
        byte = os.fsencode(path[e.start:e.start + 1])[0]
        raise HaptexFileError(f"{path!r}: the output name is not valid UTF-8 (byte 0x{byte:02x} at character {e.start}): "
                              "name it in UTF-8") from None
    for given in inputs:
        if os.path.exists(path) and os.path.exists(given) and os.path.samefile(path, given):
            raise HaptexFileError(f"{path}: is also an input ({given}): choose another output name")
    folder = os.path.dirname(path) or "."
    if not os.path.isdir(folder):
        raise HaptexFileError(f"{path}: the output folder {folder} does not exist: create it first")
    if not os.path.lexists(path):
        return
    if os.path.islink(path) or not os.path.isfile(path):
        raise HaptexFileError(f"{path}: the output path is a link, a folder, a FIFO or a device: choose another -o")
    if not overwrite:
        raise HaptexFileError(f"{path}: the output file already exists: remove it, choose another -o, or pass --force")
    try:
        with open_hdf5(path) as f:
            found = f.attrs.get("predictions_format")
    except OSError:
        found = None
    found = found.decode("utf-8", "replace") if isinstance(found, bytes) else found
    if isinstance(found, str) and _version(found) is not None and _version(found) > _version(PREDICTIONS_FORMAT):
        raise HaptexFileError(f"{path}: is {found}, written by a newer haptex than {PREDICTIONS_FORMAT}: "
                              "--force does not replace it; choose another output name")
    if not isinstance(found, str) or _version(found) is None or os.path.islink(path):
        raise HaptexFileError(f"{path}: --force replaces only an earlier predictions file, and this is not one: "
                              "choose another output name, or move the file away yourself")


def _version(mark):
    """N of a "predictions/N" mark as haptex writes it (no sign, no leading zero), else None."""
    import re
    found = re.fullmatch(r"predictions/([1-9][0-9]*)", mark)
    return int(found.group(1)) if found else None


def _temporary_file(path):
    """A new empty file at PATH.<8 letters and digits>.partial, created exclusively (core/temporary_name.hpp
    holds the rule): a name that exists is never opened, followed or reused. Returns the name and the
    open descriptor, through which alone the file is written."""
    import secrets
    import string
    letters = string.ascii_letters + string.digits
    for _ in range(100):
        partial = path + "." + "".join(secrets.choice(letters) for _ in range(8)) + ".partial"
        try:
            return partial, os.open(partial, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o666)
        except FileExistsError:
            continue
        except OSError as e:  # a read-only or full file system, a folder without write permission
            raise HaptexFileError(f"{path}: cannot write beside it ({e.strerror}): choose a folder you can write to") from None
    raise HaptexFileError(f"{path}: no free temporary name beside it")


def _window_dataset_class():
    import torch
    from torch.utils.data import Dataset

    class WindowDataset(Dataset):
        """(material, action, target) tensors of a Windows table: int64, float32 (20), float32 (100)."""

        def __init__(self, windows):
            self.windows = windows

        def __len__(self):
            return len(self.windows)

        def __getitem__(self, i):
            w = self.windows
            return (torch.tensor(int(w.material[i])), torch.from_numpy(np.asarray(w.action[i], dtype=np.float32)),
                    torch.from_numpy(np.asarray(w.target[i], dtype=np.float32)))
    WindowDataset.__module__ = __name__
    return WindowDataset


def __getattr__(name):
    """WindowDataset, made when first asked for: torch is optional, and numpy users need none of it
    (without torch the attribute does not exist, so hasattr(data, "WindowDataset") says whether it does)."""
    if name == "WindowDataset":
        try:
            cls = _window_dataset_class()
        except ImportError:
            raise AttributeError("WindowDataset needs PyTorch, which this Python cannot import "
                                 "(on Debian: apt-get install python3-torch)") from None
        globals()[name] = cls
        return cls
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
