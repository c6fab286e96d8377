#!/usr/bin/env bash
# Installs every Debian 12 package rayspec needs to build, test and run.
# Idempotent: packages already present are left alone. Needs root; without it,
# prints the exact commands to run instead.
set -euo pipefail

BACKPORTS_LINE="deb http://deb.debian.org/debian bookworm-backports main"
BACKPORTS_FILE=/etc/apt/sources.list.d/rayspec-bookworm-backports.list

# Packages from bookworm itself.
PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev vulkan-tools vulkan-validationlayers
  glslang-dev glslang-tools spirv-tools
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libre2-dev libssl-dev
  chromium fonts-dejavu-core gnuplot-nox
  clang libclang-rt-14-dev clang-format universal-ctags
  ccache
)
# Packages that must come from bookworm-backports (lavapipe with ray tracing).
BACKPORT_PACKAGES=(mesa-vulkan-drivers)
MIN_MESA_MAJOR=25

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
mesa_version=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
mesa_major=${mesa_version%%.*}
need_mesa=0
if [[ -z "$mesa_version" || "${mesa_major:-0}" -lt $MIN_MESA_MAJOR ]]; then need_mesa=1; fi
need_backports=0
grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/ || need_backports=1

if [[ ${#missing[@]} -eq 0 && $need_mesa -eq 0 ]]; then
  echo "setup: all packages present (mesa-vulkan-drivers $mesa_version)"
  exit 0
fi

commands=()
[[ $need_backports -eq 1 ]] && commands+=("echo '$BACKPORTS_LINE' > $BACKPORTS_FILE")
commands+=("apt-get update")
[[ ${#missing[@]} -gt 0 ]] && commands+=("DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends ${missing[*]}")
[[ $need_mesa -eq 1 ]] && commands+=("DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends -t bookworm-backports ${BACKPORT_PACKAGES[*]}")

if [[ $(id -u) -ne 0 ]]; then
  echo "setup: missing packages: ${missing[*]} $([[ $need_mesa -eq 1 ]] && echo "mesa-vulkan-drivers>=$MIN_MESA_MAJOR (backports)")" >&2
  echo "setup: not root; run these as root, then run this script again:" >&2
  for c in "${commands[@]}"; do echo "  sudo sh -c \"$c\"" >&2; done
  exit 1
fi

for c in "${commands[@]}"; do
  echo "setup: $c"
  sh -c "$c"
done
echo "setup: done (mesa-vulkan-drivers $(dpkg-query -W -f='${Version}' mesa-vulkan-drivers))"
