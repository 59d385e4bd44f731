#!/usr/bin/env bash
# The main job: install + build, then the viewer when a display is present, otherwise headless
# captures of every named camera of the default scene into out/. Extra arguments go to `ppr`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
cd "$root"
exec "$root/build/release/bin/ppr" "$@"
