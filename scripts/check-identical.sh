#!/usr/bin/env bash
# Renders the same frames with two `ppr` builds and checks the images are bit-identical: every
# technique on every named camera of the default scene (capture), plus compare's reflection images
# (the planar reference and each technique's reflection buffer as scored), with the --set values given.
#   scripts/check-identical.sh OLD_PPR NEW_PPR [--size WxH] [--scene F] [--set key=value]... [--new-set key=value]...
# --set goes to both builds, --new-set only to the new one (a new mode switched off, which the old
# build does not know). Exit 0 when every image matches, 1 listing those that differ. Used to show
# that a refactor, or a new mode switched off, changes no picture.
set -euo pipefail
old="$1"; new="$2"; shift 2
size=640x360
extra=()
new_only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    --new-set) new_only+=(--set "$2"); shift 2 ;;
    *) extra+=("$1"); shift ;;
  esac
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
techniques=(ppr ssr-brute ssr-lowq ssr-hiz ssr-linear planar floor none)
for side in old new; do
  exe="${!side}"
  args=("${extra[@]}")
  if [ "$side" = new ]; then args+=("${new_only[@]}"); fi
  for t in "${techniques[@]}"; do
    "$exe" capture --technique "$t" --size "$size" --frames 2 --out "$work/$side/capture-$t" "${args[@]}" >/dev/null
  done
  compare_args=()
  for t in "${techniques[@]}"; do compare_args+=(--technique "$t"); done
  "$exe" compare "${compare_args[@]}" --size "$size" --frames 1 --out "$work/$side/compare" "${args[@]}" >/dev/null
done
checked=0; differ=0
while IFS= read -r -d '' f; do
  rel="${f#"$work/old/"}"
  case "$rel" in *.png) ;; *) continue ;; esac
  checked=$((checked + 1))
  if ! cmp -s "$f" "$work/new/$rel"; then
    echo "differs: $rel"
    differ=$((differ + 1))
  fi
done < <(find "$work/old" -type f -print0 | sort -z)
echo "check-identical: $checked images compared at $size ${extra[*]:-} (new build also: ${new_only[*]:-nothing}), $differ differ"
[ "$differ" -eq 0 ] && [ "$checked" -gt 0 ]
