#!/usr/bin/env bash
# ITK comparison benchmark: ITK's sparse-field ThresholdSegmentationLevelSetImageFilter (CPU)
# against `steerseg segment` (sparse bricks and --dense) on real scans, same PDE and parameters.
# Prints markdown tables; per-case files (masks, JSON reports) go to ${STEERSEG_OUT:-out/bench-itk}.
# See docs/benchmarks-itk.md for what is compared and how to read it.
#   STEERSEG_DATA_DIR  scans (default ../shared/data)
#   BENCH_ALPHA        alpha for every case (default 0.2)
#   BENCH_CASES        space-separated case names (default: lung sts001-ct)
#   BENCH_JOBS         build parallelism (default 2)
#   BENCH_DENSE        1 (default) also runs steerseg --dense to convergence; 0 skips it (slow
#                      on llvmpipe)
#   BENCH_NOISE        1 (default) also compares the two at fixed times on synthetic volumes
#                      (tools/make-noise-volumes.py: uniform, white noise, smoothed noise)
#   BENCH_CONVERGE     1 (default) runs steerseg to convergence; 0 runs it only for ITK's
#                      converged time (a front that leaks may not converge within the cap)
#   STEERSEG_BINARY    a steerseg binary to compare instead of this checkout's Release build
#                      (which is then not built)
set -euo pipefail
cd "$(dirname "$0")/.."

data=${STEERSEG_DATA_DIR:-../shared/data}
out=${STEERSEG_OUT:-out/bench-itk}
build=${BENCH_BUILD_DIR:-build/bench-itk}
alpha=${BENCH_ALPHA:-0.2}
cases=${BENCH_CASES:-lung sts001-ct}
cap=20000

tools/install-deps.sh --bench >&2
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSTEERSEG_BENCH_ITK=ON \
  -DSTEERSEG_BUILD_TESTS=OFF >/dev/null
targets=(steerseg-itk-levelset steerseg-mask-dice steerseg-mask-stats)
[[ -n ${STEERSEG_BINARY:-} ]] || targets+=(steerseg) # a binary given is not built here
cmake --build "$build" -j "${BENCH_JOBS:-2}" --target "${targets[@]}" >&2
steerseg=${STEERSEG_BINARY:-$build/steerseg}
itk=$build/bench/steerseg-itk-levelset
dice=$build/bench/steerseg-mask-dice
stats=$build/bench/steerseg-mask-stats
mkdir -p "$out"

have_segment=0
# The help read whole first: under pipefail, grep -q leaving at its first match ends steerseg
# with SIGPIPE while it still writes, and the pipeline then fails as if no segment were found.
if [[ $'\n'$("$steerseg" --help 2>&1 || true) == *$'\n  segment '* ]]; then
  have_segment=1
fi

# case name -> "scan|expert mask", relative to $data.
case_files() {
  case $1 in
    lung) echo "lung-ct-ibsi/nifti/image.nii.gz|lung-ct-ibsi/nifti/mask.nii.gz" ;;
    sts001-ct) echo "thigh-sarcoma-sts001/STS_001_CT_image.nii.gz|thigh-sarcoma-sts001/STS_001_CT_mask.nii.gz" ;;
    *) echo "bench-itk: unknown case '$1'" >&2; return 1 ;;
  esac
}

# The value of a top-level key in a flat JSON report (a string, number or boolean).
json() {
  local v
  v=$(grep -o "\"$2\": *\"[^\"]*\"" "$1" | head -n1 | sed -e 's/^[^:]*: *"//' -e 's/"$//')
  [[ -n $v ]] || v=$(grep -o "\"$2\": *[^,}\"]*" "$1" | head -n1 | sed -e 's/^[^:]*: *//')
  echo "$v"
}
fmt() { printf '%.*f' "$1" "$2"; }
dice_of() { "$dice" "$1" "$2" | grep -o '"dice": *[0-9.]*' | sed 's/.*: *//'; }

converged_rows=()
fixed_rows=()
setup_rows=()
for name in $cases; do
  IFS='|' read -r scan_rel expert_rel < <(case_files "$name")
  scan=$data/$scan_rel
  expert=$data/$expert_rel
  if [[ ! -f $scan || ! -f $expert ]]; then
    echo "bench-itk: skipping $name: $scan or $expert not found (set STEERSEG_DATA_DIR)" >&2
    continue
  fi
  dir=$out/$name
  mkdir -p "$dir"

  # Parameters from the expert mask: T = mean, eps = std of the intensities inside it; the seed
  # sits at the mask voxel farthest from the mask's border (the centroid of a curved tumour can
  # fall outside it), radius clamp(depth / 2, 1, 3) voxels along the finest axis, round in mm on
  # both sides (the product's spheres; steerseg-itk-levelset --spheres mm, its default).
  "$stats" "$scan" "$expert" >"$dir/expert-stats.json"
  T=$(json "$dir/expert-stats.json" mean)
  eps=$(json "$dir/expert-stats.json" std)
  seed=$(json "$dir/expert-stats.json" seed)
  params=(--input "$scan" --seed "$seed" --T "$T" --eps "$eps" --alpha "$alpha")
  setup_rows+=("| $name | $seed | $(fmt 1 "$T") | $(fmt 1 "$eps") | $alpha | $(json "$dir/expert-stats.json" voxels) |")

  echo "bench-itk: $name: ITK to convergence" >&2
  "$itk" "${params[@]}" --converge --max-iterations $cap --output "$dir/itk.nii.gz" \
    --report "$dir/itk.json" >/dev/null
  itk_t=$(json "$dir/itk.json" evolved_time)
  itk_s=$(json "$dir/itk.json" solve_seconds)
  itk_cell="$(json "$dir/itk.json" iterations) / $(fmt 3 "$itk_t") / $(fmt 2 "$itk_s")"
  d_itk_expert=$(dice_of "$dir/itk.nii.gz" "$expert")

  ss_cell="n/a"; dense_cell="n/a"; speedup="n/a"; d_pair="n/a"; d_ss_expert="n/a"
  fixed_cell="n/a"; fixed_speedup="n/a"; d_fixed="n/a"
  if ((have_segment)); then
    variants=()
    if [[ ${BENCH_CONVERGE:-1} == 1 ]]; then
      variants+=(sparse)
      [[ ${BENCH_DENSE:-1} == 1 ]] && variants+=(dense)
    fi
    rm -f "$dir"/steerseg-{sparse,dense}.{json,nii.gz} # no stale results from an earlier run
    for variant in "${variants[@]}"; do
      extra=()
      [[ $variant == dense ]] && extra=(--dense)
      echo "bench-itk: $name: steerseg ($variant) to convergence" >&2
      "$steerseg" segment "${params[@]}" --converge --max-iterations $cap "${extra[@]}" \
        --output "$dir/steerseg-$variant.nii.gz" --report "$dir/steerseg-$variant.json" >/dev/null
    done
    for variant in "${variants[@]}"; do
      r=$dir/steerseg-$variant.json
      cell="$(json "$r" iterations) / $(fmt 3 "$(json "$r" evolved_time)") / $(fmt 2 "$(json "$r" solve_seconds)")"
      [[ $variant == sparse ]] && ss_cell=$cell || dense_cell=$cell
    done
    if [[ -f $dir/steerseg-sparse.json ]]; then
      speedup="$(awk -v a="$itk_s" -v b="$(json "$dir/steerseg-sparse.json" solve_seconds)" 'BEGIN { printf "%.1fx", a / b }')"
      d_pair=$(dice_of "$dir/itk.nii.gz" "$dir/steerseg-sparse.nii.gz")
      d_ss_expert=$(dice_of "$dir/steerseg-sparse.nii.gz" "$expert")
    fi

    # The same point of the PDE: steerseg evolved for exactly ITK's converged time.
    echo "bench-itk: $name: steerseg (sparse) for t = $itk_t" >&2
    "$steerseg" segment "${params[@]}" --time "$itk_t" --max-iterations $cap \
      --output "$dir/steerseg-fixed.nii.gz" --report "$dir/steerseg-fixed.json" >/dev/null
    r=$dir/steerseg-fixed.json
    fixed_cell="$(json "$r" iterations) / $(fmt 3 "$(json "$r" evolved_time)") / $(fmt 2 "$(json "$r" solve_seconds)")"
    fixed_speedup="$(awk -v a="$itk_s" -v b="$(json "$r" solve_seconds)" 'BEGIN { printf "%.1fx", a / b }')"
    d_fixed=$(dice_of "$dir/itk.nii.gz" "$dir/steerseg-fixed.nii.gz")
  fi
  converged_rows+=("| $name | $itk_cell | $ss_cell | $dense_cell | $speedup | $d_pair | $d_itk_expert | $d_ss_expert |")
  fixed_rows+=("| $name | $(fmt 3 "$itk_t") | $itk_cell | $fixed_cell | $fixed_speedup | $d_fixed |")
done

threads=$(json "$out/$(set -- $cases; echo "$1")/itk.json" threads 2>/dev/null || echo "?")
echo
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'); GL: $("$steerseg" gpu-info 2>/dev/null | grep -o '"renderer": *"[^"]*"' | sed 's/.*: *//' || echo unknown)."
echo "ITK $(json "$out/$(set -- $cases; echo "$1")/itk.json" itk_version 2>/dev/null || echo '?'), default thread count $threads (its sparse-field update loop runs on one thread)."
((have_segment)) || echo "steerseg has no 'segment' command in this build: steerseg columns are n/a."
echo
echo "Parameters (from the expert masks; alpha fixed):"
echo
echo "| case | seed i,j,k,r | T | eps | alpha | expert voxels |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${setup_rows[@]}"
echo
echo "To convergence (each solver's own criterion). Cells: iterations / evolved time / solve seconds."
echo
echo "| case | ITK | steerseg sparse | steerseg dense | speed-up (ITK s / sparse s) | Dice(ITK, steerseg) | Dice(ITK, expert) | Dice(steerseg, expert) |"
echo "|---|---|---|---|---|---|---|---|"
printf '%s\n' "${converged_rows[@]}"
echo
echo "Same evolved time t (ITK's converged time; steerseg --time t, sparse):"
echo
echo "| case | t | ITK | steerseg sparse | speed-up | Dice(ITK, steerseg) |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${fixed_rows[@]}"

# Synthetic volumes: where the two discretisations agree and where they part (voxel-scale noise).
if [[ ${BENCH_NOISE:-1} == 1 ]] && ((have_segment)); then
  noise=$out/noise
  python3 tools/make-noise-volumes.py "$noise"
  noise_rows=()
  for spec in uniform:10:5 white:15:5 white:20:5 smooth:15:5 smooth:15:15 smooth:20:5 smooth:20:15; do
    IFS=: read -r vol eps t <<<"$spec"
    p=(--input "$noise/$vol.nrrd" --seed 32,32,32,3 --T 0 --eps "$eps" --alpha 0.2 --time "$t")
    echo "bench-itk: $vol eps=$eps t=$t" >&2
    "$itk" "${p[@]}" --output "$noise/itk-$vol-$eps-$t.nii.gz" --report "$noise/itk.json" >/dev/null
    "$steerseg" segment "${p[@]}" --output "$noise/steerseg-$vol-$eps-$t.nii.gz" \
      --report "$noise/steerseg.json" >/dev/null
    noise_rows+=("| $vol | $eps | $t | $(json "$noise/itk.json" inside_voxels) | $(json "$noise/steerseg.json" inside_voxels) | $(fmt 3 "$(dice_of "$noise/itk-$vol-$eps-$t.nii.gz" "$noise/steerseg-$vol-$eps-$t.nii.gz")") |")
  done
  echo
  echo "Synthetic 64^3 volumes (intensity std 10, T = 0, alpha 0.2, seed r = 3 at the centre), same evolved time:"
  echo
  echo "| volume | eps | t | ITK voxels | steerseg voxels | Dice(ITK, steerseg) |"
  echo "|---|---|---|---|---|---|"
  printf '%s\n' "${noise_rows[@]}"
fi
