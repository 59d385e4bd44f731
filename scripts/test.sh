#!/usr/bin/env bash
# Install + build, then the whole test suite (unit, gpu on lavapipe with validation, ui under Xvfb).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
ctest --test-dir "$root/build/release" --output-on-failure -j"$(nproc)" "$@"
