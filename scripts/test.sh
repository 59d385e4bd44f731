#!/usr/bin/env bash
# Install + build, then the whole test suite (unit, gpu on lavapipe with validation, ui under Xvfb),
# then a short fuzz run of each libFuzzer target and the unit tests under the sanitizers.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
# The Khronos glTF validator for the unit.gltf.* tests, from the npm registry at the version
# tools/gltf-validator/package-lock.json pins (Node.js and npm are on every machine this runs on).
if [ ! -d "$root/tools/gltf-validator/node_modules/gltf-validator" ]; then
  npm ci --prefix "$root/tools/gltf-validator" --no-audit --no-fund
fi
ctest --test-dir "$root/build/release" --output-on-failure -j"$(nproc)" "$@"
# The whole suite (no ctest arguments) ends with a short fuzz run: each libFuzzer target for
# PPR_FUZZ_SECONDS (default 20; 0 skips) on its seeds, after replaying the saved regressions
# (clang build in build/fuzz; docs/reliability.md#fuzzing). A crash fails the suite.
fuzz_seconds="${PPR_FUZZ_SECONDS:-$([ $# -eq 0 ] && echo 20 || echo 0)}"
if [ "$fuzz_seconds" != 0 ]; then
  bash "$root/scripts/fuzz.sh" "$fuzz_seconds"
fi
# ... and the unit tests again under AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer
# (build/asan; docs/reliability.md#sanitizers). PPR_SANITIZE_UNIT=0 skips it.
if [ "${PPR_SANITIZE_UNIT:-$([ $# -eq 0 ] && echo 1 || echo 0)}" != 0 ]; then
  bash "$root/scripts/sanitize.sh" unit
fi
