#!/bin/bash
# One shard of a collection: convert, extract and align the materials whose place in the sorted list
# of press folders is SHARD modulo SHARDS, into OUT/SHARD/{recordings,gelsight,dataset}.h5
# (docs/scale-out.md). As a Slurm array task the shard and the count come from the array itself:
#   SHARDS=16; sbatch --array=0-$((SHARDS - 1)) examples/scale-out/shards.sh
# By hand, or under xargs or GNU parallel:
#   seq 0 3 | xargs -P 4 -I{} env SHARD={} SHARDS=4 examples/scale-out/shards.sh
# COLLECTION (default ./collection) holds recordings/<material>/ and presses/<material>/; OUT
# (default ./shards) is where the shards go. Exit 2, with the reason, before any work when haptex is
# not on PATH, the collection is missing, or the shard has no materials.
#SBATCH --job-name=haptex-shards
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -euo pipefail

fail() { echo "shards.sh: $*" >&2; exit 2; }

shard=${SLURM_ARRAY_TASK_ID:-${SHARD:-}}
shards=${SLURM_ARRAY_TASK_COUNT:-${SHARDS:-}}
# Plain decimals: bash would read 010 as octal 8 (review 13, F4).
[[ $shard =~ ^(0|[1-9][0-9]{0,8})$ && $shards =~ ^[1-9][0-9]{0,8}$ ]] ||
  fail "give the shard and the count as plain decimals: a Slurm array task (sbatch --array=0-N), or SHARD=n SHARDS=N"
(( shard < shards )) || fail "shard $shard of $shards: shards are numbered 0 to $((shards - 1)) (sbatch --array=0-$((shards - 1)))"
command -v haptex > /dev/null || fail "haptex is not on PATH: make install PREFIX=DIR, then add DIR/bin to PATH"
collection=$(realpath -e -- "${COLLECTION:-collection}") || fail "no collection at ${COLLECTION:-collection}: set COLLECTION"
[[ -d $collection/recordings && -d $collection/presses ]] || fail "$collection holds no recordings/ and presses/ folders"
out=$(realpath -m -- "${OUT:-shards}")/$shard

recordings=() presses=()
i=0
while IFS= read -r -d '' folder; do
  material=${folder##*/}  # not $(basename): command substitution drops a name's trailing newlines
  # A link is read through, as extract reads one (review 21, F5: find -type d passed links over); a
  # dangling one is refused, as every haptex input folder refuses it.
  [[ -d $folder ]] || fail "$folder is a link to no folder"
  if (( i % shards == shard )); then
    [[ -d $collection/recordings/$material ]] || fail "$collection/presses/$material has no recordings/$material beside it"
    recordings+=("$collection/recordings/$material")
    presses+=("$folder")
  fi
  i=$((i + 1))
done < <(find "$collection/presses" -mindepth 1 -maxdepth 1 \( -type d -o -type l \) -print0 | sort -z)
(( ${#presses[@]} )) || fail "shard $shard of $shards has no materials: $collection/presses holds $i; use at most $i shards"

mkdir -p -- "$out"
haptex convert hatt "${recordings[@]}" -o "$out/recordings.h5" --force
haptex capture extract "${presses[@]}" -o "$out/gelsight.h5" --no-sheets --force
haptex align --recordings "$out/recordings.h5" --gelsight "$out/gelsight.h5" -o "$out/dataset.h5" --force
