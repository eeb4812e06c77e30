"""Damaged HDF5 files, read as haptex reads them (docs/architecture.md, "Damaged files"): libhdf5 1.10,
which h5py uses too, crashes or loops on some damage with no error to catch (review 30, F2: a windows
file with one wrong size in its global heap killed the examples). So each HDF5 file is first read by
haptex-h5-probe, installed with the haptex binary, in a process of its own: before h5py opens it, and
again through h5py's own descriptor when that is another file (data.open_hdf5). Without the probe (no
haptex binary found), files are read unprobed."""
import glob
import os
import shutil
import signal
import subprocess

# tools/h5-probe/main.cpp's exit codes: 0 read, 1 HDF5 refused a read (place, finding, fix follow), 3 not opened.
_REFUSED, _NOT_OPENED = 1, 3
_CRASHES = {signal.SIGSEGV, signal.SIGBUS, signal.SIGABRT, signal.SIGFPE, signal.SIGILL}


def probe_program():
    """haptex-h5-probe beside the haptex binary ($HAPTEX_BINARY, else haptex on PATH) as built, or
    where an installation puts it (lib/haptex or lib/<multiarch>/haptex beside bin/); None without."""
    binary = os.environ.get("HAPTEX_BINARY") or shutil.which("haptex")
    if not binary:
        return None
    here = os.path.dirname(os.path.realpath(binary))
    candidates = [os.path.join(here, "haptex-h5-probe"), os.path.join(here, "..", "lib", "haptex", "haptex-h5-probe")]
    candidates += sorted(glob.glob(os.path.join(here, "..", "lib", "*", "haptex", "haptex-h5-probe")))
    return next((c for c in candidates if os.access(c, os.X_OK)), None)


def _run(program, fd, values, as_is):
    argv = [program] + (["--values"] if values else []) + [f"/dev/fd/{fd}"]
    environment = dict(os.environ, HAPTEX_PROBE_AS_IS="1") if as_is else None
    try:
        run = subprocess.run(argv, pass_fds=(fd,), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, env=environment)
    except OSError as e:  # not started (no descriptor or memory left): an end that says nothing of the file
        return 127, str(e).encode()
    return run.returncode, run.stdout


def _records(output):
    if output.endswith(b"\0"):
        output = output[:-1]
    return [r.decode("utf-8", "replace") for r in output.split(b"\0")]


_said = {}  # what the probe said of each file (device, inode, size, modification time, depth) in this process


def damage(fd, values=False, h5py_has_it=False):
    """What the probe finds reading the file open as `fd` (its structure; with values, its
    variable-length byte values: encoded images): None when it read it all (or cannot run), else
    (place, finding, fix). Each file is probed once per depth. A file the probe cannot open is no
    verdict before h5py opens it (h5py says why), and damage once h5py has it open."""
    program = probe_program()
    if program is None:
        return None
    s = os.fstat(fd)
    version = (s.st_dev, s.st_ino, s.st_size, s.st_mtime_ns, values)
    if version not in _said:
        _said[version] = _probe(program, fd, values)
    found = _said[version]
    if found is _NOT_OPENED:
        del _said[version]
        return (("", "haptex-h5-probe, the separate program that reads each file first, could not open it while h5py had it "
                     "open (replaced or changed meanwhile)", "Run again once nothing writes or replaces the file")
                if h5py_has_it else None)
    return found


def _probe(program, fd, values):
    code, output = _run(program, fd, values, as_is=False)
    if not output and code != 0:  # AddressSanitizer's runtime, which it starts under, did not let it start
        code, output = _run(program, fd, values, as_is=True)
    records = _records(output)
    if code == _NOT_OPENED:
        return _NOT_OPENED
    if code == _REFUSED and len(records) >= 3:
        return tuple(records[-3:])
    fix = "the file is damaged: copy it again, or make it again with the haptex command that wrote it"
    if code < 0 and -code == signal.SIGXCPU:
        return (records[-1], "reading it does not end (haptex-h5-probe used up its processor time: HDF5 loops so on "
                             "a damaged global heap or header)", fix)
    if code < 0 and -code in _CRASHES:
        return (records[-1], f"HDF5 crashes reading it ({signal.Signals(-code).name} in haptex-h5-probe, the separate "
                             "program that reads each file first, so Python does not)", fix)
    if code == 0 or code == -signal.SIGALRM:  # read it all; or waited four times its time (a stalled disk): no answer
        return None
    # Only a probe that read it all says the file can be read (review 31, F6).
    return ("", f"haptex-h5-probe, the separate program that reads each file first, ended with "
                f"{'signal ' + str(-code) if code < 0 else 'exit code ' + str(code)}, which says nothing of the file",
            f"run {program} on the file to see why")
