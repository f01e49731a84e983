#!/usr/bin/env bash
# The main job: builds steerseg (release) and runs it on its built-in sample scan. Installs what
# it needs first. Output goes to ./out/ (override with STEERSEG_OUT).
set -euo pipefail
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
bin=build/release/steerseg
out=${STEERSEG_OUT:-out}
mkdir -p "$out"

"$bin" gpu-info | tee "$out/gpu-info.json"
"$bin" info builtin:sample | tee "$out/sample-info.json"
