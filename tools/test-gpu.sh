#!/usr/bin/env bash
# The GL tests on the lent GPU machine, from the pack (tools/bench-gpu.sh --pack DIR --tests), with
# neither CMake nor CTest there: each GoogleTest program the light build labels "gpu" (gpu, speed,
# solver, render, session, engine, kiosk, cli, ui, platform), each TEST in a process of its own as
# CTest runs them, with the pack's libraries, its steerseg and the source files the tests read.
#
#   DIR/test-gpu.sh [--jobs N] [--timeout S] [--only PROGRAM[,PROGRAM...]]
#                   [--filter GTEST_FILTER] [--data DIR] [--out DIR] [--list]
#   tools/test-gpu.sh --bin DIR [same options]
#
# --jobs runs that many tests at once (default: the processor count); --timeout fails a test that
# runs longer (default 300 s); --only and --filter (GoogleTest's syntax) choose programs and
# tests; --data is the real-scan folder, laid out as ../shared/data (default $STEERSEG_DATA_DIR,
# else the pack's data/: the benchmarks' two cases are what solver_gpu's real-scan tests read;
# without them those tests skip, as they do wherever the data is missing); --out keeps
# test-gpu.log there (every test's result, the failing ones' output; default out/test-gpu);
# --list prints the tests it would run. The last line is "N passed, N failed, N skipped"; the
# exit status is non-zero if any failed or none ran. About a minute on llvmpipe (2 cores).
#
# A test that meets a part the light build leaves out (its one-line refusal, "... is not in this
# light build of steerseg": reading the PNG goldens, TIFF, KMS) counts as skipped, with that line
# as the reason: the full build runs those tests (tools/test.sh).
#
# The tests find some files through paths compiled in (tests/render's goldens, tests/gpu's
# shader, a helper program the kiosk's tests build): the pack's build made them under a fixed
# link, /tmp/steerseg-gpupack (the pack's tests/link), which this script points at the pack while
# the tests run, and puts back as it was after.
set -euo pipefail

bin=""
jobs=$(nproc 2>/dev/null || echo 2)
timeout_s=300
only=""
filter=""
data=${STEERSEG_DATA_DIR:-}
out=${STEERSEG_OUT:-out/test-gpu}
list=0
while (($#)); do
  case $1 in
    --bin) bin=${2:?--bin needs a folder}; shift ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift ;;
    --timeout) timeout_s=${2:?--timeout needs seconds}; shift ;;
    --only) only=${2:?--only needs a list of programs}; shift ;;
    --filter) filter=${2:?--filter needs a GoogleTest filter}; shift ;;
    --data) data=${2:?--data needs a folder}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    --list) list=1 ;;
    -h|--help) sed -n '2,27p' "$0"; exit 0 ;;
    *) echo "test-gpu: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "test-gpu: --jobs wants a positive number, not '$jobs'" >&2; exit 2; }
[[ $timeout_s =~ ^[1-9][0-9]*$ ]] || { echo "test-gpu: --timeout wants seconds, not '$timeout_s'" >&2; exit 2; }

# Packed, the script sits in the pack; from the source tree, --bin names it.
bin=${bin:-$(dirname "$0")}
bin=$(cd "$bin" && pwd)
if [[ ! -f $bin/tests/programs.txt && -f $bin/tests.tar.xz ]]; then
  tar -C "$bin" -xJf "$bin/tests.tar.xz" # the pack carries them compressed
fi
if [[ ! -f $bin/tests/programs.txt ]]; then
  echo "test-gpu: $bin has no tests/programs.txt: pack it with 'tools/bench-gpu.sh --pack DIR --tests'" >&2
  exit 2
fi

if [[ -n $data && ! -d $data ]]; then
  echo "test-gpu: no data folder $data" >&2
  exit 2
fi
link=$(<"$bin/tests/link")
if [[ -e $link && ! -L $link ]]; then
  echo "test-gpu: $link is not a link: the tests' compiled-in paths cannot reach $bin" >&2
  exit 2
fi
was=$(readlink "$link" || true)

mapfile -t programs <"$bin/tests/programs.txt"
if [[ -n $only ]]; then
  wanted=()
  IFS=',' read -ra names <<<"$only"
  for n in "${names[@]}"; do
    [[ -x $bin/tests/$n ]] || { echo "test-gpu: no test program '$n' in $bin/tests" >&2; exit 2; }
    wanted+=("$n")
  done
  programs=("${wanted[@]}")
fi
scratch=$(mktemp -d "${TMPDIR:-/tmp}/steerseg-test-gpu.XXXXXX")
restore() {
  rm -rf "$scratch"
  if [[ -n $was ]]; then
    ln -sfn "$was" "$link"
  else
    rm -f "$link"
  fi
}
trap restore EXIT
ln -sfn "$bin" "$link"

export LD_LIBRARY_PATH="$bin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export STEERSEG_BINARY=$bin/steerseg
if [[ -z $data && -s $bin/data/sources.txt ]]; then
  # The benchmarks' scans, packed under short names, where the tests look for them.
  data=$scratch/data
  while read -r packed original; do
    mkdir -p "$data/$(dirname "$original")"
    ln -s "$bin/data/$packed" "$data/$original"
  done <"$bin/data/sources.txt"
fi
# Unset, the tests would look in ../shared/data beside the compiled-in tree, the pack's src/:
# a folder that is not there makes the real-scan tests skip instead.
export STEERSEG_DATA_DIR=${data:-$bin/no-real-data}
mkdir -p "$out"
out=$(cd "$out" && pwd)
log=$out/test-gpu.log
: >"$log"

# Every test of every program, as "program Suite.Name": GoogleTest lists suites unindented and
# their tests indented, parameters after a '#'; disabled tests are left out as CTest leaves them.
queue=()
for p in "${programs[@]}"; do
  listing=$scratch/$p.list
  if ! timeout 60 "$bin/tests/$p" --gtest_list_tests ${filter:+"--gtest_filter=$filter"} \
    >"$listing" 2>&1; then
    echo "test-gpu: $p: cannot list its tests:" >&2
    tail -n 20 "$listing" >&2
    queue+=("$p (listing)")
    continue
  fi
  suite=""
  while IFS= read -r line; do
    if [[ $line =~ ^([^[:space:]]+)\. ]]; then
      suite=${BASH_REMATCH[1]}
    elif [[ $line =~ ^[[:space:]]+([^[:space:]]+) && -n $suite ]]; then
      name="$suite.${BASH_REMATCH[1]}"
      [[ $name == DISABLED_* || $name == *.DISABLED_* ]] && continue
      queue+=("$p $name")
    fi
  done <"$listing"
done

if ((list)); then
  printf '%s\n' "${queue[@]}"
  exit 0
fi

renderer=$("$STEERSEG_BINARY" gpu-info 2>&1 | sed -n 's/^ *"renderer": "\(.*\)",$/\1/p' || true)
echo "test-gpu: ${#queue[@]} tests from ${#programs[@]} programs, $jobs at a time, renderer: ${renderer:-unknown (steerseg gpu-info failed)}"
if [[ $renderer == *llvmpipe* || $renderer == *softpipe* || $renderer == *SwiftShader* ]]; then
  echo "test-gpu: a software renderer: these runs do not test a GPU"
fi

# One test in its own process and its own working folder (CTest's is the program's build folder);
# its result, "passed|failed|skipped SECONDS program test reason", goes to a file of its own.
run_one() {
  local i=$1 p=${2%% *} name=${2#* } dir=$scratch/run/$1
  mkdir -p "$dir"
  local start=$SECONDS rc=0 status reason=""
  if [[ $name == "(listing)" ]]; then
    echo "failed 0 $p (listing) its test list could not be read" >"$scratch/result.$i"
    return
  fi
  (cd "$dir" && exec timeout -k 10 "$timeout_s" "$bin/tests/$p" "--gtest_filter=$name" \
    --gtest_color=no) >"$scratch/out.$i" 2>&1 || rc=$?
  if ((rc == 124 || rc == 137)); then
    status=failed reason="timed out after $timeout_s s"
  elif ((rc != 0)) && grep -q 'is not in this light build of steerseg' "$scratch/out.$i"; then
    status=skipped
    reason=$(grep -o -m1 '[^":]*is not in this light build of steerseg[^"]*' "$scratch/out.$i" |
      head -n 1 | sed 's/^ *//; s/ (STEERSEG_LIGHT[^)]*)//; s/; use .*//' || true)
  elif ((rc != 0)); then
    status=failed reason="exit status $rc"
  elif grep -q '^\[  SKIPPED \] ' "$scratch/out.$i"; then
    # GoogleTest's skip message is the line after "...: Skipped".
    status=skipped reason=$(grep -A1 -m1 ': Skipped$' "$scratch/out.$i" | tail -n 1 || true)
  elif grep -q '^\[       OK \] ' "$scratch/out.$i"; then
    status=passed
  else
    status=failed reason="it ran no test"
  fi
  echo "$status $((SECONDS - start)) $p $name $reason" >"$scratch/result.$i"
  rm -rf "$dir"
}

started=$SECONDS
running=0
for i in "${!queue[@]}"; do
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
  run_one "$i" "${queue[$i]}" &
  running=$((running + 1))
done
wait || true

passed=0 failed=0 skipped=0
declare -A per_pass per_fail per_skip per_time
for i in "${!queue[@]}"; do
  read -r status seconds p name reason <"$scratch/result.$i"
  per_time[$p]=$((${per_time[$p]:-0} + seconds))
  echo "$status ${seconds}s $p $name${reason:+: $reason}" >>"$log"
  case $status in
    passed) passed=$((passed + 1)); per_pass[$p]=$((${per_pass[$p]:-0} + 1)) ;;
    skipped)
      skipped=$((skipped + 1)); per_skip[$p]=$((${per_skip[$p]:-0} + 1))
      echo "test-gpu: skipped $p $name: $reason" ;;
    *)
      failed=$((failed + 1)); per_fail[$p]=$((${per_fail[$p]:-0} + 1))
      echo "test-gpu: FAILED $p $name ($reason), its output's end:"
      if [[ -f $scratch/out.$i ]]; then
        tail -n 25 "$scratch/out.$i" | sed 's/^/    /'
        { echo "--- $p $name"; cat "$scratch/out.$i"; echo "---"; } >>"$log"
      fi ;;
  esac
done
for p in "${programs[@]}"; do
  printf 'test-gpu: %-28s %3d passed, %d failed, %d skipped (%d s of test time)\n' "$p" \
    "${per_pass[$p]:-0}" "${per_fail[$p]:-0}" "${per_skip[$p]:-0}" "${per_time[$p]:-0}"
done
echo "test-gpu: $((SECONDS - started)) s; every test's result in $log"
if ((passed + failed == 0)); then
  echo "test-gpu: no test ran (--only or --filter left none)" >&2
  echo "$passed passed, $failed failed, $skipped skipped"
  exit 1
fi
echo "$passed passed, $failed failed, $skipped skipped"
((failed == 0))
