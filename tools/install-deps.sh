#!/usr/bin/env bash
# Installs the Debian 12 packages that steerseg's build, tests and benchmarks need.
# Used by both README commands and by .ci/run; nothing is fetched from anywhere but apt.
#   tools/install-deps.sh          build + test dependencies
#   tools/install-deps.sh --bench  also ITK (only the ITK comparison benchmark needs it)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev lld clang-format python3
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libgbm-dev libdrm-dev libsdl2-dev libx11-dev
  xvfb xauth xdotool
  glslang-tools libglm-dev
  libopenimageio-dev libgdcm-dev libnifti2-dev zlib1g-dev
  libgpiod-dev libhidapi-dev libinput-dev libudev-dev libsystemd-dev
  libdcmtk-dev dicom3tools python3-pydicom python3-skimage python3-nibabel
  orthanc dcmtk openssl
  dpkg-dev fakeroot lintian systemd xz-utils
  libtomlplusplus-dev nlohmann-json3-dev libimgui-dev fonts-dejavu-core libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(libinsighttoolkit5-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
