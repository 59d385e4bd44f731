#!/usr/bin/env bash
# The pure areas' unit tests link no Vulkan, GLFW or ImGui (issue: pure logic tested without them):
# no such shared library in ldd, no such symbol in the binary.
#   pure_link_check.sh EXE...
set -euo pipefail
status=0
for exe in "$@"; do
  name=$(basename "$exe")
  if ldd "$exe" | grep -Eq 'libvulkan|libglfw'; then
    echo "$name links $(ldd "$exe" | grep -Eo 'lib(vulkan|glfw)[^ ]*' | tr '\n' ' ')"; status=1
  fi
  if nm -C "$exe" | grep -Eq ' (ImGui::|vk[A-Z][A-Za-z]+$|glfw[A-Z])'; then
    echo "$name contains $(nm -C "$exe" | grep -Eo '(ImGui::[A-Za-z]+|vk[A-Z][A-Za-z]+$|glfw[A-Z][A-Za-z]+)' | sort -u | head -3 | tr '\n' ' ')"; status=1
  fi
  [ $status -eq 0 ] && echo "$name: no Vulkan, GLFW or ImGui"
done
exit $status
