#!/usr/bin/env bash
# Builds and runs every test: the default build, the ASan+UBSan build, and each libFuzzer target
# briefly on its seed corpus. Installs what it needs first. Used by the README and .ci/run.
#   tools/test.sh            everything
#   tools/test.sh --quick    the default build's tests only
set -euo pipefail
cd "$(dirname "$0")/.."

tools/install-deps.sh
jobs=$(nproc)

echo "== default build"
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
ctest --preset default -j "$jobs"

if [[ "${1:-}" == "--quick" ]]; then
  exit 0
fi

echo "== ASan + UBSan build"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"

echo "== fuzz targets"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
fuzz_seconds=${STEERSEG_FUZZ_SECONDS:-30}
shopt -s nullglob
ran=0
for target in build/fuzz/tests/fuzz/fuzz_*; do
  [[ -x "$target" ]] || continue
  name=$(basename "$target")
  corpus="tests/fuzz/corpus/${name#fuzz_}"
  work=$(mktemp -d)
  cp -r "$corpus"/. "$work"/ 2>/dev/null || true
  echo "-- $name for ${fuzz_seconds}s on $corpus"
  "$target" -max_total_time="$fuzz_seconds" -rss_limit_mb=2048 -max_len=65536 -print_final_stats=0 \
    "$work" 2>&1 | tail -n 3
  rm -rf "$work"
  ran=$((ran + 1))
done
echo "fuzz: $ran targets ran without a crash"
