#!/usr/bin/env bash
# The GPU figures in one command: solver iterations/s at 256^3 and 512^3 over a range of active
# fractions, renderer frame times at 1920x1080 with the solver stepping, time to ITK's evolved
# time on the real cases, the README's pictures for comparison with llvmpipe's, and the kiosk's
# frame loop at 1280x800 and 1920x1080 (tools/bench-kiosk.sh), and a full-size CT (a synthetic
# 512x512x1000 int16 DICOM series: load, GPU memory, solver, a frame; docs/large-scans.md).
# Writes bench-gpu.md (the tables) and bench-gpu.json (the same figures) to the output folder.
#
#   tools/bench-gpu.sh [--small] [--skip PART[,PART...]] [--out DIR] [--bin DIR]
#   tools/bench-gpu.sh --pack DIR [--tests] [--no-scans]
#
# PARTs: solver, render, segment, pictures, kiosk, large. --small uses sizes a software rasteriser
# finishes in a minute or two (CI runs it, so the script cannot rot between GPU sessions).
# Without --bin it installs what it needs (apt) and builds the benchmarks in build/bench-gpu.
#
# The lent GPU machine has no package registry: on a development machine, --pack DIR builds the
# light build (STEERSEG_LIGHT: no OpenImageIO, GDCM, DCMTK, SDL2 or libinput; scans from the
# built-in sample and NIfTI, benchmark pictures as PPM) of the benchmarks and of the kiosk
# (steerseg: the same frame loop, offscreen), and puts them, tools/bench-kiosk.sh with its
# sessions, the few libraries they need beyond a base system (found with ldd) and the real
# cases' scans (from STEERSEG_DATA_DIR) in DIR; there, `DIR/bench-gpu.sh --bin DIR` runs them.
# large_scan_bench (GDCM) is not packed: --bin skips that part. It says so when the renderer is
# a software one: those figures are not GPU figures.
#
# --tests packs the GPU tests as well: the light build's GoogleTest programs labelled "gpu"
# (stripped), the files their compiled-in paths name and tools/test-gpu.sh; there,
# `DIR/test-gpu.sh` runs them (its --help; docs/benchmarks-gpu.md). --no-scans leaves the real
# cases' scans out (the segment part and the tests that read them then skip them), 7 MiB less.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

small=0
skip=""
out=${STEERSEG_OUT:-out/bench-gpu}
bin=""
pack=""
tests=0
scans=1
while (($#)); do
  case $1 in
    --small) small=1 ;;
    --skip) skip=${2:?--skip needs a list}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    --bin) bin=${2:?--bin needs a folder}; shift ;;
    --pack) pack=${2:?--pack needs a folder}; shift ;;
    --tests) tests=1 ;;
    --no-scans) scans=0 ;;
    -h|--help) sed -n '2,28p' "$0"; exit 0 ;;
    *) echo "bench-gpu: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
wants() { [[ ",$skip," != *",$1,"* ]]; }
if [[ -z $pack ]] && ((tests || !scans)); then
  echo "bench-gpu: --tests and --no-scans go with --pack (the packed DIR/test-gpu.sh runs the tests)" >&2
  exit 2
fi

data=${STEERSEG_DATA_DIR:-$root/../shared/data}
# The ITK comparison's cases: scan, expert mask, seed, T, eps, alpha and ITK's converged time and
# solve seconds (docs/benchmarks-itk.md: ITK 5 on one core of the 2-core development VM).
cases=(
  "sarcoma|thigh-sarcoma-sts001/STS_001_CT_image.nii.gz|thigh-sarcoma-sts001/STS_001_CT_mask.nii.gz|97,107,28,3|28.5|23.7|0.2|22.89|1.90"
  "lung|lung-ct-ibsi/nifti/image.nii.gz|lung-ct-ibsi/nifti/mask.nii.gz|94,89,29,3|-46.9|231.1|0.2|2.08|57.6"
)

build_benches() { # build-dir light(ON|OFF) [more targets]
  cmake -S "${src_link:-$root}" -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DSTEERSEG_BUILD_TESTS="${with_tests:-OFF}" -DSTEERSEG_LIGHT="$2" >/dev/null
  local io=()
  if [[ $2 == OFF ]]; then
    io=(large_scan_bench) # the DICOM series needs GDCM
  fi
  cmake --build "$1" -j "$(nproc)" --target solver_bench render_frame_bench segment_bench \
    classifier_bench classifier_walk_probe \
    "${io[@]}" "${@:3}" >&2
}

if [[ -n $pack ]]; then
  "$root/tools/install-deps.sh"
  # The pack's build sees the tree and itself through one fixed link, $link -> build/gpu-pack
  # (src/ there a link to the tree, build/ the build): the paths the tests have compiled in (the
  # goldens, a test shader, a helper program) start with it, and DIR/test-gpu.sh points it at
  # the pack, which holds those files at the same places below it, on a machine where the tree
  # lies elsewhere or not at all. (After a run of a pack here the link points at that pack; this
  # puts it back before building.)
  link=/tmp/steerseg-gpupack
  if [[ -e $link && ! -L $link ]]; then
    echo "bench-gpu: $link is in the way: the pack's build needs it as a link to $root/build/gpu-pack" >&2
    exit 1
  fi
  mkdir -p "$root/build/gpu-pack/build"
  ln -sfn "$root" "$root/build/gpu-pack/src"
  ln -sfn "$root/build/gpu-pack" "$link"
  src_link=$link/src
  built=$link/build
  with_tests=OFF
  more=(steerseg)
  if ((tests)); then
    with_tests=ON
    more+=(steerseg_gpu_tests)
  fi
  build_benches "$built" ON "${more[@]}"
  # A pack made again in the same folder: only this run's test programs are listed.
  rm -rf "$pack/tests" "$pack/tests.tar.xz" "$pack/test-gpu.sh" "$pack/data/sources.txt"
  mkdir -p "$pack/lib" "$pack/data" "$pack/tools" "$pack/bench/kiosk"
  for b in solver_bench render_frame_bench segment_bench classifier_bench classifier_walk_probe; do
    cp "$built/bench/$b" "$pack/"
  done
  cp "$built/steerseg" "$pack/"
  # Stripped like the tests below: the pack and the tree travel within the device tool's 64 MiB.
  strip --strip-unneeded "$pack"/steerseg "$pack"/*_bench "$pack"/classifier_walk_probe
  cp "$0" "$pack/bench-gpu.sh"
  programs=()
  if ((tests)); then
    # The GL test programs the light build lists (tests/CMakeLists.txt), stripped: the symbol
    # tables are most of their size, and a failure's report comes from the test, not a debugger.
    mkdir -p "$pack/tests" "$pack/src" "$pack/build"
    while read -r program; do
      [[ -n $program ]] || continue
      cp "$program" "$pack/tests/"
      programs+=("$pack/tests/$(basename "$program")")
      basename "$program" >>"$pack/tests/programs.txt"
    done <"$built/gpu_tests.txt"
    # Every file or folder of the tree or the build that a compile definition names, copied to
    # the same path below the pack. Not the tree's root (the data folder's default, which
    # STEERSEG_DATA_DIR overrides) nor the build's steerseg (STEERSEG_BINARY: the pack's own).
    python3 - "$built/compile_commands.json" "$link" <<'EOF' >"$pack/tests/compiled-in.txt"
import json, re, sys
prefix = re.escape(sys.argv[2] + "/")
found = set()
for entry in json.load(open(sys.argv[1])):
    for m in re.finditer(r'-D\w+=\\?"' + prefix + r'((?:src|build)/[^"\\]+)\\?"', entry["command"]):
        found.add(m[1])
found.discard("build/steerseg")
print("\n".join(sorted(found)))
EOF
    while read -r rel; do
      if [[ ! -e $link/$rel ]]; then
        echo "bench-gpu: a test names $link/$rel, which is not there: not packed" >&2
        continue
      fi
      mkdir -p "$pack/$(dirname "$rel")"
      cp -RLT "$link/$rel" "$pack/$rel" # -T: into a folder a packing before made, not below it
      if [[ $rel == build/* && -f $pack/$rel && -x $pack/$rel ]]; then
        programs+=("$pack/$rel") # a helper program: stripped and its libraries carried too
      fi
    done <"$pack/tests/compiled-in.txt"
    strip --strip-unneeded "${programs[@]}"
    echo "$link" >"$pack/tests/link"
    cp "$root/tools/test-gpu.sh" "$pack/test-gpu.sh"
  fi
  # bench-kiosk.sh where its own root finds it and its sessions (DIR/tools/.. = DIR).
  cp "$root/tools/bench-kiosk.sh" "$pack/tools/"
  cp "$root"/bench/kiosk/*.session "$pack/bench/kiosk/"
  # Every library the binaries load beyond what a base system with the GPU's driver has.
  base='^(linux-vdso|ld-linux|libc|libm|libstdc\+\+|libgcc_s|libEGL|libGLESv2|libGLdispatch|libgbm|libdrm|libz)\.so'
  carried=$(ldd "$pack"/steerseg "$pack"/*_bench "${programs[@]}" | awk '/=>/ { print $1, $3 }' | sort -u |
    grep -Ev "$base" || true)
  while read -r name path; do
    [[ -n $name ]] && cp -L "$path" "$pack/lib/$name"
  done <<<"$carried"
  echo "bench-gpu: carried $(echo "$carried" | awk '{ print $1 }' | tr '\n' ' ')($(du -sh "$pack/lib" | cut -f1))"
  for c in "${cases[@]}"; do
    IFS='|' read -r name scan mask _ <<<"$c"
    if ((!scans)); then
      echo "bench-gpu: $name not packed (--no-scans)" >&2
    elif [[ -f $data/$scan && -f $data/$mask ]]; then
      cp "$data/$scan" "$pack/data/$name.nii.gz"
      cp "$data/$mask" "$pack/data/${name}_mask.nii.gz"
      # Their places in the data folder, for DIR/test-gpu.sh: solver_gpu's real-scan tests read them.
      printf '%s %s\n' "$name.nii.gz" "$scan" "${name}_mask.nii.gz" "$mask" >>"$pack/data/sources.txt"
    else
      echo "bench-gpu: $name not packed: $data/$scan or its mask is missing" >&2
    fi
  done
  echo "bench-gpu: packed in $pack ($(du -sh "$pack" | cut -f1)); run '$pack/bench-gpu.sh --bin $pack' there"
  if ((tests)); then
    # xz: the stripped test programs shrink sevenfold (35 MiB to 5 on 2026-12-04), which keeps
    # the pack well inside the device tool's 64 MiB; DIR/test-gpu.sh unpacks them.
    size=$(du -sh "$pack/tests" | cut -f1)
    rm -f "$pack/tests.tar.xz"
    tar -C "$pack" -cJf "$pack/tests.tar.xz" tests
    rm -rf "$pack/tests"
    echo "bench-gpu: and the GPU tests ($size, $(du -sh "$pack/tests.tar.xz" | cut -f1) as tests.tar.xz): '$pack/test-gpu.sh'"
  fi
  exit 0
fi

# CI's small run checks the plumbing, not the figures: the default build's app and benchmarks,
# which CI has just built, save compiling them all again in Release.
have_default() {
  local b
  for b in steerseg bench/solver_bench bench/render_frame_bench bench/segment_bench \
    bench/large_scan_bench; do
    [[ -x $root/build/default/$b ]] || return 1
  done
}
if [[ -z $bin ]] && ((small)) && have_default; then
  bin=$root/build/default/bench
  kiosk_bin=$root/build/default/steerseg
  scan_of() { echo "$data/$2"; }
elif [[ -z $bin ]]; then
  "$root/tools/install-deps.sh"
  kiosk_bin=$root/build/bench-gpu/steerseg
  if wants kiosk; then
    build_benches "$root/build/bench-gpu" OFF steerseg
  else
    build_benches "$root/build/bench-gpu" OFF
  fi
  bin=$root/build/bench-gpu/bench
  scan_of() { echo "$data/$2"; }
else
  bin=$(cd "$bin" && pwd)
  kiosk_bin=$bin/steerseg
  kiosk_script=$bin/tools/bench-kiosk.sh
  export LD_LIBRARY_PATH="$bin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  scan_of() { echo "$bin/data/$1$3"; } # packed names: sarcoma.nii.gz, sarcoma_mask.nii.gz
fi
kiosk_script=${kiosk_script:-$root/tools/bench-kiosk.sh}
mkdir -p "$out"
log=$out/bench-gpu.log
: >"$log"
md=$out/bench-gpu.md
started=$(date +%s)

run() { # part command...: runs one benchmark, keeping its output in the log and in $part.txt
  local part=$1
  shift
  echo "bench-gpu: $part: $*" >&2
  "$@" 2>&1 | tee -a "$log" >>"$out/$part.txt"
}
rm -f "$out"/{solver,render,segment,pictures,kiosk,large}.txt "$out/kiosk/bench-kiosk.json" \
  "$out/large.json"

renderer=$("$bin/solver_bench" --size 16 --iterations 1 --dense-size 0 2>&1 | sed -n 's/^renderer: \(.*\), volume .*/\1/p')
software=0
if [[ -z $renderer || $renderer == *llvmpipe* || $renderer == *softpipe* || $renderer == *SwiftShader* ]]; then
  software=1
fi

if ((small)); then
  solver_sizes=(48); solver_iterations=8; frame_size=320x200; frames=1; scales=(1)
else
  solver_sizes=(256 512); solver_iterations=400; frame_size=1920x1080; frames=30; scales=(2 4)
fi
if wants solver; then
  for n in "${solver_sizes[@]}"; do
    run solver "$bin/solver_bench" --size "$n" --iterations "$solver_iterations" --dense-size 0
  done
fi
if wants render; then
  for s in "${scales[@]}"; do
    run render "$bin/render_frame_bench" --scale "$s" --size "$frame_size" --frames "$frames"
  done
fi
if wants segment; then
  for c in "${cases[@]}"; do
    IFS='|' read -r name scan mask seed T eps alpha t itk <<<"$c"
    s=$(scan_of "$name" "$scan" .nii.gz)
    m=$(scan_of "$name" "$mask" _mask.nii.gz)
    if [[ ! -f $s || ! -f $m ]]; then
      echo "bench-gpu: segment: $name skipped: $s or $m not found (STEERSEG_DATA_DIR)" >&2
      echo "case $name skipped: scan not found" >>"$out/segment.txt"
      continue
    fi
    repeat=5
    if ((small)); then
      repeat=1 t=0.5 itk=0 # llvmpipe takes tens of seconds to ITK's time: no comparison
    fi
    echo "case $name itk_seconds $itk time $t" >>"$out/segment.txt"
    # ITK's seed is a ball in voxel steps; the product's spheres are round in millimetres.
    run segment "$bin/segment_bench" --scan "$s" --seed "$seed" --T "$T" --eps "$eps" \
      --alpha "$alpha" --time "$t" --repeat "$repeat" --compare "$m" --voxel-spheres 1
  done
fi
if wants pictures; then
  run pictures "$bin/render_frame_bench" --docs "$out/pictures"
fi

if wants large; then
  if [[ -x $bin/large_scan_bench ]]; then
    large_args=(--size 512x512x1000 --repeat 3)
    if ((small)); then
      large_args=(--size 128x128x64 --body-iterations 8)
    fi
    run large "$bin/large_scan_bench" "${large_args[@]}" --json "$out/large.json"
  else
    echo "bench-gpu: large skipped: no $bin/large_scan_bench (the pack has no DICOM reader)" >&2
  fi
fi

if wants kiosk; then
  if [[ -x $kiosk_bin && -x $kiosk_script ]]; then
    kiosk_args=(--bin "$kiosk_bin" --out "$out/kiosk")
    if ((small)); then
      kiosk_args+=(--small)
    fi
    run kiosk "$kiosk_script" "${kiosk_args[@]}"
  else
    echo "bench-gpu: kiosk skipped: no $kiosk_bin or $kiosk_script" >&2
  fi
fi

# One Markdown report and one JSON file from the benchmarks' own output.
python3 - "$out" "$renderer" "$software" "$small" "$(($(date +%s) - started))" <<'EOF'
import json, re, sys, pathlib
out, renderer, software, small, seconds = sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4] == "1", int(sys.argv[5])
out = pathlib.Path(out)
def text(part):
    p = out / f"{part}.txt"
    return p.read_text() if p.exists() else ""

def tables(s):  # every Markdown table: list of rows as dicts, with the heading above it
    found, heading, lines = [], "", s.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("## ") or lines[i].startswith("renderer:"):
            heading = lines[i].lstrip("# ").strip()
        if lines[i].startswith("|") and i + 1 < len(lines) and lines[i + 1].startswith("|---"):
            head = [h.strip() for h in lines[i].strip("|").split("|")]
            rows, i = [], i + 2
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(dict(zip(head, [c.strip() for c in lines[i].strip("|").split("|")])))
                i += 1
            found.append({"table": heading, "rows": rows})
            continue
        i += 1
    return found

frames, scan = [], ""
for line in text("render").splitlines():
    if line.startswith("scan: "):
        scan = line[6:]
    # render_frame_bench's rows: view, size, median ms, CPU ms, fps, Mrays/s.
    m = re.match(r"(\S+)\s+(\d+)x(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", line)
    if m:
        frames.append({"scan": scan, "view": m[1], "size": f"{m[2]}x{m[3]}",
                       "median_ms": float(m[4]), "cpu_ms": float(m[5]), "fps": float(m[6]),
                       "mrays_per_s": float(m[7])})
cases, case = [], None
for line in text("segment").splitlines():
    m = re.match(r"case (\S+) itk_seconds (\S+) time (\S+)", line)
    if m:
        case = {"case": m[1], "itk_seconds": float(m[2]), "evolved_time": float(m[3]), "runs": []}
        cases.append(case)
    # segment_bench's "run N: STOP, I iterations, t = T, S s (R it/s), V voxels inside, ...,
    # Dice D" (the sleeping-off run, "run N (sleeping off): ...", is not one of the timed runs).
    m = re.match(r"run \d+: (?:\w+, )?(\d+) iterations, t = ([\d.]+), ([\d.]+) s(?: \([\d.]+ it/s\))?, (\d+) voxels inside", line)
    if m and case is not None:
        dice = re.search(r"Dice ([\d.]+)", line)
        case["runs"].append({"iterations": int(m[1]), "seconds": float(m[3]), "inside": int(m[4]),
                             "dice_expert": float(dice[1]) if dice else None})
    m = re.match(r"median solve seconds: ([\d.]+)", line)
    if m and case is not None:
        case["median_seconds"] = float(m[1])
        case["speedup_vs_itk"] = (round(case["itk_seconds"] / case["median_seconds"], 1)
                                  if case["itk_seconds"] > 0 and case["median_seconds"] > 0 else None)
        case["same_mask_every_run"] = len({r["inside"] for r in case["runs"]}) == 1
lesion = re.search(r"lesion: (\d+) iterations, evolved time ([\d.]+), (\d+) voxels inside", text("pictures"))
kiosk_json = out / "kiosk" / "bench-kiosk.json"
kiosk = json.loads(kiosk_json.read_text()) if kiosk_json.exists() else None
large_json = out / "large.json"
large = json.loads(large_json.read_text()) if large_json.exists() else None
report = {"renderer": renderer, "software_renderer": software, "small": small, "seconds": seconds,
          "solver": tables(text("solver")), "render": frames, "segment": cases,
          "sample_lesion": {"iterations": int(lesion[1]), "inside": int(lesion[3])} if lesion else None,
          "kiosk": kiosk, "large": large}
(out / "bench-gpu.json").write_text(json.dumps(report, indent=2) + "\n")

md = [f"# GPU benchmarks: {renderer}", ""]
if software:
    md += ["**Software renderer: these are not GPU figures** (the script's plumbing ran; run it on the GPU machine for the targets).", ""]
md += [f"{'Small sizes (--small). ' if small else ''}{seconds} s in all.", ""]
for t in report["solver"]:
    if not t["rows"]:
        continue
    md += [f"## Solver: {t['table']}", "", "| " + " | ".join(t["rows"][0]) + " |", "|" + "---|" * len(t["rows"][0])]
    md += ["| " + " | ".join(r.values()) + " |" for r in t["rows"]] + [""]
if frames:
    md += ["## Renderer", "", "| scan | view | size | median ms | CPU ms | fps | Mrays/s |",
           "|---|---|---|---|---|---|---|"]
    md += [f"| {f['scan']} | {f['view']} | {f['size']} | {f['median_ms']} | {f['cpu_ms']} | {f['fps']} "
           f"| {f['mrays_per_s']} |" for f in frames] + [""]
if cases:
    md += ["## Time to ITK's evolved time (ITK: one core of the development VM)", "",
           "| case | t | median s | ITK s | speed-up | same mask every run | inside voxels | Dice vs expert |", "|---|---|---|---|---|---|---|---|"]
    for c in cases:
        if "median_seconds" in c and c["runs"]:
            r = c["runs"][0]
            md.append(f"| {c['case']} | {c['evolved_time']} | {c['median_seconds']} | {c['itk_seconds'] or 'n/a'} | {str(c['speedup_vs_itk']) + 'x' if c['speedup_vs_itk'] else 'n/a'} | {'yes' if c['same_mask_every_run'] else 'NO'} | {r['inside']} | {r['dice_expert']} |")
    md.append("")
if lesion:
    md += [f"Sample lesion: {lesion[1]} iterations, {lesion[3]} voxels inside; pictures in pictures/ (compare with llvmpipe's: `idiff`).", ""]
if kiosk:
    md += (out / "kiosk" / "bench-kiosk.md").read_text().splitlines() + [""]
if large:
    md += ["## Full-size scan (docs/large-scans.md)", "", "```"] + text("large").splitlines() + ["```", ""]
(out / "bench-gpu.md").write_text("\n".join(md))
EOF
cat "$md"
if ((software)); then
  echo "bench-gpu: the renderer is '$renderer', a software one: these are not GPU figures"
fi
echo "bench-gpu: $md and $out/bench-gpu.json"
