#!/usr/bin/env bash
# Renders the pictures that show the renderer as it is today (the README's and the docs' headline
# images) into docs/images/, each from the command its caption names. Pictures of a measurement on a
# given day (a before/after, a sweep's plot, a GPU run) are not remade here: their sections say when
# and with what they were made.
#   scripts/docs-images.sh [--ppr EXE] [--out DIR] [--only NAME[,NAME...]] [--no-ui]
# --out       where the images go (default docs/images)
# --only      remake only these (the names in `names` below, without .png; an unknown one is an error)
# --no-ui     skip viewer.png and editor.png (they need Xvfb, xdotool and xwd, as the UI tests do)
# The renders are deterministic, but for the viewer's two, whose panel shows frame times: on an
# unchanged build the others come out the same byte for byte, so `git status docs/images` after a
# run shows which pictures a change altered.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ppr="$root/build/release/bin/ppr"
out="$root/docs/images"
only=""
ui=1
while [ $# -gt 0 ]; do
  case "$1" in
    --ppr) ppr="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --only) only=",$2,"; shift 2 ;;
    --no-ui) ui=0; shift ;;
    *) echo "docs-images: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x "$ppr" ] || { echo "docs-images: no ppr at $ppr (build first: scripts/build.sh)" >&2; exit 1; }
names=",overview,cameras,contact_puddles,contact_ssr_grazing,glass_contact,glass_atlas,debug_views,normalmap_contact,frame_graph,viewer,editor,"
for n in ${only//,/ }; do
  [[ "$names" == *",$n,"* ]] || { echo "docs-images: --only: no picture named '$n' (names: ${names:1:-1})" >&2; exit 2; }
done
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

wanted() { [ -z "$only" ] || [[ "$only" == *",$1,"* ]]; }
say() { echo "docs-images: $*"; }
# 8-bit PNGs written without a timestamp chunk, so that an unchanged picture stays the same file.
save() { convert "$1" -depth 8 -define png:exclude-chunks=date,time "$out/$2.png"; say "wrote $out/$2.png"; }

# README: the default scene's overview, PPR at 1280x720.
if wanted overview; then
  "$ppr" capture --camera overview --size 1280x720 --technique ppr --out "$work/overview" >/dev/null
  save "$work/overview/final.png" overview
fi

# README: four more named cameras, each captured at 1280x720, shown at half size in a 2 x 2 grid.
if wanted cameras; then
  for c in puddles grazing stairs mirror; do
    "$ppr" capture --camera "$c" --size 1280x720 --technique ppr --out "$work/cameras/$c" >/dev/null
  done
  montage "$work"/cameras/{puddles,grazing,stairs,mirror}/final.png -resize 640x360 -tile 2x2 -geometry +0+0 "$work/cameras.png"
  save "$work/cameras.png" cameras
fi

# README "PPR against the planar ground truth".
if wanted contact_puddles; then
  "$ppr" compare --camera puddles --size 640x360 --technique ppr --technique none --out "$work/puddles" >/dev/null
  save "$work/puddles/contact.png" contact_puddles
fi

# README "PPR against screen-space ray marching".
if wanted contact_ssr_grazing; then
  "$ppr" compare --camera grazing --size 480x270 --technique ppr --technique ssr-brute --technique ssr-lowq \
    --technique ssr-hiz --technique ssr-linear --out "$work/grazing" >/dev/null
  save "$work/grazing/contact.png" contact_ssr_grazing
fi

# README and docs/glass.md: the glass camera, PPR against ssr-hiz and the planar reference.
if wanted glass_contact; then
  "$ppr" compare --camera glass --size 640x360 --technique ppr --technique ssr-hiz --out "$work/glass" >/dev/null
  save "$work/glass/contact.png" glass_contact
fi

# docs/glass.md: debug=atlas, the glass reflection atlas fitted to the screen height.
if wanted glass_atlas; then
  "$ppr" capture --camera glass --size 640x360 --technique ppr --set debug=atlas --out "$work/atlas" >/dev/null
  save "$work/atlas/final.png" glass_atlas
fi

# docs/quality.md "Debug views": the intermediate buffer and the hole mask, puddles camera.
if wanted debug_views; then
  for v in intermediate holes; do
    "$ppr" capture --camera puddles --size 640x360 --technique ppr --set debug=$v --out "$work/debug_$v" >/dev/null
  done
  convert "$work/debug_intermediate/final.png" "$work/debug_holes/final.png" +append "$work/debug_views.png"
  save "$work/debug_views.png" debug_views
fi

# README and docs/normalmaps.md: the normalmap camera's modes against the ray-traced reference.
if wanted normalmap_contact; then
  "$ppr" compare --camera normalmap --size 480x270 --reference raytraced --technique ppr@normalmap=off \
    --technique ppr@normalmap=approx --technique ppr@normal_refine=0 --technique ppr --out "$work/normalmap" >/dev/null
  save "$work/normalmap/contact.png" normalmap_contact
fi

# docs/architecture.md: the frame graph of a capture with the default technique.
if wanted frame_graph; then
  "$ppr" capture --camera mirror --dump-graph --out "$work/graph" >/dev/null
  dot -Tpng "$work/graph/graph.dot" -o "$work/frame_graph.png"
  save "$work/frame_graph.png" frame_graph
fi

# README "Viewer" and "Authoring reflectors": the viewer in a virtual X display, 1280x720, puddles
# camera; then the Reflectors window opened and puddle_pot selected.
if [ "$ui" = 1 ] && { wanted viewer || wanted editor; }; then
  "$root/scripts/docs-images-ui.sh" "$ppr" "$work/ui"
  wanted viewer && save "$work/ui/viewer.png" viewer
  wanted editor && save "$work/ui/editor.png" editor
fi
say "done"
