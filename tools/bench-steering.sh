#!/usr/bin/env bash
# The steering benchmark (docs/steering.md): the clicks protocol on every labelled case of
# ../shared/data, the product through the kiosk's workflow against the random walker and paint
# only, with the table (steering.md) and the plot (steering.png) in the output folder. Or one
# case of any scan:
#
#   tools/bench-steering.sh [--out DIR] [run_steering.py options: --only NAMES --clicks N --box ...]
#   tools/bench-steering.sh --input SCAN --reference LABEL [--reference-label N] [--clicks N]
#                           [--box] [--paint-only] --report R.json
#
# --box: the interactive challenge's protocol, each case started from its label's bounding box
# (no click), then the corrections where the challenge's evaluation clicks (the error's centre
# in voxel steps); without it the first prompt is a click and the centres are in mm.
#
# Builds build/release's steering_bench (Release) if it is missing; STEERSEG_STEERING_BENCH
# names another one instead (build/default's, RelWithDebInfo). Scans come from
# STEERSEG_DATA_DIR (default ../shared/data). After each case the random walker replays the
# level set's prompts (bench/steering/random_walker_peer.py; --no-peer skips it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${STEERSEG_STEERING_BENCH:-$root/build/release/bench/steering_bench}
if [[ ! -x $bench ]]; then
  "$root/tools/install-deps.sh" >&2
  (cd "$root" && cmake --preset release -DSTEERSEG_BUILD_BENCH=ON >/dev/null &&
    cmake --build --preset release -j "$(nproc)" --target steering_bench >&2)
fi
case ${1:-} in
  -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
  --input) exec "$bench" "$@" ;;
esac
# The plot wants Debian's matplotlib and the random walker Debian's scikit-image and nibabel,
# so Debian's python (a pyenv one would not see them).
py=python3
[[ -x /usr/bin/python3 ]] && py=/usr/bin/python3
sudo_cmd=""; [[ $(id -u) -ne 0 ]] && sudo_cmd=sudo
if ! "$py" -c 'import matplotlib' 2>/dev/null; then
  $sudo_cmd env DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-matplotlib >&2 ||
    echo "bench-steering: no python3-matplotlib: the table without the plot" >&2
fi
if [[ " $* " != *" --no-peer "* ]] && ! "$py" -c 'import skimage, nibabel' 2>/dev/null; then
  # Without them run_steering.py stops and says so (or run with --no-peer).
  $sudo_cmd env DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-skimage \
    python3-nibabel >&2 || echo "bench-steering: no python3-skimage/python3-nibabel" >&2
fi
out=${STEERSEG_OUT:-out/steering}
rest=()
while (($#)); do
  case $1 in
    --out) out=${2:?--out needs a folder}; shift ;;
    *) rest+=("$1") ;;
  esac
  shift
done
exec "$py" "$root/bench/steering/run_steering.py" --bench "$bench" --out "$out" \
  --data "${STEERSEG_DATA_DIR:-$root/../shared/data}" "${rest[@]}"
