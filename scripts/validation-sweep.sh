#!/usr/bin/env bash
# The validation sweep (docs/reliability.md): every technique x every value of every declared setting
# (debug views included) x the named cameras, plus glass atlas sizes 64..8192, 1 and 1024 reflectors,
# and sizes from 1x4096 and 17x9 up to the 4096 PPR limit, all rendered by `ppr compare --validation`
# (Khronos validation + synchronization validation; any error makes ppr exit 1).
#   scripts/validation-sweep.sh [--ppr EXE] [--shard K/N] [--cameras "a b"] [--size WxH] [--extremes all|small|none] [--out DIR]
# The settings and techniques are read from `ppr --help`, which prints the one declaration table, so a
# new setting or value is swept without editing this script. --shard K/N keeps every N-th row (CI runs
# a slice of one shard); the full sweep is the default. Prints one line per run and a summary; exit 1
# if any run failed or reported a validation error.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
shard_k=0; shard_n=1
cameras="overview puddles grazing stairs mirror glass normalmap"
size=160x90
extremes=all
out="$(mktemp -d)"
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --shard) shard_k="${2%/*}"; shard_n="${2#*/}"; shift 2 ;;
    --cameras) cameras="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --extremes) extremes="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "validation-sweep: unknown argument $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
help="$("$ppr" --help)"

# Techniques: the indented names between --technique and --reference in the usage.
mapfile -t techniques < <(printf '%s\n' "$help" | sed -n '/^  --technique/,/^  --reference/p' | sed -nE 's/^    ([a-z][a-z-]*) {2,}.*/\1/p')
# Settings: "    key=a|b|c (default d; owner)" or "    key=[lo, hi] (default d; owner)"; every choice, or a range's ends.
rows_for() {  # technique → its rows: defaults, then one row per non-default value of each setting
  local t="$1"
  echo "$t"
  printf '%s\n' "$help" | sed -nE 's/^    ([a-z_]+)=(.*) \(default ([^;]*);.*/\1 \2 \3/p' | while read -r key values def; do
    if [[ "$values" == \[* ]]; then
      values="${values#[}"; values="${values%]}"; values="${values//,/}"
    else
      values="${values//|/ }"
    fi
    for v in $values; do [ "$v" != "$def" ] && echo "$t@$key=$v"; done
  done
}

taa_rows_for() {  # technique → its TAA rows: taa=1, then taa=1 with each non-default value of each other taa setting
  local t="$1"
  echo "$t@taa=1"
  printf '%s\n' "$help" | sed -nE 's/^    ([a-z_]+)=([^ ]*) \(default ([^;]*); taa\)$/\1 \2 \3/p' | while read -r key values def; do
    [ "$key" = taa ] && continue
    values="${values//|/ }"
    for v in $values; do [ "$v" != "$def" ] && echo "$t@taa=1,$key=$v"; done
  done
}

runs=0; failed=0; rows_total=0; errors_total=0
summary="$out/summary.txt"; : >"$summary"
run() {  # name, then ppr compare arguments
  local name="$1"; shift
  local log="$out/$name.log"
  "$ppr" compare --validation --frames 1 --out "$out/$name" "$@" >"$log" 2>&1
  local rc=$?
  local errs; errs=$(sed -nE 's/^ppr: ([0-9]+) validation error.*/\1/p' "$log" | tail -1)
  errs=${errs:-0}
  local rows=0 a; for a in "$@"; do [ "$a" = --technique ] && rows=$((rows + 1)); done
  runs=$((runs + 1)); rows_total=$((rows_total + rows)); errors_total=$((errors_total + errs))
  if [ $rc -ne 0 ]; then
    failed=$((failed + 1))
    echo "FAIL  $name (exit $rc, $errs validation errors): $(grep -m1 -E 'error|VUID|SYNC' "$log")" | tee -a "$summary"
  else
    echo "ok    $name ($rows rows)" | tee -a "$summary"
  fi
}

index=0
kept=()
keep_shard() {  # a rows function and a technique → kept: the --technique arguments of this shard's rows
  local row
  kept=()
  while read -r row; do
    if [ $((index % shard_n)) -eq "$shard_k" ]; then kept+=(--technique "$row"); fi
    index=$((index + 1))
  done < <("$1" "$2")
}

for t in "${techniques[@]}"; do
  keep_shard rows_for "$t"
  [ ${#kept[@]} -eq 0 ] && continue
  for cam in $cameras; do run "$t-$cam" --camera "$cam" --size "$size" "${kept[@]}"; done
done

# TAA's settings act only with taa=1, and its histories from the second frame on: each technique's TAA
# rows over 3 frames of a strafe (camera motion; every resolve shader and history, its cross-frame barriers).
for t in "${techniques[@]}"; do
  keep_shard taa_rows_for "$t"
  [ ${#kept[@]} -eq 0 ] && continue
  run "$t-taa" --path strafe --frames 3 --camera puddles --size "$size" "${kept[@]}"
done

# The extremes: atlas sizes, 1 and 1024 reflectors, sizes from one pixel to the PPR limit. "small"
# (CI's slice) keeps the cheap ones.
if [ "$extremes" != none ]; then
  atlas_sizes="64 128 256 512 1024 2048 4096 8192"; sizes="1x1 16x16 17x9 1x4096 4096x1 641x359 4096x2304"
  [ "$extremes" = small ] && atlas_sizes="64 8192" && sizes="1x1 17x9 1x4096"
  atlas=(); for a in $atlas_sizes; do atlas+=(--technique "ppr@glass_atlas=$a"); done
  run atlas-sizes --camera glass --size "$size" "${atlas[@]}"
  run reflectors-1 --scene stress:1 --size "$size" --technique ppr --technique ssr-hiz --technique raytraced
  run reflectors-1024 --scene stress:1024 --size "$size" --technique ppr --technique ssr-hiz --technique raytraced
  for s in $sizes; do
    run "size-$s" --camera overview --size "$s" --technique ppr --technique ssr-hiz --technique raytraced
  done
fi

echo "validation-sweep: $runs runs, $rows_total technique rows (+ the planar reference each), $failed failed, $errors_total validation errors; logs in $out" | tee -a "$summary"
[ $failed -eq 0 ] && [ $errors_total -eq 0 ]
