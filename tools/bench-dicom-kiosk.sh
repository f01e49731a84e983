#!/usr/bin/env bash
# The kiosk receiving while it segments (docs/dicom-network.md, "Figures"): SERIES x IMAGES
# images, synthesised from a real series (each series new study and series UIDs, each image a
# new SOP instance UID, instance number and position, by dcmodify; nothing is kept), pushed at
# once by SERIES parallel storescu processes into the kiosk's own Storage SCP while the kiosk
# runs offscreen on the built-in sample, evolving. Prints the receive MB/s (first push to the
# last storescu's end) and the kiosk's frame p50/p90 during the receive (its --stats), then the
# same session for as long without a sender, for the comparison in one run.
# With SILENT=N and HALF=M in the environment, N connections that say nothing and M that send
# half an A-ASSOCIATE-RQ and stop are held open against the kiosk's port for the whole push
# (each one the node closes is opened again at once, as a port scanner or a broken client
# would), so that the figures are those of a node under that load (issue 48).
#   [SILENT=N HALF=M] tools/bench-dicom-kiosk.sh [SOURCE_SERIES_DIR] [SERIES] [IMAGES] [BINARY]
set -euo pipefail
source_dir=${1:-../shared/data/lung-ct-ibsi/dicom/image}
series=${2:-10}
images=${3:-200}
binary=$(realpath "${4:-build/default/steerseg}")
silent=${SILENT:-0}
half=${HALF:-0}
work=$(mktemp -d)
kiosk=""
idle=""
cleanup() {
  if [[ -n "$idle" ]]; then kill -TERM "$idle" 2>/dev/null || true; wait "$idle" || true; fi
  if [[ -n "$kiosk" ]]; then kill -TERM "$kiosk" 2>/dev/null || true; wait "$kiosk" || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

# The images: source file i % n as image i, at 1 mm steps down from the first's position.
mapfile -t sources < <(find "$source_dir" -maxdepth 1 -type f | sort)
read -r x y z < <(dcmdump +P 0020,0032 "${sources[0]}" | sed 's/.*\[\(.*\)\].*/\1/; s/\\/ /g')
uid() { python3 -c 'import uuid; print("2.25." + str(uuid.uuid4().int))'; }
for ((s = 0; s < series; s++)); do
  mkdir -p "$work/in/$s"
  study=$(uid) serie=$(uid)
  for ((i = 0; i < images; i++)); do
    f="$work/in/$s/$(printf '%04d' "$i").dcm"
    cp "${sources[i % ${#sources[@]}]}" "$f"
    printf '%s\0' -nb -q -gin -m "(0020,000d)=$study" -m "(0020,000e)=$serie" \
      -m "(0020,0013)=$((i + 1))" -m "(0020,0032)=$x\\$y\\$((${z%.*} - i))" "$f" \
      > "$work/args-$s-$i"
  done
done
chmod -R u+w "$work/in"
find "$work" -maxdepth 1 -name 'args-*' -print0 | xargs -0 -P "$(nproc)" -I{} sh -c 'xargs -0 dcmodify < "$1"' _ {}
bytes=$(du -sb "$work/in" | cut -f1)
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')

cat > "$work/kiosk.toml" <<TOML
[audit]
path = "$work/audit.jsonl"
[autosave]
folder = "$work/autosave"
[dicom]
enabled = true
port = $port
store = "$work/store"
outbox = "$work/outbox"
min_free_mb = 0
max_associations = $series
[[dicom.peers]]
name = "scanner"
aet = "BENCH"
host = "127.0.0.1"
receive = true
TOML
# The built-in sample evolving (bench/kiosk/untouched.session's start) until WAIT holds.
session() {
  printf '%s\n' "load builtin:sample" "wait loaded timeout 60" "set T 420" "set eps 150" \
    "set alpha 0.3" "seed 64 84 48 3" "run" "wait state evolving timeout 30" "$1" "quit"
}
session "wait until received >= $series timeout 900" > "$work/receive.session"
run_kiosk() { # NAME SESSION
  (cd "$work" && "$binary" kiosk --allow-root --platform offscreen --size 800x480 --no-resume \
    --config "$work/kiosk.toml" --script "$2" --stats "$work/stats-$1.json") > "$work/kiosk-$1.log" 2>&1 &
  kiosk=$!
}
report() { # NAME
  python3 - "$work/stats-$1.json" "$1" <<'PY'
import json, sys
st = json.load(open(sys.argv[1]))
for kind in ("frames_evolving", "frames_idle"):
    f = st[kind]
    if f["count"]:
        print(f"{sys.argv[2]}: {kind}: {f['count']} frames, p50 {f['p50_ms']:.1f} ms, p90 {f['p90_ms']:.1f} ms")
PY
}

# SILENT + HALF connections held open against PORT until killed; READY once they are.
hold_idle() { # PORT READY
  python3 - "$1" "$silent" "$half" "$2" <<'PY'
import select, socket, sys, time
port, silent, half, ready = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
def item(kind, body, n=2):
    return bytes([kind, 0]) + len(body).to_bytes(n, "big") + body
ae = lambda a: a.ljust(16).encode()
context = b"\x01\0\0\0" + item(0x30, b"1.2.840.10008.1.1") + item(0x40, b"1.2.840.10008.1.2")
variable = (item(0x10, b"1.2.840.10008.3.1.1.1") + item(0x20, context)
            + item(0x50, item(0x51, b"\0\0\x40\0")))
request = item(0x01, b"\0\x01\0\0" + ae("STEERSEG") + ae("BENCH") + b"\0" * 32 + variable, 4)
def connect(halfway):
    while True:
        try:
            s = socket.create_connection(("127.0.0.1", port))
            if halfway:
                s.send(request[: len(request) // 2])
            return s
        except OSError:  # the kernel's backlog full, the connection reset at once: again
            time.sleep(0.01)
held = {connect(i >= silent): i >= silent for i in range(silent + half)}
open(ready, "w").close()
while True:
    readable, _, _ = select.select(list(held), [], [], 0.2)
    for s in readable:  # closed by the node (its negotiation timeout, or pushed out): again
        halfway = held.pop(s)
        s.close()
        held[connect(halfway)] = halfway
PY
}

run_kiosk receiving "$work/receive.session"
for _ in $(seq 300); do grep -q "listening as" "$work/kiosk-receiving.log" && break; sleep 0.1; done
sleep 5 # the sample loaded and evolving
if ((silent + half > 0)); then
  hold_idle "$port" "$work/idle.ready" &
  idle=$!
  for _ in $(seq 100); do [[ -e "$work/idle.ready" ]] && break; sleep 0.1; done
fi
start=$(date +%s.%N)
pids=()
for ((s = 0; s < series; s++)); do
  storescu -aet BENCH -aec STEERSEG --timeout 600 +sd 127.0.0.1 "$port" "$work/in/$s" > "$work/push-$s.log" 2>&1 &
  pids+=($!)
done
failed=0
for p in "${pids[@]}"; do wait "$p" || failed=$((failed + 1)); done
end=$(date +%s.%N)
if ((failed > 0)); then # the kiosk would wait for a series that is not coming
  echo "$failed storescu failed:" >&2
  tail -n 3 "$work"/push-*.log >&2
  exit 1
fi
if [[ -n "$idle" ]]; then kill -TERM "$idle"; wait "$idle" || true; idle=""; fi
wait "$kiosk" || { tail -n 20 "$work/kiosk-receiving.log" >&2; exit 1; }
kiosk=""
stored=$(find "$work/store" -type f -name '*.dcm' | wc -l)
incomplete=$(find "$work/store" -type f -name '.receiving-*' | wc -l) # series left unfinished
python3 -c "
import sys
start, end, size = $start, $end, $bytes
print(f'receive: $series series x $images images pushed at once into the kiosk ($silent silent and $half half-spoken connections held open): $stored/$((series * images)) stored, $incomplete series incomplete, $failed storescu failed, {size / 1e6:.1f} MB in {end - start:.2f} s = {size / 1e6 / (end - start):.2f} MB/s')
"
report receiving
seconds=$(python3 -c "print(round($end - $start))")
session "wait seconds $seconds" > "$work/quiet.session"
run_kiosk quiet "$work/quiet.session"
wait "$kiosk" || { tail -n 20 "$work/kiosk-quiet.log" >&2; exit 1; }
kiosk=""
report quiet
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, $(date -u +%F)"
