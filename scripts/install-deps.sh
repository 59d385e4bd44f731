#!/usr/bin/env bash
# Installs every Debian package the project needs; idempotent (does nothing when all are present).
# Mesa lavapipe 25 comes from bookworm-backports; VulkanMemoryAllocator (header only) from trixie,
# pinned at priority 50 so that `apt-get upgrade` never pulls anything else from trixie.
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

BOOKWORM_PKGS=(
  build-essential cmake pkg-config
  libvulkan-dev vulkan-validationlayers glslang-tools glslang-dev
  libglfw3-dev libglm-dev libtinygltf-dev libimgui-dev libstb-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  clang-14 libclang-rt-14-dev  # libFuzzer + ASan/UBSan runtimes for scripts/fuzz.sh (the fuzz preset)
  xvfb xauth xdotool x11-apps imagemagick graphviz assimp-testmodels
  assimp-utils  # scripts/real-scene.sh: the FZK-Haus IFC model to glTF
  time  # scripts/scale-scene.sh: load time and peak memory
  python3  # scripts/compare-timing.py, heap_floor.py, check-doc-links.py (tests run them)
)
BACKPORTS_PKGS=(mesa-vulkan-drivers)
TRIXIE_PKGS=(libvulkan-memory-allocator-dev)
MESA_MIN_MAJOR=25

missing=()
for p in "${BOOKWORM_PKGS[@]}" "${TRIXIE_PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
mesa_ver=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
mesa_ok=0
if [ -n "$mesa_ver" ] && [ "${mesa_ver%%.*}" -ge "$MESA_MIN_MAJOR" ] 2>/dev/null; then mesa_ok=1; fi

if [ ${#missing[@]} -eq 0 ] && [ $mesa_ok -eq 1 ]; then
  echo "install-deps: all packages present (mesa-vulkan-drivers $mesa_ver)"
  exit 0
fi

codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
if [ "$codename" != "bookworm" ]; then
  echo "install-deps: warning: expected Debian 12 (bookworm), found '${codename}'; trying anyway" >&2
fi

mirror="http://deb.debian.org/debian"
if [ ! -f /etc/apt/sources.list.d/ppr-backports.list ]; then
  echo "deb $mirror bookworm-backports main" | $SUDO tee /etc/apt/sources.list.d/ppr-backports.list >/dev/null
fi
if [ ! -f /etc/apt/sources.list.d/ppr-trixie.list ]; then
  echo "deb $mirror trixie main" | $SUDO tee /etc/apt/sources.list.d/ppr-trixie.list >/dev/null
fi
if [ ! -f /etc/apt/preferences.d/ppr-trixie-low ]; then
  printf 'Package: *\nPin: release n=trixie\nPin-Priority: 50\n' | $SUDO tee /etc/apt/preferences.d/ppr-trixie-low >/dev/null
fi

$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${BOOKWORM_PKGS[@]}"
$SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports "${BACKPORTS_PKGS[@]}"
$SUDO apt-get install -y -q --no-install-recommends "${TRIXIE_PKGS[@]/%//trixie}"
echo "install-deps: done (mesa-vulkan-drivers $(dpkg-query -W -f='${Version}' mesa-vulkan-drivers))"
