#!/usr/bin/env bash
# The soak (docs/reliability.md): memory must be flat after warm-up.
#   scripts/soak.sh [--frames N] [--viewer-seconds S] [--size WxH] [--ppr EXE] [--no-viewer]
# 1. Headless: `ppr capture` of N frames (default 5 000) per technique at a small size, printing a
#    memory sample every 100 frames (PPR_MEMORY_LOG); growth is measured from frame 1 000 (warm-up:
#    each technique's resident memory takes one step somewhere before frame 900, docs/reliability.md)
#    to the end and reported per 1 000 frames.
# 2. Viewer: `ppr view` under Xvfb for S seconds (default 600) driving itself (PPR_VIEWER_SOAK=1:
#    techniques, random setting values, window sizes from 1x1 up, iconify/restore).
# --heaptrack: run each capture under heaptrack (Debian package `heaptrack`) and name the allocation
#    sites whose live heap floor grew between the early and the late part of the run
#    (scripts/heap_floor.py): the resident figure cannot tell whose memory moved, this can.
# --no-capture / --no-viewer skip a part. Prints a summary table; exit 1 if any run failed, if VMA
# allocations, bytes or Vulkan object counts grew after warm-up, or if resident or malloc'd memory rose
# in every quarter of the run by more than --rss-limit / --heap-limit KiB per 1 000 frames (defaults 16
# and 4; see growth() below). The net change of each is reported too.
# PPR_MEMORY_TEST_LEAK=N in the environment makes ppr leak N bytes a frame: the soak's own test.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
frames=5000; seconds=600; size=64x64; viewer=1; rss_limit=16; heap_limit=4; warmup=1000; every=100
techniques=""
capture=1; heaptrack=0
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --viewer-seconds) seconds="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --ppr) ppr="$2"; shift 2 ;;
    --no-viewer) viewer=0; shift ;;
    --no-capture) capture=0; shift ;;
    --rss-limit) rss_limit="$2"; shift 2 ;;
    --heap-limit) heap_limit="$2"; shift 2 ;;
    --warmup) warmup="$2"; shift 2 ;;
    --every) every="$2"; shift 2 ;;
    --techniques) techniques="$2"; shift 2 ;;
    --heaptrack) heaptrack=1; shift ;;
    *) echo "soak: unknown argument $1" >&2; exit 2 ;;
  esac
done
work="$(mktemp -d)"
if [ $heaptrack -eq 1 ] && ! command -v heaptrack >/dev/null; then
  echo "soak: --heaptrack needs heaptrack (sudo apt-get install heaptrack)" >&2; exit 2
fi
if [ -z "$techniques" ]; then
  techniques=$("$ppr" --help | sed -n '/^  --technique/,/^  --reference/p' | sed -nE 's/^    ([a-z][a-z-]*) {2,}.*/\1/p' | tr '\n' ' ')
fi

# growth LOG WARMUP: from the memory lines of one run after WARMUP, per 1 000 frames:
#   "rss rss_rise shm heap heap_rise vma_allocations vma_bytes pipelines layouts pools frames allocations pipelines".
# VMA and the object counts are exact: last sample minus first. Resident and malloc'd memory jitter by
# up to a few MiB with the driver's worker threads (lavapipe's transient blocks, alive or not at the
# moment of a sample), so they are judged by their floor, the least sample of each quarter of the run:
# a transient does not raise a floor, a leak raises every one.
# - rss, shm, heap: the last quarter's floor against the first's, over the frames between their middles
#   (the net change; a one-time step or a page touched late counts in it).
# - rss_rise, heap_rise: sustained growth, the least rise within one quarter of the floor from there on
#   (the least of a sample and all later ones, which ignores a transient and a wander back down). A
#   leak raises it in every quarter by its rate; a one-time step raises it in one quarter only. This is
#   what the script asserts.
# Resident memory is the process's own (anonymous + file-backed); shared memory (the X server's
# presentation buffers, which follow the window sizes visited) is reported apart and not asserted.
growth() {
  awk -v warm="$2" '
    /^ppr: memory / {
      for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
      if (v["frame"] + 0 < warm + 0) next
      n++; f[n] = v["frame"]; heap[n] = v["heap_kib"]; shm[n] = v["rss_shmem_kib"] + 0
      rss[n] = ("rss_anon_kib" in v) ? v["rss_anon_kib"] + v["rss_file_kib"] : v["rss_kib"]
      if (n == 1) for (k in v) first[k] = v[k]
      for (k in v) last[k] = v[k]
    }
    function lo(i) { return int((i - 1) * n / parts) + 1 }
    function hi(i) { return int(i * n / parts) }
    function floorOf(a, i,   j, m) { m = a[lo(i)]; for (j = lo(i); j <= hi(i); j++) if (a[j] < m) m = a[j]; return m }
    function mid(i) { return (f[lo(i)] + f[hi(i)]) / 2 }
    function rate(a, i, k) { return mid(k) > mid(i) ? (floorOf(a, k) - floorOf(a, i)) * 1000.0 / (mid(k) - mid(i)) : 0 }
    function rise(a,   g, i, j, m, r) {
      for (j = n; j >= 1; j--) g[j] = (j == n || a[j] < g[j + 1]) ? a[j] : g[j + 1]
      for (i = 1; i <= parts; i++) {
        r = f[hi(i)] > f[lo(i)] ? (g[hi(i)] - g[lo(i)]) * 1000.0 / (f[hi(i)] - f[lo(i)]) : 0
        if (i == 1 || r < m) m = r
      }
      return m
    }
    END {
      if (n == 0) { print "none"; exit }
      parts = n < 4 ? n : 4
      span = last["frame"] - first["frame"]; s = span > 0 ? 1000.0 / span : 0
      printf "%.1f %.1f %.1f %.1f %.1f %.2f %.0f %d %d %d %d %d %d\n",
        rate(rss, 1, parts), rise(rss), rate(shm, 1, parts), rate(heap, 1, parts), rise(heap),
        (last["vma_allocations"] - first["vma_allocations"]) * s, (last["vma_bytes"] - first["vma_bytes"]) * s,
        last["pipelines"] - first["pipelines"], last["descriptor_set_layouts"] - first["descriptor_set_layouts"],
        last["descriptor_pools"] - first["descriptor_pools"], span, last["vma_allocations"], last["pipelines"]
    }' "$1"
}

fail=0
row='%-12s %7s %11s %11s %10s %11s %11s %13s %15s %10s %8s %7s %7s\n'
printf "$row" run frames "rss KiB/1k" "rss rise/1k" "shm KiB/1k" "heap KiB/1k" "heap rise/1k" "vma allocs/1k" "vma bytes/1k" pipelines+ layouts+ pools+ allocs
report() {  # name log rc [warm-up frame]
  local g; g=$(growth "$2" "${4:-$warmup}")
  if [ "$3" -ne 0 ] || [ "$g" = none ]; then echo "$1: FAILED (exit $3; see $2)"; fail=1; return; fi
  read -r rss rss_rise shm heap heap_rise allocs bytes pipes layouts pools span nallocs npipes <<<"$g"
  printf "$row" "$1" "$span" "$rss" "$rss_rise" "$shm" "$heap" "$heap_rise" "$allocs" "$bytes" "$pipes" "$layouts" "$pools" "$nallocs"
  local what=""
  awk -v a="$allocs" -v b="$bytes" 'BEGIN { exit !(a != 0 || b != 0) }' && what+=" VMA"
  [ "$pipes" -ne 0 ] || [ "$layouts" -ne 0 ] || [ "$pools" -ne 0 ] && what+=" objects"
  awk -v r="$rss_rise" -v l="$rss_limit" 'BEGIN { exit !(r > l) }' && what+=" resident"
  awk -v h="$heap_rise" -v l="$heap_limit" 'BEGIN { exit !(h > l) }' && what+=" heap"
  if [ -n "$what" ]; then echo "  ^ grew after warm-up (frame ${4:-$warmup}):$what"; fail=1; fi
}

[ $capture -eq 0 ] && techniques=""
for t in $techniques; do
  log="$work/capture-$t.log"
  wrap=(); [ $heaptrack -eq 1 ] && wrap=(heaptrack -o "$work/heap-$t")
  PPR_MEMORY_LOG=$every "${wrap[@]}" "$ppr" capture --technique "$t" --camera overview --size "$size" --set shadowres=256 --frames "$frames" --out "$work/$t" >"$log" 2>&1
  report "$t" "$log" $?
  if [ $heaptrack -eq 1 ]; then
    python3 "$root/scripts/heap_floor.py" "$work/heap-$t.zst" | sed 's/^/    /' || fail=1
  fi
done

if [ $viewer -eq 1 ]; then
  log="$work/viewer.log"
  display=:$((90 + RANDOM % 9))
  Xvfb "$display" -screen 0 1600x900x24 >/dev/null 2>&1 &
  xvfb=$!
  sleep 1
  DISPLAY=$display PPR_VIEWER_SOAK=1 timeout -s INT "$seconds" "$ppr" view --size 640x360 >"$log" 2>&1
  rc=$?
  [ $rc -eq 124 ] && rc=0  # (timeout's own code when it had to signal; ppr exits 0 on SIGINT)
  kill "$xvfb" 2>/dev/null
  report viewer "$log" $rc 1  # the viewer samples itself at the end of each cycle's home stretch (frame 599, 1199, ...)
fi
echo "soak: logs in $work"
exit $fail
