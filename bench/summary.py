"""The table that ends `make bench` (bench/README.md): every figure with its peer from the same run,
the ratio, and the goal. Reads the JSON files bench/run_bench.sh leaves in its output directory.

Usage: /usr/bin/python3 bench/summary.py OUT_DIR
"""
import json
import os
import sys

UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def load(out, name):
    path = os.path.join(out, name)
    return json.load(open(path)) if os.path.exists(path) else {}


def benchmarks(out, name):
    return {b["name"].replace("/real_time", ""): b for b in load(out, name).get("benchmarks", [])}


def cpu_seconds(b):
    return b["cpu_time"] * UNIT[b["time_unit"]]


def main():
    out = sys.argv[1]
    signal, convert = benchmarks(out, "signal.json"), benchmarks(out, "convert.json")
    capture, evaluate, predict = benchmarks(out, "capture.json"), benchmarks(out, "evaluate.json"), benchmarks(out, "predict.json")
    scipy, opencv, torchaudio = load(out, "scipy.json"), load(out, "opencv_loop.json"), load(out, "torchaudio.json")
    torch, etree, demo, build = load(out, "torch_forward.json"), load(out, "elementtree.json"), load(out, "demo.json"), load(out, "build.json")
    rows = []  # work, haptex, peer, ratio (haptex's speed over the peer's), goal, met

    def row(work, ours, peer, ratio, goal, met):
        """met: bool, or one (part of the goal, bool or None when the peer did not run) per part."""
        if isinstance(met, bool):
            verdict = "yes" if met else "**no**"
        elif all(m for _, m in met):
            verdict = "yes"
        else:
            verdict = "; ".join(f"{part}: {'yes' if m else 'no peer' if m is None else '**no**'}" for part, m in met)
        rows.append((work, ours, peer or "-", f"{ratio:.2f}x" if ratio else "-", goal, verdict))

    fps = capture["BM_ScoreDecodedFrame/960/720"]["items_per_second"]
    theirs = opencv.get("960x720", {}).get("decoded_fps")
    row("contact score, decoded 960x720 frame", f"{fps:.0f} fps", theirs and f"python3-opencv loop {theirs:.0f} fps",
        theirs and fps / theirs, ">= 4000 fps, >= 2x", [("4000 fps", fps >= 4000), ("2x", theirs and fps >= 2 * theirs)])
    extract = capture["BM_ExtractPressFile/960/720"]["items_per_second"]
    row("whole extraction of an MJPG press file, 960x720", f"{extract:.0f} frames/s", None, None, ">= 400 frames/s", extract >= 400)

    fgla = cpu_seconds(evaluate["BM_GriffinLim_10s/iterations:100/momentum_pct:99"])
    f32 = torchaudio.get("float32", {}).get("seconds")
    row("fast Griffin-Lim, 10 s, 100 iterations", f"{fgla:.3f} s (SC {evaluate['BM_GriffinLim_10s/iterations:100/momentum_pct:99']['sc_db']:.1f} dB)",
        f32 and f"torchaudio float32 {f32:.3f} s (SC {torchaudio['float32']['sc_db']:.1f} dB)", f32 and f32 / fgla,
        "<= 0.45 s, >= 2x torchaudio float32", [("0.45 s", fgla <= 0.45), ("2x", f32 and f32 >= 2 * fgla)])

    sos = signal["BM_Sosfiltfilt_1e5"]["real_time"] * UNIT[signal["BM_Sosfiltfilt_1e5"]["time_unit"]]
    theirs = scipy.get("scipy_sosfiltfilt_1e5_seconds")
    row("sosfiltfilt, 1e5 samples, order 4", f"{sos * 1e3:.3f} ms", theirs and f"scipy {theirs * 1e3:.3f} ms", theirs and theirs / sos,
        "<= 1.0 ms, >= 2.5x scipy", [("1.0 ms", sos <= 1e-3), ("2.5x", theirs and theirs >= 2.5 * sos)])

    parse = convert["BM_ParseHattXml_10s"]["bytes_per_second"] / 1e6
    whole = convert["BM_ConvertXmlToHdf5_10s"]["bytes_per_second"] / 1e6
    theirs = etree.get("megabytes_per_second")
    row("HaTT XML parse, 10 s recording", f"{parse:.0f} MB/s; whole conversion {whole:.0f} MB/s",
        theirs and f"Python ElementTree + numpy {theirs:.1f} MB/s", theirs and parse / theirs,
        "parse >= 500 MB/s, conversion >= 250 MB/s", [("parse", parse >= 500), ("conversion", whole >= 250)])

    single = cpu_seconds(predict["BM_PredictSingle"])
    theirs = torch.get("single_query_seconds")
    row("predict, one query, default model", f"{single * 1e6:.2f} us", theirs and f"PyTorch {torch['torch']} {theirs * 1e6:.1f} us",
        theirs and theirs / single, "<= 2 us, >= 25x PyTorch", [("2 us", single <= 2e-6), ("25x", theirs and theirs >= 25 * single)])
    batch = cpu_seconds(predict["BM_PredictBatch/1000"])
    theirs = torch.get("batch_seconds")
    row("predict_batch, 1000 queries", f"{1000 / batch / 1e6:.2f} M/s", theirs and f"PyTorch batched {1000 / theirs / 1e6:.3f} M/s",
        theirs and theirs / batch, ">= PyTorch batched", [("PyTorch", theirs and theirs >= batch)])

    if demo:
        row("make demo after the build", f"{demo['seconds']:.0f} s, {demo['bytes'] / 1e6:.0f} MB on disk", None, None,
            "<= 60 s, <= 500 MB", [("60 s", demo["seconds"] <= 60), ("500 MB", demo["bytes"] <= 500e6)])
    if build:
        row(f"fresh build ({build['jobs']} jobs)", f"{build['seconds'] / 60:.1f} min, {build['warnings']} warnings", None, None,
            "<= 5 min, zero warnings", [("5 min", build["seconds"] <= 300), ("no warning", build["warnings"] == 0)])

    print("\n| work | haptex | peer, same run | ratio | goal | met |\n|---|---|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(r) + " |")


if __name__ == "__main__":
    main()
