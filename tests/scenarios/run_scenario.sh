#!/usr/bin/env bash
# One scripted operator session through the whole kiosk, offscreen (a CTest test; see
# tests/scenarios/CMakeLists.txt and docs/scripts.md).
#   run_scenario.sh STEERSEG SESSION OUTDIR [WxH]
# A session that reads $DATA needs the real scans: without them it is skipped (exit 77, CTest's
# skip code) saying which are missing, or fails under STEERSEG_REQUIRE_DATA=1 (CI).
set -euo pipefail
bin=$1
session=$2
out=$3
size=${4:-800x500}

missing=()
while read -r ref; do
  path="${STEERSEG_DATA_DIR:-}/${ref#\$DATA/}"
  [[ -n "${STEERSEG_DATA_DIR:-}" && -e "$path" ]] || missing+=("$path")
done < <(grep -o '\$DATA/[^ ]*' "$session" | sort -u)
if ((${#missing[@]} > 0)); then
  if [[ "${STEERSEG_REQUIRE_DATA:-}" == "1" ]]; then
    echo "FAILED: $(basename "$session") needs real scans that are missing: ${missing[*]}" >&2
    exit 1
  fi
  echo "skipped: $(basename "$session") needs real scans (STEERSEG_DATA_DIR): ${missing[*]}"
  exit 77
fi

rm -rf "$out"
mkdir -p "$out"
# The session's own audit log, export and autosave folders, so runs do not mix. Nobody watches a replay:
# the solver may take most of each frame (an operator's console keeps half for the views).
cat >"$out/kiosk.toml" <<TOML
[frame]
solver_share = 0.9
[audit]
path = "$out/audit.jsonl"
[export]
folder = "$out/export"
[autosave]
folder = "$out/autosave"
TOML
"$bin" kiosk --platform offscreen --script "$session" --frames "$out" --size "$size" \
  --config "$out/kiosk.toml" --allow-root
# Every session leaves its trail: each action and transition on its own JSON line.
if ! grep -q '"event":"transition"' "$out/audit.jsonl"; then
  echo "FAILED: $out/audit.jsonl records no state transition" >&2
  exit 1
fi
