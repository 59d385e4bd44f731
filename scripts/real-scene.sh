#!/usr/bin/env bash
# A real third-party scene end to end (README "Real scenes"): the KIT/IAI "FZK-Haus" IFC model that
# Debian's assimp-testmodels installs, converted to glTF by assimp, its floors and glazing fitted with
# reflectors by `ppr fit`, then captured and compared with validation. Nothing is written into the
# repository.
#   scripts/real-scene.sh [--ppr EXE] [--size WxH] [--out DIR]
# Model: made by KIT/IAI (Karlsruhe Institute of Technology / Institute for Applied Computer
# Science), "used with permission and fine to redistribute; KIT/IAI would appreciate if the
# attribution was retained" (AC14-FZK-Haus.source.txt beside the model).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
size=960x540
out="$root/out/real-scene"
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "real-scene: unknown argument $1" >&2; exit 2 ;;
  esac
done
ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
command -v assimp >/dev/null || { echo "real-scene: assimp not found (apt-get install assimp-utils; scripts/install-deps.sh does)" >&2; exit 2; }
[ -f "$ifc" ] || { echo "real-scene: $ifc not found (apt-get install assimp-testmodels)" >&2; exit 2; }
mkdir -p "$out"
scene="$out/fzk-haus.gltf"
reflectors="$out/fzk-haus.reflectors.json"  # the sidecar name: view and capture find it by themselves

assimp export "$ifc" "$scene" -fgltf2 >"$out/assimp.log" 2>&1 || { cat "$out/assimp.log" >&2; exit 1; }
echo "real-scene: $ifc -> $scene"
# The Khronos glTF validator over the converted file, when scripts/test.sh has installed it.
validator="$root/tools/gltf-validator"
if [ -d "$validator/node_modules/gltf-validator" ]; then node "$validator/validate.mjs" "$scene"; fi
# The concrete slabs: the ground floor, the upper floor and the ceiling under it.
"$ppr" fit --scene "$scene" --materials '^Beton$' --min-area 4 --out "$reflectors" | tee "$out/fit.txt"
# The glazing: every pane face of half a square metre or more, appended (glass reflectors; the glass
# pass finds each pixel's pane, as the converter merges a window's panes into one draw).
"$ppr" fit --scene "$scene" --materials '^Glas$' --min-area 0.5 --append --out "$reflectors" | tee "$out/fit-glass.txt"
# Inside, on the ground floor, looking across the kitchen to the stairs (no camera in the file).
camera="2,1.6,-1.5,45,-25,70"
"$ppr" capture --validation --scene "$scene" --reflectors "$reflectors" --camera "$camera" --size "$size" --frames 2 --out "$out/capture"
"$ppr" capture --scene "$scene" --reflectors "$reflectors" --camera "$camera" --size "$size" --frames 1 --technique none --out "$out/capture-none"
"$ppr" compare --validation --scene "$scene" --reflectors "$reflectors" --camera "$camera" --size "$size" --frames 1 \
  --technique ppr --technique ssr-hiz --out "$out/compare" | tee "$out/compare.txt"
# Along the ground floor to the glass door at its end: floor and glazing reflections together.
windows="3,1.5,-1,70,-5,70"
"$ppr" capture --scene "$scene" --reflectors "$reflectors" --camera "$windows" --size "$size" --frames 2 --out "$out/capture-windows"
"$ppr" capture --scene "$scene" --reflectors "$reflectors" --camera "$windows" --size "$size" --frames 1 --technique none --out "$out/capture-windows-none"
"$ppr" compare --validation --scene "$scene" --reflectors "$reflectors" --camera "$windows" --size "$size" --frames 1 \
  --technique ppr --out "$out/compare-windows" | tee "$out/compare-windows.txt"

# What must hold: the fit found the floors, and PPR covers them and is at least as close to the planar
# truth as Hi-Z SSR ("ppr: custom   ppr     PSNR  52.88 dB (reflection alone  31.30 dB)  coverage 0.9993 ...").
fitted=$(sed -n 's/^\([0-9]*\) reflectors;.*/\1/p' "$out/fit.txt")
[ "${fitted:-0}" -ge 3 ] || { echo "real-scene: ppr fit found ${fitted:-no} reflectors, expected the 3 slab faces at least" >&2; exit 1; }
score() { awk -v t="$1" '$3 == t && $4 == "PSNR" { gsub(/\)/, "", $9); print $9, $12 }' "$out/compare.txt"; }
read -r ppr_db ppr_cov < <(score ppr)
read -r hiz_db _ < <(score ssr-hiz)
awk -v p="$ppr_db" -v c="$ppr_cov" -v h="$hiz_db" 'BEGIN { exit !(c >= 0.99 && p >= h) }' ||
  { echo "real-scene: ppr reflection ${ppr_db:-?} dB, coverage ${ppr_cov:-?}; ssr-hiz ${hiz_db:-?} dB: expected coverage >= 0.99 and ppr >= ssr-hiz" >&2; exit 1; }
echo "real-scene: ppr reflection $ppr_db dB (coverage $ppr_cov), ssr-hiz $hiz_db dB"
# The glazing ("ppr: custom   ppr     glass: PSNR  30.48 dB (reflection alone  26.77 dB)  coverage 0.9999  over 7962 texels").
panes=$(sed -n 's/^\([0-9]*\) reflectors;.*/\1/p' "$out/fit-glass.txt")
[ "${panes:-0}" -ge 2 ] || { echo "real-scene: ppr fit found ${panes:-no} glass reflectors, expected the panes of the windows" >&2; exit 1; }
read -r glass_db glass_cov glass_texels < <(awk '$3 == "ppr" && $4 == "glass:" { gsub(/\)/, "", $10); print $10, $13, $15 }' "$out/compare-windows.txt")
awk -v c="$glass_cov" -v n="$glass_texels" 'BEGIN { exit !(c >= 0.98 && n >= 100) }' ||
  { echo "real-scene: ppr glass reflection coverage ${glass_cov:-?} over ${glass_texels:-?} texels: expected >= 0.98 over >= 100" >&2; exit 1; }
echo "real-scene: ppr glass reflection $glass_db dB (coverage $glass_cov over $glass_texels texels, $panes pane reflectors)"
echo "real-scene: done ($out: fit.txt, fit-glass.txt, capture*/final.png, compare*/metrics.json)"
