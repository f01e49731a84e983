#!/usr/bin/env bash
# The main job: builds steerseg (release) and runs the kiosk on its built-in sample scan.
#   - Where there is a display ($DISPLAY or $WAYLAND_DISPLAY): the kiosk in a window with the
#     sample loaded, for an operator to probe, seed, steer and export by touch, mouse and keys.
#   - Elsewhere: offscreen, replaying the demo session (tests/scenarios/demo.session): load,
#     probe the lesion, seed, evolve until converged, review, export. The mask, frames of the
#     full screen and the audit log go to ./out/ (override with STEERSEG_OUT).
# STEERSEG_PLATFORM=offscreen|window|kms forces a display backend. Installs what it needs first.
set -euo pipefail
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
bin=build/release/steerseg
out=${STEERSEG_OUT:-out}
mkdir -p "$out"
out=$(cd "$out" && pwd)

platform=${STEERSEG_PLATFORM:-}
if [[ -z "$platform" ]]; then
  if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then platform=window; else platform=offscreen; fi
fi
# The kiosk refuses to run as root (an appliance runs it as its own user); a fresh build
# machine or container is often root.
root=()
if [[ $(id -u) -eq 0 ]]; then root=(--allow-root); fi
cat >"$out/kiosk.toml" <<TOML
[audit]
path = "$out/audit.jsonl"
[export]
folder = "$out"
TOML

"$bin" gpu-info >"$out/gpu-info.json"
echo "GPU: $(grep '"renderer"' "$out/gpu-info.json")"
if [[ "$platform" == "offscreen" ]]; then
  "$bin" kiosk --platform offscreen --config "$out/kiosk.toml" "${root[@]}" \
    --script tests/scenarios/demo.session --frames "$out" --size 1280x800 --stats "$out/frame-stats.json"
  echo "steerseg: the demo session's mask, frames, audit log and frame statistics are in $out/"
  ls -l "$out"
else
  "$bin" kiosk --platform "$platform" --config "$out/kiosk.toml" "${root[@]}" --scan builtin:sample
fi
