#pragma once
#include "cli/cli.hpp"

namespace ppr::app {
// `ppr bench`: GPU timings in one process, warm-up then the median of --frames frames per
// configuration, with a progress line on stderr. Sweeps (--sweep, default all):
//   techniques  every technique but none (or the --technique ones) on one camera: GPU ms per technique
//               and pass, × PPR, × floor, the depth hierarchy build alone, PSNR and coverage against
//               planar (always measured), the slides' numbers beside ours;
//   reflectors  the stress scene with N = 1 … 1024 mirror tiles × tiles=1|0 → projection-pass ms;
//   coverage    stress-scene cameras ~5 / 25 / 100 % reflective × indirect=1|0 → reflection-pass ms.
// Writes bench.json, bench.md and bench.png (the sweeps' plot) into --out. Returns the exit code.
int runBench(const Options& options);
}  // namespace ppr::app
