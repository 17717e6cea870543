#!/usr/bin/env bash
# Installs every Debian 12 package TunnelMap needs to build, test, benchmark and package.
# Idempotent: skips apt entirely when everything is already present.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  qtbase5-dev libqt5opengl5-dev
  libvtk9-dev libvtk9-qt-dev
  libpcl-dev libeigen3-dev libqhull-dev libceres-dev
  libopencv-dev libopencv-contrib-dev libpng-dev libjpeg62-turbo-dev
  libopenni2-dev openni2-utils
  libosmesa6-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libtbb-dev libopenvdb-dev
  libsqlite3-dev libzstd-dev liblz4-dev libbz2-dev
  librosbag-storage-dev pluginlib-dev librcpputils-dev librcutils-dev libament-index-cpp-dev libtinyxml2-dev
  xvfb xauth
  dpkg-dev file help2man poppler-utils
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
