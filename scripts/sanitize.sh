#!/usr/bin/env bash
# The sanitizer build (docs/reliability.md): the `asan` preset builds everything with AddressSanitizer,
# LeakSanitizer and UndefinedBehaviorSanitizer (build/asan), then runs the tests under them.
#   scripts/sanitize.sh [unit|gpu|all]     (default unit: what CI runs; gpu adds the GPU tests)
# Its executables keep dlopen()ed libraries loaded to the end, so a leak's stack names its library; leaks
# are suppressed only inside the Khronos validation layer (tests/sanitize/lsan.supp, justified there).
# Exit non-zero on any report or failing test.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
what="${1:-unit}"
cmake --preset asan -S "$root" >/dev/null
if [ "$what" = unit ]; then
  cmake --build "$root/build/asan" -j"$(nproc)" --target ppr_unit_tests
else
  cmake --build "$root/build/asan" -j"$(nproc)"
fi
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
labels=unit
[ "$what" = gpu ] && labels=gpu
[ "$what" = all ] && labels='unit|gpu|ui'
ctest --test-dir "$root/build/asan" --output-on-failure -j"$(nproc)" -L "$labels"
