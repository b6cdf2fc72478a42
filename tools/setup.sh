#!/usr/bin/env bash
# Installs what Proceduray needs on Debian 12 (bookworm), then checks that a Vulkan
# device offers ray tracing. Idempotent: when everything is present it only checks.
#   sudo tools/setup.sh          # or as root
#   PROCEDURAY_SETUP_QUIET=1 tools/setup.sh   # less output
set -euo pipefail

say() { [ "${PROCEDURAY_SETUP_QUIET:-0}" = 1 ] || echo "setup: $*"; }
die() { echo "setup: error: $*" >&2; exit 1; }

# Debian 12's own Mesa (22.3) has no ray tracing in lavapipe; >= 24.1 has.
mesa_min=24.1
pkgs=(libvulkan-dev glslang-dev glslang-tools libglm-dev libstb-dev doctest-dev
      vulkan-validationlayers vulkan-tools cmake meson ninja-build pkg-config g++ libcli11-dev libtinyobjloader-dev
      python3-matplotlib clang parallel)

have_pkg() { dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null | grep -q '^install ok installed'; }

mesa_version() { dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null | sed 's/^[0-9]*://'; }
mesa_ok() {
  local v; v=$(mesa_version) || return 1
  [ -n "$v" ] && dpkg --compare-versions "$v" ge "$mesa_min"
}

missing=()
for p in "${pkgs[@]}"; do have_pkg "$p" || missing+=("$p"); done

if [ ${#missing[@]} -gt 0 ] || ! mesa_ok; then
  [ "$(id -u)" = 0 ] || die "packages missing (${missing[*]:-mesa-vulkan-drivers>=$mesa_min}); run this script as root"
  . /etc/os-release
  [ "${VERSION_CODENAME:-}" = bookworm ] || say "warning: written for Debian 12 (bookworm), this is ${PRETTY_NAME:-unknown}"
  export DEBIAN_FRONTEND=noninteractive
  if ! mesa_ok && ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    say "adding the bookworm-backports suite (Mesa with lavapipe ray tracing)"
    printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      > /etc/apt/sources.list.d/proceduray-backports.sources
  fi
  say "apt-get update"
  apt-get update -qq
  if [ ${#missing[@]} -gt 0 ]; then
    say "installing: ${missing[*]}"
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
  if ! mesa_ok; then
    say "installing mesa-vulkan-drivers from bookworm-backports"
    # Only Mesa and what it needs come from backports: apt's default pin keeps everything else on bookworm.
    apt-get install -y -qq --no-install-recommends -t bookworm-backports mesa-vulkan-drivers >/dev/null
  fi
fi

mesa_ok || die "mesa-vulkan-drivers $(mesa_version) is older than $mesa_min: lavapipe has no ray tracing. Add bookworm-backports and run: apt-get install -t bookworm-backports mesa-vulkan-drivers"

# A device must offer both extensions; vulkaninfo lists them per device.
info=$(vulkaninfo 2>/dev/null || true)
for ext in VK_KHR_ray_tracing_pipeline VK_KHR_acceleration_structure VK_KHR_buffer_device_address; do
  grep -q "$ext" <<<"$info" || die "no Vulkan device offers $ext. On a machine without a GPU install Mesa >= $mesa_min (apt-get install -t bookworm-backports mesa-vulkan-drivers); on an NVIDIA GPU install the proprietary driver >= 470."
done
say "ok: $(grep -m1 -E 'deviceName' <<<"$info" | sed 's/.*= //') offers ray tracing"
