#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`: clang-14 + ASan + UBSan, in build/fuzz), replays their
# seeds and saved regressions, then fuzzes each target for SECONDS on a scratch copy of its seed
# corpus and prints, per target, executions, coverage (libFuzzer's cov/ft), corpus size and any crash.
#   scripts/fuzz.sh [SECONDS] [TARGET...]     SECONDS default 60; TARGETs: reflectors gltf cli camera_path (default all)
# Exits 1 when a target crashes (a sanitizer report, a broken invariant, an uncaught exception, a
# timeout or running out of memory); the input that did it is kept under build/fuzz/artifacts/.
# Seeds and dictionaries: tests/data/fuzz/. New corpus entries go to a temporary directory, removed
# at exit, unless PPR_FUZZ_WORK names a directory to keep them in (grown across runs).
# Installs nothing: clang-14 and libclang-rt-14-dev come from scripts/install-deps.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(reflectors gltf cli camera_path)
data="$root/tests/data/fuzz"
build="$root/build/fuzz"

if ! command -v clang++-14 >/dev/null; then
  echo "fuzz: clang++-14 not found (scripts/install-deps.sh installs clang-14 and libclang-rt-14-dev)" >&2
  exit 1
fi

start=$(date +%s)
cmake --preset fuzz -S "$root" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
echo "fuzz: built in $(( $(date +%s) - start )) s"
replay=$(IFS='|'; echo "${targets[*]}")
ctest --test-dir "$build" -L fuzz -R "^fuzz\.($replay)\.replay$" --output-on-failure

if [ -n "${PPR_FUZZ_WORK:-}" ]; then
  work="$PPR_FUZZ_WORK"
  mkdir -p "$work"
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/ppr-fuzz.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi
artifacts="$build/artifacts"
mkdir -p "$artifacts"

failed=0
summary=()
for t in "${targets[@]}"; do
  corpus="$work/$t"
  mkdir -p "$corpus"
  log="$work/$t.log"
  regressions=()
  [ -d "$data/regressions/$t" ] && regressions=("$data/regressions/$t")
  echo "fuzz: $t for $seconds s ..."
  rc=0
  # The first directory receives new inputs; the seeds and regressions are only read.
  "$build/bin/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -dict="$data/$t.dict" -artifact_prefix="$artifacts/$t-" \
    "$corpus" "$data/$t" "${regressions[@]}" >"$log" 2>&1 || rc=$?

  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([^ ]*\).*/\1/p' <<<"$last")
  if [ "$rc" -eq 0 ]; then
    verdict="no crash"
  else
    failed=1
    what=$(grep -m1 -E '^(==[0-9]+==ERROR|SUMMARY:|fuzz invariant broken|terminate called|.*runtime error:|==[0-9]+== ERROR: libFuzzer)' "$log" || echo "exit $rc")
    input=$(sed -n 's/.*Test unit written to \(.*\)/\1/p' "$log" | tail -1)
    verdict="CRASH: $what${input:+ (input: $input)}"
    tail -n 40 "$log" >&2
  fi
  line="$t: ${execs:-?} executions (${rate:-?}/s), cov ${cov:-?} ft ${ft:-?}, corpus ${corp:-?}, $verdict"
  echo "fuzz: $line"
  summary+=("$line")
done

echo "fuzz: summary ($seconds s per target, $(( $(date +%s) - start )) s in all)"
printf '  %s\n' "${summary[@]}"
exit "$failed"
