#!/usr/bin/env bash
# Builds and runs every test: the default build, the ASan+UBSan build (leak detection on), and
# each libFuzzer target briefly on its seed corpus. Installs what it needs first. Used by the
# README and .ci/run. Prints how many tests ran and skipped per build, then one summary line.
#   tools/test.sh            everything
#   tools/test.sh --quick    the default build's tests only
# STEERSEG_REQUIRE_DATA=1 (set by .ci/run) makes a test whose real scan is missing fail instead
# of skipping, and any skipped test fail the run.
set -euo pipefail
cd "$(dirname "$0")/.."

tools/install-deps.sh
jobs=$(nproc)
summary=()
passed_total=0

# Runs one build's CTest suite (its preset errors on zero tests) and reports the counts from
# CTest's JUnit output.
run_ctest() {
  local preset=$1
  local junit="$PWD/build/$preset/ctest-junit.xml"
  rm -f "$junit"
  local rc=0
  # Tests of hardware this machine may lack (label "hardware": a DRM display) skip without it:
  # the presets leave them out, and they run apart below, where a skip is not a missing scan.
  ctest --preset "$preset" -j "$jobs" --output-junit "$junit" || rc=$?
  if [[ ! -f "$junit" ]]; then
    echo "$preset: CTest wrote no results ($junit)" >&2
    exit 1
  fi
  local counts
  # tests= counts every test, skipped ones included; failures= and skipped= are separate. The
  # fourth number: failed tests whose only fault is LeakSanitizer's own tracer crashing at exit
  # ("LeakSanitizer has encountered a fatal error", a sanitizer fault with many GL threads, not
  # a leak it found: a leak reads "ERROR: LeakSanitizer: detected memory leaks").
  counts=$(python3 - "$junit" <<'EOF'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
suite = root if root.tag == "testsuite" else root.find("testsuite")
total = int(suite.get("tests", 0))
skipped = int(suite.get("skipped", 0)) + int(suite.get("disabled", 0))
failed = int(suite.get("failures", 0)) + int(suite.get("errors", 0))
tracer = 0
for case in suite.iter("testcase"):
    if case.get("status") != "fail":
        continue
    out = "".join(e.text or "" for e in case.iter() if e.tag in ("system-out", "failure"))
    # A GoogleTest program's own verdict is in its output; a script test (the kiosk's crash and
    # resume) runs the kiosk as a child whose exit status the tracer's crash turns into 1, so it
    # has none, and only the rerun below can tell: it must then pass.
    verdict_ok = "[  PASSED  ]" in out or "[  FAILED  ]" not in out
    if ("LeakSanitizer has encountered a fatal error" in out and verdict_ok
            and "detected memory leaks" not in out):
        tracer += 1
print(total - skipped, skipped, failed, tracer)
EOF
)
  local ran skipped failed tracer
  read -r ran skipped failed tracer <<<"$counts"
  # Only when every failure is the tracer's crash: those tests run again, up to three times (the
  # crash is a race at exit, rarer on a second run but not impossible), and count as passed only
  # if they then pass. A real failure or leak still fails the run.
  if ((rc != 0 && failed > 0 && tracer == failed)); then
    echo "$preset: LeakSanitizer's tracer crashed at exit in $tracer test(s) that passed:" \
      "$(tr '\n' ' ' <"build/$preset/Testing/Temporary/LastTestsFailed.log")"
    local rerun_log="$PWD/build/$preset/ctest-rerun.log"
    local attempt
    for attempt in 1 2 3; do
      if ctest --preset "$preset" --rerun-failed >"$rerun_log" 2>&1; then
        echo "$preset: they passed when run again (attempt $attempt, $rerun_log)"
        rc=0
        failed=0
        break
      fi
      if ! grep -q "LeakSanitizer has encountered a fatal error" "$rerun_log" ||
        grep -q "detected memory leaks" "$rerun_log"; then
        break # a failure of another kind: no more attempts
      fi
      echo "$preset: attempt $attempt: the tracer crashed again"
    done
    ((rc == 0)) || cat "$rerun_log"
  fi
  echo "$preset: $ran tests ran, $skipped skipped, $failed failed"
  summary+=("$preset $ran ran/$skipped skipped/$failed failed")
  passed_total=$((passed_total + ran - failed))
  if ((rc != 0)); then
    echo "test.sh: FAILED in the $preset build (${summary[*]})" >&2
    exit "$rc"
  fi
  if [[ "${STEERSEG_REQUIRE_DATA:-}" == "1" ]] && ((skipped > 0)); then
    echo "test.sh: FAILED: $skipped tests skipped in the $preset build with STEERSEG_REQUIRE_DATA=1" >&2
    exit 1
  fi
  # Its log is kept apart and summarised: CI reads CTest's closing line, and a run whose only
  # test skipped (no display here) would close the output as if nothing had been tested.
  local hw_log="$PWD/build/$preset/ctest-hardware.log"
  if ! ctest --test-dir "build/$preset" -L hardware --no-tests=ignore >"$hw_log" 2>&1; then
    cat "$hw_log"
    echo "test.sh: FAILED: a hardware test failed in the $preset build ($hw_log)" >&2
    exit 1
  fi
  echo "$preset: hardware tests: $(grep -c -- '\*\*\*Skipped' "$hw_log" || true) skipped without the device," \
    "$(grep -c -- ' Passed ' "$hw_log" || true) passed ($hw_log)"
}

echo "== default build"
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
run_ctest default

if [[ "${1:-}" == "--quick" ]]; then
  echo "test.sh: passed (${summary[*]})"
  exit 0
fi

echo "== ASan + UBSan build"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
run_ctest asan

echo "== fuzz targets"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs" --target steerseg_fuzzers
fuzz_seconds=${STEERSEG_FUZZ_SECONDS:-12}
fuzz_seed=${STEERSEG_FUZZ_SEED:-1}
shopt -s nullglob
ran=0
for target in build/fuzz/tests/fuzz/fuzz_*; do
  [[ -x "$target" ]] || continue
  name=$(basename "$target")
  corpus="tests/fuzz/corpus/${name#fuzz_}"
  # A fuzzer started on an empty folder only mutates from nothing: that is not the test CI means.
  seeds=("$corpus"/*)
  if ((${#seeds[@]} == 0)); then
    echo "test.sh: FAILED: $name has no seed corpus in $corpus (tests/fuzz/make_corpus.py)" >&2
    exit 1
  fi
  work=$(mktemp -d)
  cp -r "$corpus"/. "$work"/
  # A crashing input is kept under build/fuzz/artifacts/, not dropped in the checkout.
  artifacts="build/fuzz/artifacts/$name/"
  mkdir -p "$artifacts"
  echo "-- $name for ${fuzz_seconds}s on $corpus (${#seeds[@]} seeds)"
  rc=0
  # A fixed seed: each run mutates the corpus in the same order, so the result depends on the
  # change, not on luck (STEERSEG_FUZZ_SEED=0 draws a random one for exploring). Every input
  # that once crashed stays in the corpus and is replayed first.
  "$target" -seed="$fuzz_seed" -max_total_time="$fuzz_seconds" -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=0 -artifact_prefix="$artifacts" "$work" >"$work.log" 2>&1 ||
    rc=$?
  tail -n "$( ((rc == 0)) && echo 3 || echo 40)" "$work.log"
  rm -rf "$work" "$work.log"
  if ((rc != 0)); then
    echo "test.sh: FAILED: $name found a crash (exit $rc; input in $artifacts) (${summary[*]})" >&2
    exit 1
  fi
  ran=$((ran + 1))
done
if ((ran == 0)); then
  echo "test.sh: FAILED: no fuzz targets under build/fuzz/tests/fuzz" >&2
  exit 1
fi
echo "fuzz: $ran targets ran without a crash"
summary+=("fuzz $ran targets")

# The GPU benchmark's whole plumbing in its small form, so the one command for the lent GPU
# machine cannot rot between the sessions that have one (its figures here are llvmpipe's).
echo "== tools/bench-gpu.sh --small"
tools/bench-gpu.sh --small --out build/bench-gpu-small >build/bench-gpu-small.log 2>&1 || {
  tail -n 40 build/bench-gpu-small.log
  echo "test.sh: FAILED: tools/bench-gpu.sh --small (log: build/bench-gpu-small.log)" >&2
  exit 1
}
python3 - build/bench-gpu-small/bench-gpu.json <<'EOF'
import json, os, sys
r = json.load(open(sys.argv[1]))
missing = [k for k in ("solver", "render", "kiosk") if not r.get(k)]
if missing or r["sample_lesion"] is None:
    sys.exit(f"bench-gpu.json lacks {missing or 'the sample lesion'}")
# A case ran when its runs were read too: a change of segment_bench's line would leave them out.
ran = [c for c in r["segment"] if c.get("median_seconds") is not None and c.get("runs")]
if len(ran) < 2 and os.environ.get("STEERSEG_REQUIRE_DATA") == "1":
    sys.exit("bench-gpu.json: the real cases did not run (STEERSEG_DATA_DIR)")
print(f"bench-gpu --small: {len(r['solver'])} solver tables, {len(r['render'])} frame rows, "
      f"{len(r['segment'])} real cases, kiosk latency p50 {r['kiosk']['sizes'][0]['latency']['p50_ms']} ms, "
      f"{r['seconds']} s on {r['renderer']}")
EOF
summary+=("bench-gpu --small")
echo "test.sh: passed (${summary[*]})"
echo "tests: $passed_total passed, 0 failed"

