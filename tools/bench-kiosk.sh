#!/usr/bin/env bash
# The frame loop's figures: the whole kiosk, offscreen, replaying bench/kiosk/evolve.session (the
# solver growing a front on the built-in sample for 10 s while drags on the 3D view and arrow
# keys arrive at 20 events a second, then 5 s paused with the same input) at 1280x800 and
# 1920x1080. Per size: frame time percentiles while evolving and otherwise, input-to-screen
# latency percentiles, solver iterations per second evolving, pixels per second drawn.
# Writes bench-kiosk.md (the table) and bench-kiosk.json (the same figures and the kiosk's
# --stats files) to the output folder.
# Besides (not with --small), at the first size, ratios measured in the same run:
# - untouched: the kiosk's iterations per second evolving with nobody touching anything
#   (bench/kiosk/untouched.session, 10 s) over `steerseg segment`'s on the same scan, parameters
#   and iteration count;
# - still: the wait of a full-screen `frame` once still (bench/kiosk/still.session, the view
#   turned and the frame asked for at once) over render_frame_bench drawing the same views
#   (the 3D view with its surface and the two slices, at the kiosk's sizes) whole.
#
# - with --scan: the same untouched ratio on SCAN from a seed at voxel I,J,K (T and eps from
#   `segment --probe` there, alpha 0.5), and the input-to-screen latency while the solver runs
#   on it (evolve.session's input, after that set-up). ../shared/data has no 512x512x120-class
#   scan: bench/kiosk/resample_nifti.py makes one from a real MR (--large does, into DIR).
#
#   tools/bench-kiosk.sh [--small] [--sizes WxH[,WxH...]] [--out DIR] [--bin STEERSEG]
#                        [--scan SCAN --seed I,J,K [--scan-only] | --large]
#
# --scan-only: the scan's figures alone (at the first size), not the built-in sample's: a run
# over many scans spends its time on them.
# --small: 800x500 and a 3 s + 2 s session (CI runs it through tools/bench-gpu.sh --small).
# Without --bin it builds build/release/steerseg (Release) if it is missing. Latency runs from
# the poll that brought an event to the end of the present of the frame that drew its effect
# (app/kiosk/kiosk_app.cpp); frames count from the first one showing the scan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

small=0
sizes=""
out=${STEERSEG_OUT:-out/bench-kiosk}
bin=""
scan=""
scan_seed=""
large=0
scan_only=0
while (($#)); do
  case $1 in
    --small) small=1 ;;
    --sizes) sizes=${2:?--sizes needs WxH[,WxH...]}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    --bin) bin=${2:?--bin needs the steerseg binary}; shift ;;
    --scan) scan=${2:?--scan needs a scan}; shift ;;
    --seed) scan_seed=${2:?--seed needs I,J,K}; shift ;;
    --large) large=1 ;;
    --scan-only) scan_only=1 ;;
    -h|--help) sed -n '2,/^set -euo/{/^set -euo/d;p}' "$0"; exit 0 ;;
    *) echo "bench-kiosk: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

if ((small)); then
  session=$root/bench/kiosk/evolve_short.session
  sizes=${sizes:-800x500}
else
  session=$root/bench/kiosk/evolve.session
  sizes=${sizes:-1280x800,1920x1080}
fi
if ((large)); then
  # The thigh sarcoma's T1 MR (174x158x59 at 0.98 x 0.98 x 3.27 mm) on a 512x512x120 grid
  # (0.33 x 0.30 x 1.59 mm), its tumour's deepest voxel (the clicks protocol's first click,
  # docs/steering.md) carried over.
  data=${STEERSEG_DATA_DIR:-$root/../shared/data}
  mr=$data/thigh-sarcoma-sts001/STS_001_MR_T1_image.nii.gz
  if [[ ! -f $mr ]]; then
    echo "bench-kiosk: --large needs $mr (set STEERSEG_DATA_DIR)" >&2
    exit 2
  fi
  scan=${TMPDIR:-/tmp}/bench-kiosk-mr512.nii.gz
  [[ -f $scan ]] || /usr/bin/python3 "$root/bench/kiosk/resample_nifti.py" "$mr" "$scan" 512 512 120 >&2
  scan_seed=210,257,53
fi
if [[ -n $scan && ! $scan_seed =~ ^[0-9]+,[0-9]+,[0-9]+$ ]]; then
  echo "bench-kiosk: --scan needs --seed I,J,K (voxel indices)" >&2
  exit 2
fi
if ((scan_only)) && [[ -z $scan ]]; then
  echo "bench-kiosk: --scan-only goes with --scan SCAN --seed I,J,K (or --large)" >&2
  exit 2
fi
IFS=',' read -r -a size_list <<<"$sizes"
for s in "${size_list[@]}"; do
  if [[ ! $s =~ ^[1-9][0-9]{1,4}x[1-9][0-9]{1,4}$ ]]; then
    echo "bench-kiosk: '$s' is not a size WxH" >&2
    exit 2
  fi
done

if [[ -z $bin ]]; then
  bin=$root/build/release/steerseg
  if [[ ! -x $bin ]]; then
    "$root/tools/install-deps.sh"
    (cd "$root" && cmake --preset release >/dev/null &&
      cmake --build --preset release -j "$(nproc)" --target steerseg >&2)
  fi
fi
if [[ ! -x $bin ]]; then
  echo "bench-kiosk: $bin is not an executable steerseg" >&2
  exit 2
fi
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
mkdir -p "$out"
out=$(cd "$out" && pwd)
log=$out/bench-kiosk.log
: >"$log"

"$bin" gpu-info >"$out/gpu-info.json" 2>>"$log"
renderer=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("renderer", ""))' \
  "$out/gpu-info.json")
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
started=$(date +%s)
# One run of the whole kiosk, offscreen: run_kiosk NAME SESSION SIZE [KIOSK ARGS...] writes
# stats-NAME.json and frames-NAME/ to the output folder. The kiosk runs as root in containers
# and CI; the session ends it (a wait has a timeout). From the output folder: the kiosk's audit
# log (steerseg-export/) goes there, not into the checkout.
run_kiosk() {
  local name=$1 script=$2 size=$3
  shift 3
  echo "bench-kiosk: $size: $bin kiosk $* --script ${script#"$root"/}" | tee -a "$log" >&2
  rm -f "$out/stats-$name.json"
  if ! (cd "$out" && "$bin" kiosk --platform offscreen "$@" --script "$script" \
    --frames "$out/frames-$name" --size "$size" --stats "$out/stats-$name.json" --allow-root \
    >>"$log" 2>&1); then
    tail -n 20 "$log" >&2
    echo "bench-kiosk: the kiosk failed on ${script##*/} at $size (log: $log)" >&2
    exit 1
  fi
}

if ((!scan_only)); then
  for s in "${size_list[@]}"; do
    run_kiosk "$s" "$session" "$s"
  done
fi

# The ratios (see the top): the kiosk and its parts on the same scan, in this run.
ratios=""
if ((!small && !scan_only)); then
  s=${size_list[0]}
  for name in untouched still; do
    run_kiosk "$name" "$root/bench/kiosk/$name.session" "$s"
  done
  n=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["iterations"])' "$out/stats-untouched.json")
  echo "bench-kiosk: $bin segment, $n iterations" | tee -a "$log" >&2
  "$bin" segment --input builtin:sample --seed 64,84,48,3 --T 420 --eps 150 --alpha 0.3 \
    --iterations "$n" --output "$out/segment-untouched.nii.gz" --report "$out/segment-untouched.json" >>"$log" 2>&1
  frame_bench=$(dirname "$bin")/bench/render_frame_bench
  if [[ ! -x $frame_bench && -x $(dirname "$bin")/render_frame_bench ]]; then
    frame_bench=$(dirname "$bin")/render_frame_bench # the GPU pack keeps it beside steerseg
  elif [[ ! -x $frame_bench ]]; then
    (cd "$root" && cmake --build --preset release --target render_frame_bench >&2)
  fi
  read -r w3 h3 ws hs < <(python3 -c 'import json,sys; v=json.load(open(sys.argv[1]))["view_sizes"]; print(*v[0], *v[1])' \
    "$out/stats-still.json")
  "$frame_bench" --frames 2 --size "${w3}x${h3}" --view 3d+surface >"$out/frame-bench-3d.txt" 2>>"$log"
  "$frame_bench" --frames 2 --size "${ws}x${hs}" --view axial+contour >"$out/frame-bench-slice.txt" 2>>"$log"
  ratios="$out/stats-untouched.json $out/segment-untouched.json $out/stats-still.json $out/frame-bench-3d.txt $out/frame-bench-slice.txt"
fi

# The same on the given scan: T and eps probed where the seed goes, then the untouched run, the
# segment run of as many iterations, and evolve.session's input after the same set-up.
scan_files=""
if [[ -n $scan ]] && ((!small)); then
  s=${size_list[0]}
  IFS=',' read -r si sj sk <<<"$scan_seed"
  "$bin" segment --input "$scan" --probe "$si,$sj,$sk,5" --seed "$si,$sj,$sk,3" --alpha 0.5 \
    --iterations 1 --output "$out/scan-probe.nii.gz" --report "$out/scan-probe.json" >>"$log" 2>&1
  read -r scan_t scan_eps < <(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["T"], r["eps"])' \
    "$out/scan-probe.json")
  python3 - "$root/bench/kiosk/evolve.session" "$out" "$si $sj $sk" "$scan_t" "$scan_eps" <<'EOF'
import pathlib, sys
evolve, out, seed, t, eps = pathlib.Path(sys.argv[1]).read_text().splitlines(), pathlib.Path(sys.argv[2]), *sys.argv[3:]
setup = ["load $SCAN", "wait loaded timeout 600", "expect state inspect", f"set T {t}", f"set eps {eps}",
         "set alpha 0.5", f"seed {seed} 3", "run", "wait state evolving timeout 120"]
start = evolve.index("wait state evolving timeout 30") + 1
(out / "scan-evolve.session").write_text("\n".join(setup + evolve[start:]) + "\n")
(out / "scan-untouched.session").write_text("\n".join(
    setup + ["wait seconds 10", "pause", "wait state paused timeout 60", "quit"]) + "\n")
EOF
  for name in scan-untouched scan-evolve; do
    run_kiosk "$name" "$out/$name.session" "$s" --scan "$scan"
  done
  n=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["iterations"])' "$out/stats-scan-untouched.json")
  echo "bench-kiosk: $bin segment --input $scan, $n iterations" | tee -a "$log" >&2
  "$bin" segment --input "$scan" --seed "$si,$sj,$sk,3" --T "$scan_t" --eps "$scan_eps" --alpha 0.5 \
    --iterations "$n" --output "$out/segment-scan.nii.gz" --report "$out/segment-scan.json" >>"$log" 2>&1
  scan_files="$out/stats-scan-untouched.json $out/segment-scan.json $out/stats-scan-evolve.json"
fi
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

planned=$( ((small)) && echo 3 || echo 10)
python3 - "$out" "$renderer" "$small" "$planned" "$(($(date +%s) - started))" "$load_before" "$load_after" \
  "$ratios" "$scan" "$scan_files" "$scan_only" "${size_list[@]}" <<'EOF'
import json, pathlib, sys
out, renderer, small, planned = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3] == "1", float(sys.argv[4])
seconds, load_before, load_after, ratio_files = int(sys.argv[5]), sys.argv[6], sys.argv[7], sys.argv[8].split()
scan, scan_files, scan_only, sizes = sys.argv[9], sys.argv[10].split(), sys.argv[11] == "1", sys.argv[12:]
software = any(s in renderer for s in ("llvmpipe", "softpipe", "SwiftShader")) or not renderer
rows = []
for size in [] if scan_only else sizes:
    st = json.loads((out / f"stats-{size}.json").read_text())
    ev, idle, lat = st["frames_evolving"], st["frames_idle"], st["latency"]
    if ev["count"] == 0 or idle["count"] == 0 or lat["count"] == 0:
        sys.exit(f"bench-kiosk: {size}: no frames evolving, idle or with input: the session did not run as meant")
    frames = ev["total_s"] + idle["total_s"]
    if ev["total_s"] < 0.8 * planned:
        # A machine fast enough to converge the front early: fewer evolving frames, still true ones.
        print(f"bench-kiosk: {size}: the front converged after {ev['total_s']:.1f} s of the "
              f"{planned:g} s meant: the evolving figures cover those", file=sys.stderr)
    rows.append({"size": size, "renderer": renderer, "display": st["display"],
                 "evolving_seconds": round(ev["total_s"], 2),
                 "frames_evolving": {k: round(ev[k], 1) for k in ("p50_ms", "p90_ms", "p99_ms", "max_ms")} | {"count": ev["count"]},
                 "frames_idle": {k: round(idle[k], 1) for k in ("p50_ms", "p90_ms", "p99_ms", "max_ms")} | {"count": idle["count"]},
                 "latency": {k: round(lat[k], 1) for k in ("p50_ms", "p90_ms", "p99_ms", "max_ms")} | {"count": lat["count"]},
                 "iterations": st["iterations"],
                 "iterations_per_second": round(st["iterations_per_second"], 1),
                 "megapixels_per_second": round(st["pixels_per_second"] / 1e6, 2),
                 # Where the frames' time went: the solver, the views' draws, the rest (panel,
                 # compositing, present, the script).
                 "share_solver": round(st["solver_seconds"] / frames, 3) if frames else None,
                 "share_draw": round(st["draw_seconds"] / frames, 3) if frames else None})
ratios = None
if ratio_files:
    untouched, segment, still = (json.loads(pathlib.Path(f).read_text()) for f in ratio_files[:3])

    def bench_ms(path, case):
        # render_frame_bench's row: "CASE WxH MEDIAN_MS CPU_MS ...".
        for line in pathlib.Path(path).read_text().splitlines():
            f = line.split()
            if len(f) > 2 and f[0] == case:
                return float(f[2])
        sys.exit(f"bench-kiosk: no {case} frame time in {path}")

    whole = (bench_ms(ratio_files[3], "3d+surface") + 2 * bench_ms(ratio_files[4], "axial+contour")) / 1e3
    waits = still["frame_waits_s"]
    if not waits:
        sys.exit("bench-kiosk: still.session wrote no frame")
    ratios = {"kiosk_iterations_per_second_untouched": round(untouched["iterations_per_second"], 1),
              "segment_iterations_per_second": round(segment["iterations_per_second"], 1),
              "untouched_over_segment": round(untouched["iterations_per_second"] / segment["iterations_per_second"], 2),
              "still_frame_seconds": round(waits[-1], 2), "render_frame_bench_seconds": round(whole, 2),
              "still_frame_over_bench": round(waits[-1] / whole, 2), "view_sizes": still["view_sizes"]}
on_scan = None
if scan_files:
    untouched, segment, evolve = (json.loads(pathlib.Path(f).read_text()) for f in scan_files)
    lat = evolve["latency"]
    if lat["count"] == 0 or evolve["frames_evolving"]["count"] == 0:
        sys.exit("bench-kiosk: scan-evolve.session had no input while evolving: the session did not run as meant")
    on_scan = {"scan": scan, "kiosk_iterations_per_second_untouched": round(untouched["iterations_per_second"], 2),
               "segment_iterations_per_second": round(segment["iterations_per_second"], 2),
               "untouched_over_segment": round(untouched["iterations_per_second"] / segment["iterations_per_second"], 2),
               "latency": {k: round(lat[k], 1) for k in ("p50_ms", "p90_ms", "p99_ms", "max_ms")} | {"count": lat["count"]},
               "frames_evolving": {k: round(evolve["frames_evolving"][k], 1) for k in ("p50_ms", "p90_ms", "p99_ms")},
               "iterations_per_second_with_input": round(evolve["iterations_per_second"], 2)}
report = {"renderer": renderer, "software_renderer": software, "small": small, "seconds": seconds,
          "load_before": load_before, "load_after": load_after, "sizes": rows, "ratios": ratios,
          "on_scan": on_scan}
(out / "bench-kiosk.json").write_text(json.dumps(report, indent=2) + "\n")

def pct(p):
    return f"{p['p50_ms']:g} / {p['p90_ms']:g} / {p['p99_ms']:g}"
md = ["## The kiosk's frame loop", "",
      f"Renderer {renderer or 'unknown'}; {'short session (--small); ' if small else ''}{seconds} s in all; "
      f"load average {load_before} before, {load_after} after."]
if rows:
    md += ["", "| size | renderer | frame ms evolving p50 / p90 / p99 | frame ms idle p50 / p90 / p99 | input to screen ms p50 / p90 / p99 | iterations/s evolving | Mpixels/s drawn | time: solver / draw |",
           "|---|---|---|---|---|---|---|---|"]
for r in rows:
    md.append(f"| {r['size']} | {r['renderer']} | {pct(r['frames_evolving'])} | {pct(r['frames_idle'])} | "
              f"{pct(r['latency'])} | {r['iterations_per_second']:g} | {r['megapixels_per_second']:g} | "
              f"{r['share_solver']:.0%} / {r['share_draw']:.0%} |")
if ratios:
    md += ["", "| ratio (same run, " + sizes[0] + ") | kiosk | its part | ratio |", "|---|---|---|---|",
           f"| iterations/s untouched / `steerseg segment` (sample, same parameters and count) | "
           f"{ratios['kiosk_iterations_per_second_untouched']:g} | {ratios['segment_iterations_per_second']:g} | "
           f"{ratios['untouched_over_segment']:g} |",
           f"| full-screen `frame` once still, s / render_frame_bench, same views whole | "
           f"{ratios['still_frame_seconds']:g} | {ratios['render_frame_bench_seconds']:g} | "
           f"{ratios['still_frame_over_bench']:g} |"]
if on_scan:
    md += ["", f"| on {pathlib.Path(scan).name} ({sizes[0]}) | kiosk | its part | ratio |", "|---|---|---|---|",
           f"| iterations/s untouched / `steerseg segment` (same parameters and count) | "
           f"{on_scan['kiosk_iterations_per_second_untouched']:g} | {on_scan['segment_iterations_per_second']:g} | "
           f"{on_scan['untouched_over_segment']:g} |",
           f"| input to screen ms p50 / p90 / p99 while the solver runs (frame ms evolving p50 / p90 / p99; "
           f"it/s with input) | {pct(on_scan['latency'])} | {pct(on_scan['frames_evolving'])}; "
           f"{on_scan['iterations_per_second_with_input']:g} it/s | |"]
(out / "bench-kiosk.md").write_text("\n".join(md) + "\n")
EOF
cat "$out/bench-kiosk.md"
echo "bench-kiosk: $out/bench-kiosk.md and $out/bench-kiosk.json"
