"""haptex's PEP 517 build backend (pyproject.toml): writes the wheel (and an sdist) with the standard
library alone, so `pip install ./python` needs neither setuptools nor the network.

The wheel holds python/haptex/**.py, python/haptex_data.py (the old module's name), a generated
haptex/_version.py, and haptex-VERSION.dist-info/ with METADATA (from pyproject.toml's [project] and
README.md), WHEEL and RECORD. It only reads and zips files: nothing in the tree is run.
VERSION is CMakeLists.txt's project(haptex VERSION ...) beside this folder, or an sdist's PKG-INFO.
"""
import base64
import hashlib
import io
import os
import re
import tarfile
import zipfile

try:
    import tomllib
except ModuleNotFoundError:  # Python before 3.11
    import tomli as tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # python/
EPOCH = (1980, 1, 1, 0, 0, 0)  # fixed dates: the same tree gives the same wheel


def _project():
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        return tomllib.load(f)["project"]


def _version():
    pkg_info = os.path.join(ROOT, "PKG-INFO")  # only in an sdist
    if os.path.isfile(pkg_info):
        with open(pkg_info, encoding="utf-8") as f:
            found = re.search(r"^Version: (\S+)$", f.read(), re.M)
    else:
        try:
            with open(os.path.join(ROOT, "..", "CMakeLists.txt"), encoding="utf-8") as f:
                found = re.search(r"^project\(haptex\s+VERSION\s+([0-9][0-9.]*)", f.read(), re.M)
        except OSError:
            found = None
    if not found:
        raise RuntimeError(f"{ROOT}: no version: build from the haptex repository (python/ beside CMakeLists.txt) or its sdist")
    return found.group(1)


def _metadata(version):
    p = _project()
    lines = ["Metadata-Version: 2.1", f"Name: {p['name']}", f"Version: {version}", f"Summary: {p['description']}",
             f"Requires-Python: {p['requires-python']}"]
    lines += [f"Requires-Dist: {d}" for d in p.get("dependencies", [])]
    for extra, deps in p.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {d}; extra == "{extra}"' for d in deps]
    with open(os.path.join(ROOT, p["readme"]), encoding="utf-8") as f:
        readme = f.read()
    return "\n".join(lines + ["Description-Content-Type: text/markdown", "", readme])


def _sources():
    """(name in the archive, path) of the package's .py files, regular files only (no links)."""
    out = [("haptex_data.py", os.path.join(ROOT, "haptex_data.py"))]
    for folder, dirs, files in os.walk(os.path.join(ROOT, "haptex")):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__" and not os.path.islink(os.path.join(folder, d)))
        for name in sorted(files):
            path = os.path.join(folder, name)
            if name.endswith(".py") and name != "_version.py" and os.path.isfile(path) and not os.path.islink(path):
                out.append((os.path.relpath(path, ROOT).replace(os.sep, "/"), path))
    return out


def _read(path):
    with open(path, "rb") as f:
        return f.read()


def _add(archive, name, data, record):
    info = zipfile.ZipInfo(name, EPOCH)
    info.external_attr = 0o644 << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, data)
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    record.append(f"{name},sha256={digest},{len(data)}")


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version = _version()
    name = f"haptex-{version}-py3-none-any.whl"
    info, record = f"haptex-{version}.dist-info", []
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w") as wheel:
        for arcname, path in _sources():
            _add(wheel, arcname, _read(path), record)
        _add(wheel, "haptex/_version.py", f'version = "{version}"  # written by build_backend/haptex_build.py\n'.encode(), record)
        _add(wheel, f"{info}/METADATA", _metadata(version).encode("utf-8"), record)
        _add(wheel, f"{info}/WHEEL", b"Wheel-Version: 1.0\nGenerator: haptex_build\nRoot-Is-Purelib: true\nTag: py3-none-any\n", record)
        record.append(f"{info}/RECORD,,")
        _add(wheel, f"{info}/RECORD", ("\n".join(record) + "\n").encode(), [])
    return name


def build_sdist(sdist_directory, config_settings=None):
    version = _version()
    base = f"haptex-{version}"
    files = [("pyproject.toml", os.path.join(ROOT, "pyproject.toml")), ("README.md", os.path.join(ROOT, "README.md")),
             ("build_backend/haptex_build.py", os.path.abspath(__file__))] + _sources()
    with tarfile.open(os.path.join(sdist_directory, base + ".tar.gz"), "w:gz", format=tarfile.PAX_FORMAT) as sdist:
        for arcname, data in [(a, _read(p)) for a, p in files] + [("PKG-INFO", _metadata(version).encode("utf-8"))]:
            info = tarfile.TarInfo(f"{base}/{arcname}")
            info.size, info.mode, info.mtime = len(data), 0o644, 315532800
            sdist.addfile(info, io.BytesIO(data))
    return base + ".tar.gz"
