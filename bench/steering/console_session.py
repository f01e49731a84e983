#!/usr/bin/env python3
"""The console's first session on one labelled scan, as an operator at the kiosk runs it
(issue 51's held-out session): probe and seed at the label's deepest voxel, classify, three
outside marks 3 mm beyond the label's edge on that slice (at 0, 120 and 240 degrees in the
slice), run to the solver's stop, export. The label only places the taps; the kiosk runs the
session script through its real frame loop (offscreen), and the exported mask is scored
against the label. Two builds given the same case run the same taps: a regression between
them shows here without the scan it was seen on.

  console_session.py --bin STEERSEG --scan SCAN --label LABEL [--label-value N]
                     [--seed-radius R] [--config FILE] [--out DIR]

Prints one JSON line: dice, mask and label voxels, the taps, the seconds. Needs Debian's
python3-nibabel and python3-scipy (/usr/bin/python3).
"""
import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import nibabel as nib
import numpy as np
from scipy import ndimage


def label_voxels(path, value):
    data = np.asarray(nib.load(path).dataobj)
    return (data == value) if value is not None else (data > 0)


def taps(label, spacing):
    """The deepest voxel of the label's largest component (exact distance in mm) and three
    points 3 mm beyond its edge on that slice."""
    parts, count = ndimage.label(label)
    if count == 0:
        raise SystemExit("console_session: the label is empty")
    largest = parts == (np.argmax(np.bincount(parts.ravel())[1:]) + 1)
    depth = ndimage.distance_transform_edt(largest, sampling=spacing)
    centre = np.unravel_index(np.argmax(depth), label.shape)
    marks = []
    for degrees in (0, 120, 240):
        step = np.array([math.cos(math.radians(degrees)), math.sin(math.radians(degrees))])
        mm = 0.0
        while True:
            at = np.round(np.array(centre[:2], float) + step * mm / spacing[:2]).astype(int)
            inside = (0 <= at[0] < label.shape[0] and 0 <= at[1] < label.shape[1]
                      and largest[at[0], at[1], centre[2]])
            if not inside:
                break
            mm += 0.25
        at = np.round(np.array(centre[:2], float) + step * (mm + 3.0) / spacing[:2]).astype(int)
        at = np.clip(at, 0, np.array(label.shape[:2]) - 1)
        marks.append((int(at[0]), int(at[1]), int(centre[2])))
    return tuple(int(c) for c in centre), marks


def session_text(scan, centre, marks, seed_radius, export):
    i, j, k = centre
    seed = f"seed {i} {j} {k}" + (f" {seed_radius}" if seed_radius else "")
    lines = [f"load {scan}", "wait loaded timeout 600", "speed classify", f"probe {i} {j} {k}",
             seed]
    lines += [f"outside {m[0]} {m[1]} {m[2]}" for m in marks]
    lines += ["run", "wait state paused timeout 1800", f"export {export}", "wait seconds 2",
              "quit"]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--scan", required=True)
    ap.add_argument("--label", required=True)
    ap.add_argument("--label-value", type=int)
    ap.add_argument("--seed-radius", type=float, help="voxels along the finest axis (default: "
                    "the brush)")
    ap.add_argument("--config", help="a kiosk config layered over the defaults (the kiosk's "
                    "--config)")
    ap.add_argument("--out", default="out/console-session")
    a = ap.parse_args()
    binary = str(Path(a.bin).resolve())
    out = Path(a.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    label = label_voxels(a.label, a.label_value)
    spacing = np.array(nib.load(a.label).header.get_zooms()[:3], float)
    centre, marks = taps(label, spacing)
    export = out / "mask.nii.gz"
    export.unlink(missing_ok=True)
    script = out / "console.session"
    script.write_text(session_text(Path(a.scan).resolve(), centre, marks, a.seed_radius, export))
    start = time.monotonic()
    command = [binary, "kiosk", "--platform", "offscreen", "--script", str(script), "--size",
               "1280x800", "--allow-root"]
    if a.config:
        command += ["--config", str(Path(a.config).resolve())]
    run = subprocess.run(command, cwd=out,
                         capture_output=True, text=True)
    seconds = time.monotonic() - start
    (out / "kiosk.log").write_text(run.stdout + run.stderr)
    if run.returncode != 0 or not export.exists():
        sys.exit(f"console_session: the kiosk failed (status {run.returncode}): {out}/kiosk.log")
    mask = np.asarray(nib.load(export).dataobj) > 0
    if mask.shape != label.shape:
        sys.exit("console_session: the exported mask is not on the label's grid")
    both = int((mask & label).sum())
    print(json.dumps({"dice": round(2.0 * both / (int(mask.sum()) + int(label.sum())), 4),
                      "mask_voxels": int(mask.sum()), "label_voxels": int(label.sum()),
                      "seed": list(centre), "seed_radius": a.seed_radius,
                      "outside": [list(m) for m in marks], "seconds": round(seconds, 1)}))


if __name__ == "__main__":
    main()
