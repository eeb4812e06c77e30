"""Whole commands as a user times them (start-up included), each beside the peer a user would otherwise
run, in the same run, on one core (taskset -c 0), the median of several runs; issue 37's table.

Usage: whole_commands.py HAPTEX REPO WORK XML [--demo]
  XML     a 10 s HaTT recording (bench_convert --export-xml writes one)
  --demo  also time examples/demo/run.sh (about 1.5 minutes)
Prints a Markdown table: command, haptex, peer, ratio, goal.
"""
import glob
import json
import os
import resource
import shutil
import subprocess
import sys
import time

ONE_CORE = ["taskset", "-c", "0"] if shutil.which("taskset") else []
PYTHON = "/usr/bin/python3"


def timed(argv, runs, cwd=None):
    """Median wall seconds of `runs` runs of argv on one core, and the largest child RSS (MB)."""
    seconds = []
    for _ in range(runs):
        start = time.perf_counter()
        r = subprocess.run(ONE_CORE + argv, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=False)
        seconds.append(time.perf_counter() - start)
        if r.returncode != 0:
            raise SystemExit(f"{' '.join(argv)} failed: {r.stderr.decode(errors='replace')[-400:]}")
    seconds.sort()
    rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return seconds[len(seconds) // 2], rss


def opencv_loop(folder):
    """The python3-opencv peer of extract: decode every frame of every video and score it against the
    median of the first five (grey, blurred), as a ten-line script would."""
    import cv2
    import numpy as np

    cv2.setNumThreads(1)
    frames = 0
    for path in sorted(glob.glob(os.path.join(folder, "**", "*.avi"), recursive=True)):
        video = cv2.VideoCapture(path)
        grey, first, reference = [], [], None
        while True:
            ok, frame = video.read()
            if not ok:
                break
            g = cv2.GaussianBlur(cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY), (5, 5), 0)
            if reference is None:  # the median of the first five frames, taken once
                first.append(g)
                if len(first) == 5:
                    reference = np.median(np.stack(first), axis=0).astype(np.uint8)
            grey.append(float(cv2.absdiff(g, g if reference is None else reference).sum()))
            frames += 1
        int(np.argmax(grey))
    print(frames)


def row(name, ours, peer_name, theirs, goal):
    ratio = f"{ours / theirs:.2f}x" if theirs else ""
    peer = f"{peer_name} {theirs * 1e3:.0f} ms" if theirs else peer_name
    return f"| {name} | {ours * 1e3:.0f} ms | {peer} | {ratio} | {goal} |"


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--opencv-loop":
        return opencv_loop(sys.argv[2])
    haptex, repo, work, xml = sys.argv[1:5]
    demo = "--demo" in sys.argv
    os.makedirs(work, exist_ok=True)
    rows = ["| whole command (one core, median) | haptex | peer in the same run | haptex / peer | goal |", "|---|---|---|---|---|"]

    start, _ = timed([haptex, "--help"], 21)
    numpy, _ = timed([PYTHON, "-c", "import numpy"], 21)
    rows.append(row("start: `haptex --help`", start, "`python3 -c 'import numpy'`", numpy, "<= 40 ms, <= 0.25x"))
    if shutil.which("ffprobe"):
        ffprobe, _ = timed(["ffprobe", "-version"], 21)
        rows.append(row("start: `haptex --help`", start, "`ffprobe -version`", ffprobe, ""))

    megabytes = os.path.getsize(xml) / 1e6
    one, _ = timed([haptex, "convert", "hatt", xml, "-o", os.path.join(work, "one.h5"), "--force", "-q"], 5)
    etree, _ = timed([PYTHON, os.path.join(repo, "bench", "elementtree_parse.py"), xml], 3)
    rows.append(row(f"convert one {megabytes:.0f} MB HaTT XML ({megabytes / one:.0f} MB/s)", one, "ElementTree + numpy parse", etree,
                    ">= 150 MB/s"))
    four = []
    for k in range(4):
        copy = os.path.join(work, f"Material_{k}.xml")
        shutil.copyfile(xml, copy)
        four.append(copy)
    several, _ = timed([haptex, "convert", "hatt", *four, "-o", os.path.join(work, "four.h5"), "--force", "-q"], 3)
    rows.append(row(f"convert four such files ({4 * megabytes / several:.0f} MB/s)", several, "", 0, ">= 150 MB/s"))

    presses = os.path.join(work, "presses")
    if not os.path.isdir(presses):
        subprocess.run([haptex, "synth", "materials", "-n", "2", "--presses", "5", "--recordings", "1", "--seconds", "1", "-q", "-o", presses],
                       check=True)
    videos = os.path.join(presses, "gelsight")
    extract, _ = timed([haptex, "capture", "extract", videos, "-o", os.path.join(work, "g.h5"), "--force", "--no-sheets", "-q"], 3)
    counted = subprocess.run([PYTHON, __file__, "--opencv-loop", videos], capture_output=True, text=True, check=False)
    if counted.returncode == 0:
        frames = int(counted.stdout)
        loop, _ = timed([PYTHON, __file__, "--opencv-loop", videos], 3)
        rows.append(row(f"extract 10 MJPG press videos, {frames} frames ({frames / extract:.0f} frames/s)", extract,
                        f"python3-opencv decode + score loop ({frames / loop:.0f} frames/s)", loop, "<= 0.5x (>= 2x the loop's frames/s)"))
    else:  # python3-opencv is make bench's (BENCH_PACKAGES)
        rows.append(row("extract 10 MJPG press videos", extract, "python3-opencv is not installed (make bench installs it)", 0,
                        "<= 0.5x (>= 2x the loop's frames/s)"))

    if demo:
        out = os.path.join(work, "demo")
        shutil.rmtree(out, ignore_errors=True)
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        seconds, rss = timed([os.path.join(repo, "examples", "demo", "run.sh"), haptex, out], 1)
        rows.append(f"| demo pipeline after the build (examples/demo/run.sh) | {seconds:.0f} s, largest step {rss:.0f} MB | | | <= 45 s, <= 400 MB |"
                    if rss * 1024 > before else f"| demo pipeline | {seconds:.0f} s | | | <= 45 s |")
    print("\n".join(rows))
    json.dump({"rows": rows}, open(os.path.join(work, "whole_commands.json"), "w"))


if __name__ == "__main__":
    main()
