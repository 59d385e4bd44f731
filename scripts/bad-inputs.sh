#!/usr/bin/env bash
# Bad input, end to end (docs/reliability.md): every case must exit non-zero (never a crash: no exit
# status of 128 or more) with one `ppr: error:` line naming the file, field or option and the problem.
#   scripts/bad-inputs.sh [--ppr EXE] [--markdown]
# Prints one line per case (or a Markdown table with --markdown); exit 1 if any case misbehaved.
# The full-disk case mounts a 200 KiB tmpfs and is skipped where mounting is not allowed.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
markdown=0
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --markdown) markdown=1; shift ;;
    *) echo "bad-inputs: unknown argument $1" >&2; exit 2 ;;
  esac
done
work="$(mktemp -d)"
cleanup() { mountpoint -q "$work/full" 2>/dev/null && umount "$work/full"; rm -rf "$work"; }
trap cleanup EXIT
cd "$work"

# Reflector files: one good reflector, then each problem.
good='{"name":"floor","center":[0,0,0],"normal":[0,1,0],"tangent":[1,0,0],"half_extents":[5,5]}'
refl() { printf '{"version":1,"reflectors":[%s]}' "$2" >"$1.json"; }
refl nan "${good/\[0,0,0\]/[0,NaN,0]}"
refl infinite "${good/\[5,5\]/[5,1e999]}"
refl zero_area "${good/\[5,5\]/[0,5]}"
refl huge "${good/\[5,5\]/[1e9,1e9]}"
refl far "${good/\[0,0,0\]/[0,1e9,0]}"
refl duplicate "$good,$good"
refl wrong_type "${good/\[0,1,0\]/\"up\"}"
refl not_unit "${good/\[0,1,0\]/[0,2,0]}"
awk 'BEGIN { printf "{\"version\":1,\"reflectors\":["; for (i = 0; i < 100000; i++) printf "%s{\"name\":\"r%d\",\"center\":[0,0,0],\"normal\":[0,1,0],\"tangent\":[1,0,0],\"half_extents\":[1,1]}", (i ? "," : ""), i; printf "]}" }' >many.json
head -c 100000 /dev/zero | tr '\0' '[' >deep.json
printf '{"asset":{"version":"2.0"},"nodes":[{"mesh":7}],"scenes":[{"nodes":[0]}]}' >dangling.gltf
printf '{"asset":{"version":"2.0"' >truncated.gltf
head -c 100000 /dev/zero | tr '\0' '[' >deep.gltf
printf 'glTF\x02\x00\x00\x00\xff\xff\xff\x7f' >lying_header.glb

results=()
fail=0
case_() {  # description, expected substring, then ppr arguments (run with the environment in $env)
  local what="$1" expect="$2"; shift 2
  local out rc
  out=$(env ${env:-} timeout 300 "$ppr" "$@" 2>&1 >/dev/null); rc=$?
  local line; line=$(printf '%s\n' "$out" | grep -m1 '^ppr: error:' || printf '%s\n' "$out" | tail -1)
  local verdict=ok
  if [ $rc -eq 0 ] || [ $rc -ge 124 ] || [[ "$line" != *"$expect"* ]]; then verdict=FAIL; fail=1; fi
  results+=("$verdict|$what|$rc|$line")
}
small=(capture --camera overview --size 64x64 --frames 1 --out "$work/out")
case_ "reflectors: NaN" "byte" "${small[@]}" --reflectors nan.json
case_ "reflectors: infinite (1e999)" "1e999" "${small[@]}" --reflectors infinite.json
case_ "reflectors: zero-area rectangle" "half_extents" "${small[@]}" --reflectors zero_area.json
case_ "reflectors: 1e9-sized rectangle" "half_extents: must be at most" "${small[@]}" --reflectors huge.json
case_ "reflectors: centre 1e9 m away" "center: beyond" "${small[@]}" --reflectors far.json
case_ "reflectors: 100 000 entries" "at most 16384" "${small[@]}" --reflectors many.json
case_ "reflectors: duplicate names" "duplicate name" "${small[@]}" --reflectors duplicate.json
case_ "reflectors: wrong type" "reflectors[0].normal" "${small[@]}" --reflectors wrong_type.json
case_ "reflectors: non-unit normal" "not unit length" "${small[@]}" --reflectors not_unit.json
case_ "reflectors: 100 000 nested brackets" "nested deeper" "${small[@]}" --reflectors deep.json
case_ "reflectors: missing file" "no such file" "${small[@]}" --reflectors missing.json
case_ "glTF: missing file" "no such file" "${small[@]}" --scene missing.gltf
case_ "glTF: dangling mesh index" "mesh 7 out of range" "${small[@]}" --scene dangling.gltf
case_ "glTF: truncated JSON" "truncated.gltf" "${small[@]}" --scene truncated.gltf
case_ "glTF: 100 000 nested brackets" "nested deeper" "${small[@]}" --scene deep.gltf
case_ "GLB: header claims 2 GiB" "lying_header.glb" "${small[@]}" --scene lying_header.glb
case_ "--size 0x0" "--size 0: out of range" capture --size 0x0
case_ "--size -5x10" "--size -5: expected a whole number" capture --size -5x10
case_ "--size 100000x100000" "--size 100000: out of range" capture --size 100000x100000
case_ "--size 8192x8192 with PPR" "at most 4096" capture --size 8192x8192
case_ "--frames 0" "--frames 0: out of range" capture --frames 0
case_ "--frames 1e12" "--frames 1e12: expected a whole number" capture --frames 1e12
case_ "--set unknown key" "--set colour" capture --set colour=red
case_ "--set value out of range" "--set glass_atlas=9" capture --set glass_atlas=9
case_ "--camera unknown name" "--camera" "${small[@]/overview/attic}"
case_ "--out under /proc" "--out /proc/ppr: cannot create directory" "${small[@]/$work\/out//proc/ppr}"
touch "$work/file"
case_ "--out is a file" "cannot create directory" "${small[@]/$work\/out/$work/file/sub}"
env="PPR_HEAP_LIMIT_MB=64" case_ "device heap of 64 MiB at 1920x1080" "device memory:" capture --camera overview --size 1920x1080 --frames 1 --out "$work/out"
env="PPR_HIDE_RAY_QUERY=1" case_ "raytraced without ray queries" "lacks VK_KHR_ray_query" "${small[@]}" --technique raytraced
if mkdir -p "$work/full" && mount -t tmpfs -o size=200k tmpfs "$work/full" 2>/dev/null; then
  case_ "disk full during a capture (200 KiB tmpfs)" "write failed" capture --size 640x360 --frames 1 --out "$work/full/out"
else
  results+=("skipped|disk full during a capture (cannot mount a tmpfs here)|-|-")
fi

if [ $markdown -eq 1 ]; then
  echo "| case | exit | message |"
  echo "|---|---|---|"
  for r in "${results[@]}"; do IFS='|' read -r v what rc line <<<"$r"; echo "| $what | $rc | \`${line//|/\\|}\` |"; done
else
  for r in "${results[@]}"; do IFS='|' read -r v what rc line <<<"$r"; printf '%-7s %-45s exit %-3s %s\n' "$v" "$what" "$rc" "$line"; done
fi
[ $fail -eq 0 ]
