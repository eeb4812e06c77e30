#!/usr/bin/env bash
# Speed against accuracy of the predictor's sizes: trains a small sweep with `haptex train` on one
# dataset and split and prints a table (sizes, parameters, training time, validation distance, the
# mean-spectrum baseline's distance).
# Usage: bench/predict_sweep.sh DATASET SPLIT [OUT_DIR]
#   OUT_DIR (default: a temporary folder, removed afterwards) keeps the models and training logs; the
#   table shows every run on DATASET found there, so further calls with other SWEEP runs add rows.
#   HAPTEX: the haptex binary (default: build/haptex beside this script's folder).
#   SWEEP: the runs, one per line: a name, then haptex train's size flags (default: the list below).
set -euo pipefail
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: $0 DATASET SPLIT [OUT_DIR]" >&2
  exit 2
fi
dataset=$1 split=$2
here=$(cd "$(dirname "$0")" && pwd)
haptex=${HAPTEX:-$here/../build/haptex}
[[ -x $haptex ]] || { echo "$0: no haptex binary at $haptex (build it, or set HAPTEX)" >&2; exit 2; }
if [[ $# -eq 3 ]]; then
  out=$3
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi

# name  flags   (the default sizes: --latent 64 --texture-hidden 128 --action-hidden 32 --action-layers 2
#                --hidden 256 --hidden-layers 1)
default_sweep='latent16      --latent 16
hidden64      --hidden 64
default
hidden128     --hidden 128
action16      --action-hidden 16
per-material  --per-material'
sweep=${SWEEP:-$default_sweep}

while read -r name flags; do
  [[ -z $name || $name == \#* ]] && continue
  echo "training $name ${flags:-(defaults)}" >&2
  # shellcheck disable=SC2086 # flags are words
  "$haptex" train "$dataset" --split "$split" -o "$out/$name.h5" --log "$out/$name.training.json" --force -q $flags
done <<< "$sweep"

/usr/bin/python3 - "$out" "$dataset" <<'PY'
import json, os, sys
out, dataset = sys.argv[1], sys.argv[2]
logs = sorted((os.path.getmtime(os.path.join(out, f)), f) for f in os.listdir(out) if f.endswith(".training.json"))
rows = []
for _, f in logs:
    log = json.load(open(os.path.join(out, f)))
    if os.path.abspath(log["dataset"]["path"]) != os.path.abspath(dataset):
        continue  # OUT_DIR gathers runs across calls, but only on this dataset
    o, m = log["options"], log["metrics"]
    spectrum = m["spectrum"]
    per_material = o.get("variant", "unified") != "unified"
    if per_material:  # one network per material: the mean over materials of their validation distances
        val = sum(r["val_distance"] for r in spectrum.values()) / len(spectrum)
        epochs = f"{min(r['best_epoch'] for r in spectrum.values())}-{max(r['best_epoch'] for r in spectrum.values())}"
        texture = "-"
    else:
        val, epochs = spectrum["val_distance"], str(spectrum["best_epoch"])
        texture = f"{m['texture']['val_accuracy']:.2f}" if "texture" in m else "-"
    # Each stage's epochs count seconds from the stage's start. Unified: stage 1 + stage 2 (wall time on
    # all threads); per-material: the sum over the materials' networks (each trains on one thread, as
    # many at once as there are threads). The rest of the total is reading the dataset and computing
    # the press images' texture descriptors.
    stages = {}
    for e in log["epochs"]:
        stages[e["stage"]] = max(stages.get(e["stage"], 0.0), e["seconds"])
    fit = sum(stages.values())
    base = m["mean_spectrum_baseline"]["val_distance"]
    rows.append((f[: -len(".training.json")], "per-material" if per_material else "unified",
                 "-" if per_material else f"{o['latent']}/{o['texture_hidden']}",
                 f"{o['action_layers']}x{o['action_hidden']}", f"{o['predictor_layers']}x{o['predictor_hidden']}",
                 str(log["parameters"]), f"{log['seconds']:.1f}", f"{fit:.1f}", epochs, texture,
                 f"{val:.5f}", f"{base:.5f}", f"{val / base:.3f}"))
head = ("run", "variant", "latent/tex", "action", "predictor", "parameters", "total s", "fit s", "best epoch",
        "tex val acc", "val dist", "baseline", "val/base")
print(f"dataset {dataset}; distances in m/s^2 on the validation windows (per-material: mean over materials); "
      "baseline: each material's mean training spectrum; fit s: stage 1 + stage 2 (per-material: summed over the networks, one thread each)")
widths = [max(len(r[i]) for r in rows + [head]) for i in range(len(head))]
for r in [head] + rows:
    print("  ".join(c.rjust(w) if i >= 5 else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths))))
PY
