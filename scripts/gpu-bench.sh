#!/usr/bin/env bash
# The measurements of docs/performance.md's GPU sections, in one run (the H200 session of 2026-11-29
# ran these): the bench at each size, the width and hierarchy-skip rows, the normal-mapped view, TAA,
# the open goals' ratios in rounds, then the GPU tests and a compare under validation. Each step's
# output lands in OUT/<step>/ and its log in OUT/<step>.log; OUT/steps.txt says what each step
# returned and took.
#   scripts/gpu-bench.sh [--ppr EXE] [--tests EXE] [--out DIR] [--sizes "1920x1080 3840x2160"]
#                        [--frames N] [--warmup N] [--no-tests]
# A timing never fails the script; a failed step is recorded and the next one runs. Exit 1 if any failed.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
tests="$root/build/release/tests/gpu/ppr_gpu_tests"
out="$root/out/gpu-bench"
sizes="1920x1080 3840x2160"
frames=30 warmup=10 run_tests=1
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --tests) tests="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --sizes) sizes="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --warmup) warmup="$2"; shift 2 ;;
    --no-tests) run_tests=0; shift ;;
    *) echo "gpu-bench.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out" || exit 2
: > "$out/steps.txt"
failed=0
step() {  # step NAME command...
  local name=$1; shift
  local t0=$SECONDS
  "$@" > "$out/$name.log" 2>&1
  local rc=$?
  [ $rc -ne 0 ] && failed=1
  echo "$name rc=$rc $((SECONDS - t0))s" | tee -a "$out/steps.txt"
}
timing="--frames $frames --warmup $warmup"
first_size=${sizes%% *}
for size in $sizes; do
  step "bench_$size" "$ppr" bench --size "$size" $timing --out "$out/bench_$size"
  step "widths_$size" "$ppr" bench --size "$size" $timing --sweep techniques --technique ppr \
    --technique ppr@project_threads=64 --technique ppr@project_threads=128 --technique ppr@reach_threads=4 \
    --technique ppr@reach_threads=64 --technique ppr@hiz_threads=16 --technique ppr@hiz_threads=64 --technique floor \
    --out "$out/widths_$size"
  step "features_$size" "$ppr" bench --size "$size" $timing --sweep techniques --technique ppr \
    --technique ppr@hiz_skip=0 --technique ssr-hiz --technique ssr-hiz@hiz_skip=0 --technique ppr@splat=0 \
    --technique ppr@holes=slides --technique ppr@normalmap=off --technique ppr@fallback=ssr --technique floor \
    --out "$out/features_$size"
  step "normalmap_$size" "$ppr" bench --size "$size" $timing --camera normalmap --sweep techniques \
    --technique ppr --technique ppr@fallback=ssr --technique ppr@normalmap=off --technique ssr-hiz --technique floor \
    --out "$out/normalmap_$size"
  step "taa_$size" "$ppr" bench --size "$size" $timing --set taa=1 --sweep techniques --technique ppr \
    --technique floor --technique ssr-hiz --out "$out/taa_$size"
  # The open goals' ratios, each taken within a round (bench.md "Rounds"): issue 15's planar part /
  # ssr-hiz, PPR / floor, classify / floor, 1 024 / 1 reflectors and ppr.reflect at 5 % / 100 %
  # coverage; issue 19's ppr.reflect against the slides' pass; issue 16's TAA against the floor pass,
  # and the split's second history (taa_split=1 against 0).
  step "goals_$size" "$ppr" bench --size "$size" $timing --rounds 3 --sweep techniques --sweep reflectors --sweep coverage \
    --technique ppr --technique ppr@holes=slides,facing=0 --technique ppr@taa=1 --technique ppr@taa=1,taa_split=0 \
    --technique ssr-hiz --technique floor --out "$out/goals_$size"
done
if [ $run_tests -eq 1 ]; then
  # A Vulkan instance per test: NVIDIA's driver needs more static TLS than glibc reserves by default.
  step gpu_tests env GLIBC_TUNABLES=glibc.rtld.optional_static_tls=1048576 "$tests" --gtest_brief=1
fi
step validation "$ppr" compare --validation --size "$first_size" --frames 3 --out "$out/validation"
step validation_taa "$ppr" capture --validation --size "$first_size" --set taa=1 --technique ppr --path strafe \
  --frames 8 --camera puddles --out "$out/validation_taa"
exit $failed
