#!/usr/bin/env bash
# Receive throughput of `steerseg listen` (docs/dicom-network.md): COPIES copies of a DICOM
# series, each given new study, series and instance UIDs (dcmodify), pushed at once by COPIES
# parallel storescu processes. Prints the objects stored, MB and MB/s (wall time from the first
# push to the last storescu's end). The node serves up to [dicom] max_associations (default 4)
# associations at once. The same pushes then go to DCMTK's own storescp (which writes without
# fsync), for the ratio in one run. The kiosk receiving while it segments:
# tools/bench-dicom-kiosk.sh.
#   tools/bench-dicom-receive.sh [SERIES_DIR] [COPIES] [BINARY]
set -euo pipefail
series=${1:-../shared/data/lung-ct-ibsi/dicom/image}
copies=${2:-4}
binary=${3:-build/default/steerseg}
work=$(mktemp -d)
listener=""
cleanup() {
  if [[ -n "$listener" ]]; then kill -TERM "$listener" 2>/dev/null || true; wait "$listener" || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

for ((c = 0; c < copies; c++)); do
  mkdir -p "$work/in/$c"
  cp "$series"/* "$work/in/$c/"
  chmod u+w "$work/in/$c"/*
  dcmodify -q -nb -gst -gse -gin "$work/in/$c"/* 
done
bytes=$(du -sb "$work/in" | cut -f1)
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
push() { # NAME: every copy at once into the listener on $port, then the figures
  local start end failed=0 pids=() stored sent
  start=$(date +%s.%N)
  for ((c = 0; c < copies; c++)); do
    storescu -aet BENCH -aec STEERSEG --timeout 600 +sd 127.0.0.1 "$port" "$work/in/$c" > "$work/push-$c.log" 2>&1 &
    pids+=($!)
  done
  for p in "${pids[@]}"; do wait "$p" || failed=$((failed + 1)); done
  end=$(date +%s.%N)
  stored=$(find "$work/store-$1" -type f | wc -l)
  sent=$(find "$work/in" -type f | wc -l)
  python3 - "$1" "$start" "$end" "$bytes" "$stored" "$sent" "$failed" "$copies" <<'PY'
import sys
name = sys.argv[1]
start, end, size = float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
stored, sent, failed, copies = map(int, sys.argv[5:9])
wall = end - start
print(f"{name}: {copies} series pushed at once: {stored}/{sent} objects stored, {failed} storescu "
      f"failed, {size / 1e6:.1f} MB in {wall:.2f} s = {size / 1e6 / wall:.2f} MB/s")
PY
}
wait_for() { for _ in $(seq 100); do grep -q "$1" "$2" && return; sleep 0.1; done; }

"$binary" listen --port "$port" --store "$work/store-steerseg" --allow BENCH > "$work/listen.log" &
listener=$!
wait_for listening "$work/listen.log"
push steerseg
kill -TERM "$listener"; wait "$listener" || true

mkdir -p "$work/store-storescp"
storescp -aet STEERSEG -od "$work/store-storescp" -uf "$port" > "$work/storescp.log" 2>&1 &
listener=$!
sleep 1
push storescp
