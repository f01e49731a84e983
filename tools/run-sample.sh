#!/usr/bin/env bash
# The main job: builds steerseg (release) and runs it on its built-in sample scan: prints the GPU
# and the scan, segments the phantom's lesion from one seed until the surface converges, writes
# the mask and a report, and renders a few frames of the result. Installs what it needs first.
# Output goes to ./out/ (override with STEERSEG_OUT). Offscreen: the kiosk window and KMS
# backends come with the kiosk shell.
set -euo pipefail
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
bin=build/release/steerseg
out=${STEERSEG_OUT:-out}
mkdir -p "$out"

"$bin" gpu-info >"$out/gpu-info.json"
echo "GPU: $(grep '"renderer"' "$out/gpu-info.json")"
"$bin" info builtin:sample >"$out/sample-info.json"

# The lesion of the phantom (app/core/sample_phantom.hpp): one seed inside it, T and eps around
# its intensity, mostly data term.
segmentation=(--seed 80,56,52,5 --T 800 --eps 100 --alpha 0.8)
"$bin" segment --input builtin:sample "${segmentation[@]}" --converge --max-iterations 2000 \
  --output "$out/lesion-mask.nii.gz" --report "$out/segment-report.json"

mask=(--input builtin:sample --mask "$out/lesion-mask.nii.gz")
"$bin" render "${mask[@]}" --size 384x384 --view 3d --surface translucent --output "$out/frame-3d.png"
"$bin" render "${mask[@]}" --size 384x384 --view 3d --clip 0,-1,0,-56 --output "$out/frame-3d-clip.png"
"$bin" render "${mask[@]}" --size 512x512 --view axial --slice 52 --output "$out/frame-axial.png"
"$bin" render "${mask[@]}" --size 512x512 --view coronal --slice 56 --output "$out/frame-coronal.png"
"$bin" render --input builtin:sample --view sagittal --slice 80 --speed --T 800 --eps 100 \
  --size 512x512 --output "$out/frame-sagittal-speed.png"

echo "steerseg: mask, report and frames in $out/"
ls -l "$out"
