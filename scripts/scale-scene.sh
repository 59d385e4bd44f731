#!/usr/bin/env bash
# The scale scene end to end (docs/scenes.md): generate it, check it with the Khronos glTF validator
# (zero errors, at least 1 000 000 triangles, 1000 materials and 500 textures), then load and render
# it with validation, printing the load-and-render wall time and peak memory.
#   scripts/scale-scene.sh [--ppr EXE] [--generator EXE] [--segments N] [--size WxH] [--out DIR]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
generator="$root/build/release/content/ppr_make_default_scene"
segments=32
size=640x360
out="$root/out/scale-scene"
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --generator) generator="$2"; shift 2 ;;
    --segments) segments="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "scale-scene: unknown argument $1" >&2; exit 2 ;;
  esac
done
rm -rf "$out/scene"
"$generator" --scale="$segments" "$out/scene"
validator="$root/tools/gltf-validator/validate.mjs"
line=$(node "$validator" "$out/scene/scale.gltf")
echo "$line"
# "...: 0 errors, 0 warnings, ...; 1045440 triangles, 1090 materials, 512 images, 1090 draw calls"
read -r errors triangles materials images < <(echo "$line" | sed -E 's/.*: ([0-9]+) errors,.*; ([0-9]+) triangles, ([0-9]+) materials, ([0-9]+) images.*/\1 \2 \3 \4/')
[ "$errors" = 0 ] || { echo "scale-scene: the validator found $errors errors" >&2; exit 1; }
if [ "$segments" = 32 ] && { [ "$triangles" -lt 1000000 ] || [ "$materials" -lt 1000 ] || [ "$images" -lt 500 ]; }; then
  echo "scale-scene: $triangles triangles, $materials materials, $images textures: expected at least 1000000, 1000, 500" >&2
  exit 1
fi
# Load (parse, upload, mip chains) and render both cameras with validation.
/usr/bin/time -f "scale-scene: load and render: %e s wall, %M KiB peak memory" \
  "$ppr" capture --validation --scene "$out/scene/scale.gltf" --size "$size" --frames 2 --out "$out/capture"
