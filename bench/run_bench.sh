#!/usr/bin/env bash
# Runs every benchmark on one core and prints the figures the issues ask for.
# Usage: bench/run_bench.sh BUILD_DIR   (make bench calls it)
set -euo pipefail
build=$(realpath "${1:-build}")
repo=$(realpath "$(dirname "$0")/..")
out=$build/bench-results
mkdir -p "$out"
one_core="taskset -c 0"
command -v taskset >/dev/null || one_core=""

$one_core "$build/bench/bench_signal" --benchmark_format=json --benchmark_out="$out/signal.json" --benchmark_out_format=json >/dev/null
$one_core "$build/bench/bench_convert" --benchmark_format=json --benchmark_out="$out/convert.json" --benchmark_out_format=json >/dev/null
$one_core /usr/bin/python3 "$(dirname "$0")/scipy_sosfiltfilt.py" > "$out/scipy.json"
$one_core /usr/bin/python3 "$(dirname "$0")/scipy_resample_poly.py" > "$out/scipy_resample.json"
"$build/bench/bench_convert" --export-xml "$out/recording_10s.xml"
$one_core /usr/bin/python3 "$(dirname "$0")/elementtree_parse.py" "$out/recording_10s.xml" > "$out/elementtree.json" \
  || echo '{"note": "bench/elementtree_parse.py failed; no comparison"}' > "$out/elementtree.json"
rm -f "$out/recording_10s.xml"

/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
# Names without Google Benchmark's suffixes ("/real_time").
bench = {b["name"].split("/")[0]: b for f in ("signal", "convert") for b in json.load(open(f"{out}/{f}.json"))["benchmarks"]}
scipy = json.load(open(f"{out}/scipy.json"))
def seconds(name):
    b = bench[name]
    return b["real_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
ours = seconds("BM_Sosfiltfilt_1e5")
theirs = scipy["scipy_sosfiltfilt_1e5_seconds"]
print(f"sosfiltfilt, 1e5 samples, order 4:  haptex {ours*1e3:.3f} ms   scipy {scipy['scipy']} {theirs*1e3:.3f} ms   scipy/haptex = {theirs/ours:.2f}x")
resample = json.load(open(f"{out}/scipy_resample.json"))
ours, theirs = seconds("BM_ResamplePoly_999983Hz"), resample["scipy_resample_poly_999983_seconds"]
print(f"resample_poly 999983 Hz -> 10 kHz (20 M taps), 60000 samples:  haptex {ours:.2f} s   scipy {theirs:.2f} s   scipy/haptex = {theirs/ours:.2f}x")
print(f"SHA-256 of the 10 s XML: {seconds('BM_Sha256_10sXml')*1e3:.1f} ms ({bench['BM_Sha256_10sXml']['bytes_per_second']/1e9:.2f} GB/s)")
for name in ("BM_ParseHattXml_10s", "BM_ConvertXmlToHdf5_10s"):
    b = bench[name]
    print(f"{name}: {seconds(name)*1e3:.1f} ms per 10 s recording, {b['bytes_per_second']/1e6:.1f} MB/s of XML, {b['items_per_second']/1e6:.2f} M samples/s (x 9 channels)")
etree = json.load(open(f"{out}/elementtree.json"))
if "seconds" in etree:
    print(f"the same XML through Python {etree['python']} ElementTree + numpy: {etree['seconds']*1e3:.0f} ms, {etree['megabytes_per_second']:.1f} MB/s")
else:
    print(etree["note"])
print(f"DFT321 of 10 s: {seconds('BM_Dft321_10s')*1e3:.2f} ms;  amplitude spectrum of one window: {seconds('BM_AmplitudeSpectrum_1000')*1e6:.2f} us")
PY

# Synthetic data: piecewise AR rendering on one core, and the default 8 materials on all cores.
$one_core "$build/bench/bench_synth" --benchmark_format=json --benchmark_out="$out/synth.json" --benchmark_out_format=json >/dev/null 2>&1 || true
synth_dir=$(mktemp -d)
start=$(date +%s.%N)
"$build/haptex" synth materials -o "$synth_dir/out" -q
end=$(date +%s.%N)
rm -rf "$synth_dir"
/usr/bin/python3 - "$out" "$start" "$end" <<'PY'
import json, sys
out, start, end = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
bench = {b["name"].split("/")[0]: b for b in json.load(open(f"{out}/synth.json"))["benchmarks"]}
for name in ("BM_PiecewiseArRendering", "BM_PiecewiseArRenderingHattBook"):
    b = bench.get(name)
    if b and "items_per_second" in b:
        print(f"{name}: {b['items_per_second']/1e6:.2f} M samples/s on one core")
print(f"haptex synth materials (default 8 materials, 2 x 10 s recordings and 5 presses each): {end - start:.1f} s on all cores")
PY

# capture: contact scoring and press-file extraction on one core, the same JPEGs through a plain
# python3-opencv loop (absdiff, threshold, sum), and the recorder's 60 s keep-up runs on the fake camera.
"$build/bench/bench_capture" --export-frames "$out/capture_frames"
$one_core "$build/bench/bench_capture" --benchmark_format=json --benchmark_out="$out/capture.json" --benchmark_out_format=json >/dev/null
if /usr/bin/python3 -c 'import cv2' 2>/dev/null; then
  $one_core /usr/bin/python3 "$(dirname "$0")/opencv_peak_loop.py" "$out/capture_frames" > "$out/opencv_loop.json"
else
  echo '{}' > "$out/opencv_loop.json"  # python3-opencv is not installed: no ratio
fi
for mode in size=3280x2464 size=960x720,fps=30; do
  rm -rf "$out/capture_keepup"
  "$build/haptex" capture record --device "fake:$mode" --material Bench --presses 100000 --seconds 60 \
    -o "$out/capture_keepup" --json > "$out/keepup_${mode%%,*}.json"
done
rm -rf "$out/capture_keepup" "$out/capture_frames"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
bench = {b["name"].replace("/real_time", ""): b for b in json.load(open(f"{out}/capture.json"))["benchmarks"]}
py = json.load(open(f"{out}/opencv_loop.json"))
for w, h in ((960, 720), (3280, 2464)):
    ours_raw = bench[f"BM_ScoreDecodedFrame/{w}/{h}"]["items_per_second"]
    ours_jpg = bench[f"BM_ScoreMjpgFrame/{w}/{h}"]["items_per_second"]
    theirs = py.get(f"{w}x{h}")
    if theirs:
        print(f"contact score {w}x{h}, one core: decoded frames {ours_raw:.0f} fps (python3-opencv loop {theirs['decoded_fps']:.0f}, "
              f"x{ours_raw / theirs['decoded_fps']:.1f}); MJPG {ours_jpg:.0f} fps (python {theirs['mjpg_fps']:.0f}, x{ours_jpg / theirs['mjpg_fps']:.1f})")
    else:
        print(f"contact score {w}x{h}, one core: decoded frames {ours_raw:.0f} fps; MJPG {ours_jpg:.0f} fps "
              "(install python3-opencv for the comparison with a plain python loop)")
    print(f"  whole extraction of a recorded MJPG press file {w}x{h}: {bench[f'BM_ExtractPressFile/{w}/{h}']['items_per_second']:.1f} frames/s")
for mode in ("size=3280x2464", "size=960x720"):
    m = json.load(open(f"{out}/keepup_{mode}.json"))
    t, s = m["totals"], m["stream"]
    print(f"recorder keep-up, fake {s['fourcc']} {s['width']}x{s['height']} at {s['granted_fps']:g} fps for {t['wall_seconds']:.0f} s: "
          f"{t['frames']} frames, {t['dropped_frames']} dropped, {len(m['presses'])} presses, CPU {100 * t['cpu_seconds'] / t['wall_seconds']:.0f}% "
          f"of one core (fake camera included), deepest queue {t['max_queue_depth']} frames")
PY

# evaluate: spectral distance, Welch's test and phase reconstruction on one core, and torchaudio's
# Griffin-Lim on the same 10 s texture signal, one thread (no torchaudio: a note, no ratio).
$one_core "$build/bench/bench_evaluate" --benchmark_format=json --benchmark_out="$out/evaluate.json" --benchmark_out_format=json >/dev/null
"$build/bench/bench_evaluate" --export-signal "$out/texture_10s.f64"
$one_core /usr/bin/python3 "$(dirname "$0")/torchaudio_griffinlim.py" "$out/texture_10s.f64" > "$out/torchaudio.json" \
  || echo '{"note": "bench/torchaudio_griffinlim.py failed; no comparison"}' > "$out/torchaudio.json"
rm -f "$out/texture_10s.f64"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
bench = {b["name"]: b for b in json.load(open(f"{out}/evaluate.json"))["benchmarks"]}
def seconds(b):  # CPU time: one thread, so the time on one core whatever else the machine runs
    return b["cpu_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
print(f"spectral distance of 10 s: {seconds(bench['BM_SpectralDistance_10s'])*1e3:.2f} ms;  "
      f"Welch's t-test 1000 vs 1000: {seconds(bench['BM_WelchTest_1000_1000'])*1e6:.1f} us")
print("fast Griffin-Lim on 10 s of texture (exact magnitudes), CPU time on one core:")
for name, b in bench.items():
    if name.startswith("BM_GriffinLim_10s/"):
        print(f"  {name[len('BM_GriffinLim_10s/'):]:<30} {seconds(b):7.3f} s  ({b['seconds_per_second']*1e3:.1f} ms per second of vibration)  SC {b['sc_db']:.2f} dB")
print("online RTISI-LA, per 100-sample frame (10 ms of vibration):")
for name, b in bench.items():
    if name.startswith("BM_OnlineReconstruction_PerFrame/"):
        print(f"  {name[len('BM_OnlineReconstruction_PerFrame/'):]:<30} {seconds(b)*1e6:7.1f} us  latency {b['latency_ms']:.0f} ms  SC {b['sc_db']:.2f} dB")
ours = seconds(bench["BM_GriffinLim_10s/iterations:100/momentum_pct:99"])
theirs = json.load(open(f"{out}/torchaudio.json"))
if "float64" in theirs:
    for precision in ("float64", "float32"):
        t = theirs[precision]
        print(f"Griffin-Lim 100 iterations, momentum 0.99, 10 s, CPU time: haptex {ours:.3f} s   torchaudio {theirs['torchaudio']} {precision} "
              f"{t['seconds']:.3f} s (SC {t['sc_db']:.2f} dB, centred frames)   torchaudio/haptex = {t['seconds']/ours:.2f}x")
else:
    print(f"Griffin-Lim 100 iterations, momentum 0.99, 10 s, CPU time: haptex {ours:.3f} s   ({theirs.get('note', 'no torchaudio figures')})")
PY

# predict: one query of the predictor (the haptic loop's per-millisecond call), predict_batch, encoding
# a 960 x 720 press and the per-material variant's query, on one core; PyTorch's forward pass of the
# same network and weights, one thread, batch 1 (no PyTorch: a note, no ratio). CPU times, as above.
predict_model="$out/predict_model.h5"
$one_core "$build/bench/bench_predict" --benchmark_out="$out/predict.json" --benchmark_out_format=json >/dev/null
"$build/bench/bench_predict" --export-model "$predict_model"
{ $one_core /usr/bin/python3 "$(dirname "$0")/torch_forward.py" "$predict_model" \
    || echo '{"note": "bench/torch_forward.py failed; no comparison"}'; } > "$out/torch_forward.json"
# play: a live stream of actions at 1 kHz on standard input, played through ALSA's file plugin (haptex
# and the stream's writer on one core).
$one_core /usr/bin/python3 "$(dirname "$0")/play_stream.py" "$build/haptex" "$predict_model" > "$out/play.json"
rm -f "$predict_model"
/usr/bin/python3 - "$out/play.json" <<'PY'
import json, sys
for method, r in json.load(open(sys.argv[1])).items():
    l = r["line_to_device_ms"]
    print(f"play, 10 s of actions at 1 kHz on standard input, {method}, one core: line to device median {l['median']:.2f} ms, "
          f"99th percentile {l['p99']:.2f} ms (then the device's {r['latency_ms']['buffer']:.0f} ms buffer; nominal latency "
          f"{r['latency_ms']['total']:.1f} ms); {r['underruns']} underruns, {r['late_periods']} late periods in {r['frames']} frames; "
          f"slowest frame {r['slowest_frame_ms']:.2f} ms; CPU {100 * r['cpu_share']:.1f}% of one core")
PY
/usr/bin/python3 - "$out/predict.json" "$out/torch_forward.json" <<'PY'
import json, sys
unit = {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}
ns = {b["name"]: b["cpu_time"] * unit[b["time_unit"]] for b in json.load(open(sys.argv[1]))["benchmarks"]}
torch = json.load(open(sys.argv[2]))
single = ns["BM_PredictSingle"]
print(f"predict, one query, default sizes, one core: unified {single:.0f} ns, per-material "
      f"{ns['BM_PredictSinglePerMaterial']:.0f} ns (goal < 5000 ns); predictor hidden 64: "
      f"{ns['BM_PredictSingleHidden/hidden:64']:.0f} ns, 256: {ns['BM_PredictSingleHidden/hidden:256']:.0f} ns")
print(f"predict_batch of 1000 queries: {1e6 / ns['BM_PredictBatch/1000']:.3f} M predictions/s "
      f"({ns['BM_PredictBatch/1000'] / 1e3:.0f} us per batch)")
print(f"encode a 960x720 press (texture descriptor + texture encoder): {ns['BM_Encode960x720'] / 1e6:.2f} ms")
if "single_query_seconds" in torch:
    theirs = torch["single_query_seconds"] * 1e9
    print(f"one query: haptex {single:.0f} ns   PyTorch {torch['torch']} {theirs:.0f} ns (one thread, batch 1, same weights, "
          f"latent part {torch['latent_part']}; concatenated {torch['single_query_seconds_concatenated'] * 1e9:.0f} ns)   "
          f"torch/haptex = {theirs / single:.1f}x")
else:
    print(f"one query: haptex {single:.0f} ns   ({torch.get('note', 'no PyTorch figures')})")
if "batch_seconds" in torch:
    theirs = torch["batch_seconds"] * 1e9
    print(f"a batch of 1000 queries: haptex {ns['BM_PredictBatch/1000'] / 1e6:.2f} ms   PyTorch batched {theirs / 1e6:.2f} ms "
          f"(one thread, same weights)   torch/haptex = {theirs / ns['BM_PredictBatch/1000']:.1f}x")
PY

# Whole commands: `make demo` after the build (its build step finds nothing to do), timed and measured
# on disk; then a fresh configure and build of this tree with make build's settings, its warnings counted.
demo_dir=$(mktemp -d)
fresh=$(mktemp -d)
trap 'rm -rf "$demo_dir" "$fresh"' EXIT  # on success too
make -C "$repo" --no-print-directory build BUILD="$build" >/dev/null
start=$(date +%s.%N)
make -C "$repo" --no-print-directory demo BUILD="$build" DEMO="$demo_dir/demo" > "$out/demo.log" 2>&1 \
  || { echo "make demo failed: see $out/demo.log" >&2; exit 1; }
end=$(date +%s.%N)
bytes=$(du -sb "$demo_dir/demo" | cut -f1)
du -sb "$demo_dir"/demo/* | sort -rn | head -5 | sed "s|$demo_dir/demo/||" > "$out/demo_sizes.txt"
seconds=$(/usr/bin/python3 -c "print(round($end - $start, 1))")
echo "{\"seconds\": $seconds, \"bytes\": $bytes}" > "$out/demo.json"
echo "make demo after the build: $seconds s, $((bytes / 1000000)) MB on disk; largest:"
sed 's/^/  /' "$out/demo_sizes.txt"

# Whole commands (issue 37): start-up included, each beside its peer in the same run, on one core.
"$build/bench/bench_convert" --export-xml "$out/recording_10s.xml"
echo "whole commands:"
/usr/bin/python3 "$repo/bench/whole_commands.py" "$build/haptex" "$repo" "$out/whole" "$out/recording_10s.xml"
rm -rf "$out/recording_10s.xml" "$out/whole"

jobs=$(nproc)
start=$(date +%s.%N)
{ cmake -S "$repo" -B "$fresh" -DCMAKE_BUILD_TYPE=Release && cmake --build "$fresh" -j "$jobs"; } > "$out/build.log" 2>&1 \
  || { echo "the fresh build failed: see $out/build.log" >&2; exit 1; }
end=$(date +%s.%N)
warnings=$(grep -c "warning:" "$out/build.log" || true)
seconds=$(/usr/bin/python3 -c "print(round($end - $start, 1))")
echo "{\"seconds\": $seconds, \"jobs\": $jobs, \"warnings\": $warnings}" > "$out/build.json"
echo "fresh build of this tree ($jobs jobs): $seconds s, $warnings warnings (log: $out/build.log)"

/usr/bin/python3 "$(dirname "$0")/summary.py" "$out"
