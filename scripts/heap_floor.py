#!/usr/bin/env python3
"""Which allocation site's live heap grows during a run: reads a heaptrack recording (.zst).

For every allocation site (the first instruction outside the C and C++ runtimes' allocators on the
allocating stack, whatever the path to it), the least number of live bytes over heaptrack's ~10 ms ticks is taken in an early and a late window of the run (fractions of its length); a leak
raises that floor, a transient (a frame's command memory, a worker's scratch) does not. Prints the
floor growth in bytes, the sites that grew with the project function that called in, and the same
floor statistic for resident memory (heaptrack's RSS samples).

usage: heap_floor.py RECORDING.zst [--early A,B] [--late C,D]   (fractions, default 0.3,0.45 0.8,0.95)
"""
import argparse
import collections
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("recording")
    ap.add_argument("--early", default="0.3,0.45")
    ap.add_argument("--late", default="0.8,0.95")
    ap.add_argument("--project-module", default="ppr", help="the binary whose frames name the caller")
    args = ap.parse_args()
    fractions = [float(x) for x in args.early.split(",") + args.late.split(",")]

    # First pass: the run's length (tick times are ms from the start, hex).
    ticks = subprocess.run(["zstdcat", args.recording], capture_output=True, text=True, errors="replace").stdout
    times = [int(line[2:], 16) for line in ticks.splitlines() if line.startswith("c ")]
    if len(times) < 20:
        sys.exit(f"{args.recording}: only {len(times)} heaptrack ticks; run longer")
    first, last = times[0], times[-1]
    windows = [(first + fractions[2 * k] * (last - first), first + fractions[2 * k + 1] * (last - first)) for k in (0, 1)]

    strings, traces, ips, infos, leaves = [], [None], [None], [], []
    live = collections.Counter()  # live bytes per site (leaf instruction)
    touched = set()
    state = [None, None]  # per window: (live counts at its start, least counts of the sites touched in it)
    rss = [None, None]
    now = 0
    runtime = ("libc.so.6", "libstdc++.so.6", "libheaptrack_preload.so")
    site_memo = {}

    def site_of(trace):  # operator new and friends are one frame for everyone: skip them
        if trace in site_memo:
            return site_memo[trace]
        t = trace
        while t:
            ip_index, parent = traces[t]
            module = ips[ip_index][1]
            if not module or strings[module - 1].rsplit("/", 1)[-1] not in runtime or not parent:
                break
            t = parent
        site_memo[trace] = traces[t][0] if t else 0
        return site_memo[trace]

    for line in ticks.splitlines():
        kind, rest = line[:1], line[2:]
        if kind == "+" or kind == "-":
            i = int(rest, 16)
            live[leaves[i]] += infos[i][0] if kind == "+" else -infos[i][0]
            touched.add(leaves[i])
        elif kind == "c":
            now = int(rest, 16)
            for k, (a, b) in enumerate(windows):
                if a <= now <= b:
                    if state[k] is None:
                        state[k] = (live.copy(), {})
                    else:
                        start, least = state[k]
                        for i in touched:
                            least[i] = min(least.get(i, start[i]), live[i])
            touched = set()
        elif kind == "R":
            for k, (a, b) in enumerate(windows):
                if a <= now <= b:
                    pages = int(rest, 16)
                    rss[k] = pages if rss[k] is None else min(rss[k], pages)
        elif kind == "a":
            size, trace = rest.split()
            infos.append((int(size, 16), int(trace, 16)))
            leaves.append(site_of(infos[-1][1]))
        elif kind == "t":
            ip, parent = rest.split()
            traces.append((int(ip, 16), int(parent, 16)))
        elif kind == "i":
            ips.append([int(x, 16) for x in rest.split()])
        elif kind == "s":
            strings.append(rest.split(" ", 1)[1] if " " in rest else "")
    if state[0] is None or state[1] is None:
        sys.exit(f"{args.recording}: a window holds no tick")

    def tenths(leaf):  # a step stays level afterwards; a leak keeps climbing
        mine = {i for i in range(len(infos)) if leaves[i] == leaf}
        size = {i: infos[i][0] for i in mine}
        held, now, least = 0, 0, [None] * 10
        for line in ticks.splitlines():
            kind = line[:1]
            if (kind == "+" or kind == "-") and line[1:2] == " ":
                i = int(line[2:], 16)
                if i in mine:
                    held += size[i] if kind == "+" else -size[i]
            elif kind == "c":
                now = int(line[2:], 16)
                b = min(9, int(10 * (now - first) / max(1, last - first)))
                least[b] = held if least[b] is None else min(least[b], held)
        return [f"{x / 1024:.1f}" if x is not None else "-" for x in least]

    def floor(k, i):
        start, least = state[k]
        return least.get(i, start[i])

    def frame(ip_index):
        ip = ips[ip_index]
        module = strings[ip[1] - 1].rsplit("/", 1)[-1] if ip[1] else "?"
        function = strings[ip[2] - 1] if len(ip) > 2 and ip[2] else hex(ip[0])
        return function, module

    def describe(site, trace):
        function, module = frame(site)
        caller = None
        while trace and caller is None:
            ip_index, trace = traces[trace]
            f, m = frame(ip_index)
            caller = f[:120] if m == args.project_module else None
        return f"{function[:80]} [{module}]", caller or "(no frame of " + args.project_module + ")"

    # One allocator reached by many paths (a driver's pool refilled from different calls) is one site.
    example = {}  # site -> one full call stack, to name the caller
    for i, (size, trace) in enumerate(infos):
        if trace:
            example.setdefault(leaves[i], trace)
    growth = collections.Counter()
    sites = set(state[0][0]) | set(state[1][0]) | set(state[0][1]) | set(state[1][1])
    for leaf in sites:
        growth[leaf] = floor(1, leaf) - floor(0, leaf)
    print(f"run {last - first} ms; windows {windows[0][0]:.0f}-{windows[0][1]:.0f} and {windows[1][0]:.0f}-{windows[1][1]:.0f} ms; "
          f"{len(example)} allocation sites")
    print(f"live heap floor growth: {sum(growth.values())} bytes; sites that moved: {sum(1 for b in growth.values() if b)}")
    shown = sorted((k for k in growth if growth[k]), key=lambda k: -abs(growth[k]))[:8]
    for key in shown:
        leaf, caller = describe(key, example[key])
        print(f"  {growth[key]:+9d}  {leaf}  <- {caller}")
        print(f"             its live bytes' floor per tenth of the run (KiB): {' '.join(tenths(key))}")
    if rss[0] is not None and rss[1] is not None:
        print(f"resident floor: {rss[0] * 4} -> {rss[1] * 4} KiB ({(rss[1] - rss[0]) * 4:+d} KiB; heaptrack's samples, 4 KiB pages)")


if __name__ == "__main__":
    main()
