#!/usr/bin/env bash
# The accuracy table (docs/speed.md "Accuracy"): Dice against the expert or reference label for
# each speed (threshold, edge, classify) on every labelled case of bench/accuracy/cases.toml,
# each run to the solver's own stop. Writes accuracy.md and accuracy.json to the output folder.
#
#   tools/bench-accuracy.sh [--out DIR] [--bin STEERSEG] [--bounds | --bounds-only]
#                           [run_accuracy.py options...]
#
# Options after these go to bench/accuracy/run_accuracy.py (--only CASES, --speeds LIST,
# --max-iterations N). The scans are read from STEERSEG_DATA_DIR (default ../shared/data).
# Without --bin it builds build/release/steerseg (Release) if it is missing. --bounds adds what
# each speed reaches when fitted to the case's own label (bounds.md; bench/accuracy_bound, built
# beside it); --bounds-only runs those alone.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

out=${STEERSEG_OUT:-out/accuracy}
bin=""
bounds=""
rest=()
while (($#)); do
  case $1 in
    --out) out=${2:?--out needs a folder}; shift ;;
    --bin) bin=${2:?--bin needs the steerseg binary}; shift ;;
    --bounds) bounds=with ;;
    --bounds-only) bounds=only ;;
    -h|--help) sed -n '2,13p' "$0"; python3 "$root/bench/accuracy/run_accuracy.py" --help; exit 0 ;;
    *) rest+=("$1") ;;
  esac
  shift
done

# Builds the Release target $1 unless its binary $2 exists.
build_missing() {
  if [[ ! -x $2 ]]; then
    "$root/tools/install-deps.sh" >&2
    (cd "$root" && cmake --preset release >/dev/null &&
      cmake --build --preset release -j "$(nproc)" --target "$1" >&2)
  fi
}

if [[ -z $bin ]]; then
  bin=$root/build/release/steerseg
  [[ $bounds == only ]] || build_missing steerseg "$bin"
fi
if [[ -n $bounds ]]; then
  bound=$root/build/release/bench/accuracy_bound
  build_missing accuracy_bound "$bound"
  rest+=(--bound "$bound")
  [[ $bounds == only ]] && rest+=(--bound-only)
fi
exec python3 "$root/bench/accuracy/run_accuracy.py" --steerseg "$bin" --out "$out" \
  --data "${STEERSEG_DATA_DIR:-$root/../shared/data}" "${rest[@]}"
