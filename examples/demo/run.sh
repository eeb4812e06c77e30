#!/bin/bash
# The demo pipeline (`make demo`): built-in synthetic materials -> data, checks, both models, the
# evaluation report. One home for it: `make demo` runs it, and tests/e2e/docs_numbers_test.cpp runs it
# to check that the figures the docs quote from the demo are the ones it gives.
#   run.sh HAPTEX OUT [SYNTH...]   (OUT must not exist yet, or be empty)
# SYNTH is what `haptex synth` makes, `materials` by default; the HaTT-driven figures of docs/evaluate.md
# come from `run.sh build/haptex OUT hatt --models ../shared/data/hatt/models --images ../shared/data/hatt/images`.
set -euo pipefail
if [ $# -lt 2 ]; then echo "usage: $0 HAPTEX OUT [SYNTH...]" >&2; exit 2; fi
haptex=$1 out=$2
shift 2
if [ $# -eq 0 ]; then set -- materials; fi
mkdir -p -- "$out"
set -x
"$haptex" synth "$@" -o "$out/synth"
"$haptex" capture extract "$out/synth/gelsight" -o "$out/gelsight.h5"
"$haptex" convert hatt "$out/synth/recordings" -o "$out/recordings.h5"
"$haptex" align --recordings "$out/recordings.h5" --gelsight "$out/gelsight.h5" -o "$out/dataset.h5"
"$haptex" split "$out/dataset.h5" -o "$out/split.json"
"$haptex" qa "$out/dataset.h5" --split "$out/split.json"
"$haptex" train "$out/dataset.h5" --split "$out/split.json" -o "$out/model.h5"
"$haptex" train "$out/dataset.h5" --split "$out/split.json" --per-material -o "$out/per_material.h5"
"$haptex" evaluate "$out/dataset.h5" --split "$out/split.json" --model "$out/model.h5" --model "$out/per_material.h5" \
  --truth "$out/synth/truth.h5" -o "$out/report"
