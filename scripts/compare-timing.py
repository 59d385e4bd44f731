#!/usr/bin/env python3
"""Times two `ppr` builds (or one build with two sets of settings) in interleaved rounds.

Each round runs `ppr capture` once with the old build, then once with the new one (the order swaps
every other round), on the same camera, size and scene, and reads report.json's per-pass medians.
Prints every round's milliseconds of the chosen passes for each side, the new/old ratio within each
round and the median of those ratios: on a shared machine whose speed drifts between runs (lavapipe
moved 30 % between runs of one binary, docs/performance.md), that median is the number to quote; a
single pair of runs is not. The sibling of check-identical.sh, which shows a change keeps the
pictures; this shows what it costs.

usage: compare-timing.py OLD_PPR NEW_PPR [--rounds N] [--pass P[+Q...]] [--frames F]
                         [--new-set key=value]... [--new-args "OPTIONS"] [-- capture options...]
  --pass      the passes summed (default: the technique's total, report.json's technique_gpu_ms);
              e.g. ppr.project+ppr.reach; a name ending in ? counts 0 where the frame has no such
              pass (a mode that adds one: --pass gbuffer+gbuffer.prepass? --new-set depth_prepass=0);
              total: the whole frame (report.json's total_gpu_ms)
  --new-set   a setting for the new side only (the same build twice: a mode on against off)
  --new-args  capture options for the new side only, after the shared ones (the last of an option
              wins): e.g. --new-args="--scene stress:1024" -- --scene stress:1 times 1 024
              reflectors against one, round by round
  after --     passed to both sides' `ppr capture` (--scene, --camera, --size, --technique, --set ...);
              one camera: overview unless --camera names another
Exit 0 when every run succeeded; the ratios are measurements, never a pass/fail verdict.
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys
import tempfile


def measure(exe, out, passes, frames, capture_args):
    cmd = [exe, "capture", "--frames", str(frames), "--out", out] + capture_args
    run = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        sys.exit("compare-timing: %s failed (%d): %s" % (" ".join(cmd), run.returncode, run.stderr.strip()))
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    if not passes:
        return report["technique_gpu_ms"]
    if passes == ["total"]:
        return report["total_gpu_ms"]
    missing = [p for p in passes if not p.endswith("?") and p not in report["passes"]]
    if missing:
        sys.exit("compare-timing: no pass %s in this frame (passes: %s)" % (", ".join(missing), ", ".join(sorted(report["passes"]))))
    present = [p.rstrip("?") for p in passes if p.rstrip("?") in report["passes"]]
    return sum(report["passes"][p]["gpu_ms"] for p in present)


def ratio(new, old):
    return new / old if old > 0 else float("nan")


def main():
    argv = sys.argv[1:]
    capture_args = []
    if "--" in argv:
        at = argv.index("--")
        argv, capture_args = argv[:at], argv[at + 1:]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--pass", dest="passes", default="", help="passes to sum, joined by +")
    ap.add_argument("--frames", type=int, default=12)
    ap.add_argument("--new-set", action="append", default=[])
    ap.add_argument("--new-args", default="")
    args = ap.parse_args(argv)
    if args.rounds < 1 or args.frames < 1:
        sys.exit("compare-timing: --rounds and --frames must be at least 1")
    if "--camera" not in capture_args:
        capture_args += ["--camera", "overview"]  # one report.json, not one per named camera
    passes = [p for p in args.passes.split("+") if p]
    new_args = capture_args + [a for kv in args.new_set for a in ("--set", kv)] + shlex.split(args.new_args)
    label = args.passes or "technique_gpu_ms"
    for name, exe, extra in (("old", args.old, capture_args), ("new", args.new, new_args)):
        print("%s: %s" % (name, " ".join([exe, "capture", "--frames", str(args.frames)] + [shlex.quote(a) for a in extra])))
    old_ms, new_ms = [], []
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.rounds):
            sides = [("old", args.old, capture_args, old_ms), ("new", args.new, new_args, new_ms)]
            if r % 2:
                sides.reverse()  # neither side always runs first
            for name, exe, extra, into in sides:
                into.append(measure(exe, os.path.join(work, name), passes, args.frames, extra))
            print("round %d: old %.3f ms, new %.3f ms, new/old %.3f" % (r + 1, old_ms[-1], new_ms[-1], ratio(new_ms[-1], old_ms[-1])))
    ratios = [ratio(n, o) for n, o in zip(new_ms, old_ms)]
    print("compare-timing: %s over %d rounds: old median %.3f ms, new median %.3f ms, new/old median of the rounds' ratios %.3f"
          % (label, args.rounds, statistics.median(old_ms), statistics.median(new_ms), statistics.median(ratios)))


if __name__ == "__main__":
    main()
