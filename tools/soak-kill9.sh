#!/usr/bin/env bash
# The kill -9 soak's long form (issue 25; the README's performance table): cycles of start,
# random scripted work on the built-in sample, SIGKILL at a random moment and resume, each
# checked (tests/kiosk/kill9_soak.py says what). CI runs 5 cycles as CTest kiosk_kill9_soak.
#
#   tools/soak-kill9.sh [--cycles N] [--seed S] [--bin STEERSEG] [--out DIR]
#
# Writes soak-kill9.json (cycles, resumes, masks compared, files checked, seconds of work lost
# per kill: median and max) to the output folder and prints it. Offscreen: llvmpipe will do.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cycles=200
seed=25
bin="$root/build/default/steerseg"
out=${STEERSEG_OUT:-out/soak-kill9}
while [ $# -gt 0 ]; do
  case "$1" in
    --cycles) cycles=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "soak-kill9.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
if [ ! -x "$bin" ]; then
  echo "soak-kill9.sh: $bin is not built (cmake --build build/default --target steerseg)" >&2
  exit 2
fi
mkdir -p "$out"
python3 "$root/tests/kiosk/kill9_soak.py" "$bin" "$out/work" --cycles "$cycles" --seed "$seed" \
  --figures "$out/soak-kill9.json"
