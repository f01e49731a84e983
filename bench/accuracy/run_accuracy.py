#!/usr/bin/env python3
"""The accuracy benchmark: Dice against the expert or reference label for each speed on each
labelled case (bench/accuracy/cases.toml), every run to the solver's own stop.

Each run is one `steerseg segment ... --converge --stop-on-leak --reference LABEL`, so the
figures come from the product's own command line and its report. The parameters follow one rule
for every case (RULES below); only the operator's spheres differ, and those come from the image.
Writes accuracy.json (every report) and accuracy.md (the table) to --out.

  run_accuracy.py --steerseg BIN [--data DIR] [--out DIR] [--cases FILE]
                  [--only NAME[,NAME]] [--speeds threshold,edge,classify] [--max-iterations N]
                  [--bound BIN] [--bound-only]

--bound BIN (bench/accuracy_bound) adds, per case, what each speed's ingredient reaches when
fitted to the case's own label (bounds.md, and "bounds" in accuracy.json): the figure a goal is
read against. --bound-only runs that alone.
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
GOALS = {"tumour": 0.85, "tissue": 0.90}
LIMITS = {"seeds": 3, "outside": 3, "barriers": 2}

# One rule per speed, the same on every case. The probe gives T and eps (and, for the edge
# speed, the smoothing's conductance and kappa from its noise); for classify it is the inside
# example. alpha weighs curvature against a data term in the scan's units (threshold, edge) or
# in [-1, 1] (classify), hence the larger weight there.
RULES = {
    "threshold": ["--alpha", "0.2"],
    "edge": ["--speed", "edge", "--smooth", "10", "--alpha", "0.2"],
    "classify": ["--speed", "classify", "--alpha", "0.5"],
}


def check_case(case):
    for key in ("name", "scan", "label", "goal", "seeds", "probe"):
        if key not in case:
            sys.exit(f"cases: a case lacks '{key}': {case}")
    if case["goal"] not in GOALS:
        sys.exit(f"cases: {case['name']}: goal must be one of {sorted(GOALS)}")
    for key, most in LIMITS.items():
        if len(case.get(key, [])) > most:
            sys.exit(f"cases: {case['name']}: at most {most} {key} (an operator's inputs)")
    if not case["seeds"]:
        sys.exit(f"cases: {case['name']}: no seed")


def command(binary, case, speed, data, out, max_iterations):
    mask = out / f"{case['name']}-{speed}.nii.gz"
    report = out / f"{case['name']}-{speed}.json"
    cmd = [str(binary), "segment", "--input", str(data / case["scan"]), "--output", str(mask),
           "--report", str(report), "--reference", str(data / case["label"]),
           "--probe", case["probe"], "--converge", "--max-iterations", str(max_iterations),
           "--stop-on-leak"]
    if "label_value" in case:
        cmd += ["--reference-label", str(case["label_value"])]
    for s in case["seeds"]:
        cmd += ["--seed", s]
    for s in case.get("barriers", []):
        cmd += ["--barrier", s]
    if speed == "classify":
        for s in case.get("outside", []):
            cmd += ["--outside", s]
    return cmd + RULES[speed], report


def run_one(binary, case, speed, data, out, max_iterations):
    cmd, report = command(binary, case, speed, data, out, max_iterations)
    print(f"accuracy: {case['name']} {speed}: {' '.join(cmd)}", file=sys.stderr, flush=True)
    start = time.monotonic()
    done = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        return {"case": case["name"], "speed": speed, "error": done.stderr.strip()[-400:],
                "wall_seconds": wall}
    r = json.loads(report.read_text())
    return {
        "case": case["name"], "speed": speed, "dice": r["reference"]["dice"],
        "inside_voxels": r["inside_voxels"], "label_voxels": r["reference"]["voxels"],
        "stop_reason": r["stop_reason"], "iterations": r["iterations"],
        "evolved_time": r["evolved_time"], "solve_seconds": r["solve_seconds"],
        "preprocessing_seconds": r["preprocessing_seconds"],
        "training_seconds": r["training_seconds"], "wall_seconds": wall,
        "T": r["T"], "eps": r["eps"], "renderer": r["renderer"], "report": r,
    }


def bound_one(binary, case, data, out, max_iterations):
    report = out / f"{case['name']}-bound.json"
    cmd = [str(binary), "--scan", str(data / case["scan"]), "--label", str(data / case["label"]),
           "--max-iterations", str(max_iterations), "--json", str(report)]
    if "label_value" in case:
        cmd += ["--label-value", str(case["label_value"])]
    for s in case["seeds"]:
        cmd += ["--seed", s]
    print(f"accuracy: {case['name']} bound: {' '.join(cmd)}", file=sys.stderr, flush=True)
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        return {"case": case["name"], "error": done.stderr.strip()[-400:]}
    return {"case": case["name"], **json.loads(report.read_text())}


def bound_table(cases, bounds):
    by = {b["case"]: b for b in bounds}
    lines = ["| case | goal | interval | classifier (voxels) | classifier + level set |",
             "|---|---|---|---|---|"]
    for case in cases:
        b = by.get(case["name"])
        goal = GOALS[case["goal"]]
        if b is None or "error" in b:
            cells = ["error" if b else "-"] * 3
        else:
            def cell(d):
                return f"**{d:.3f}**" if d >= goal else f"{d:.3f}"
            iv, cl, ls = b["interval"], b["classifier"], b["level_set"]
            cells = [f"{cell(iv['dice'])} [{iv['lo']:.0f}, {iv['hi']:.0f}]",
                     f"{cell(cl['dice_connected'])} (out-of-bag {cl['out_of_bag']:.3f})",
                     f"{cell(ls['dice'])} ({ls['stop']})"]
        lines.append(f"| {case['what']} | {goal:.2f} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def table(cases, rows, speeds):
    by = {(r["case"], r["speed"]): r for r in rows}
    lines = ["| case | goal | " + " | ".join(speeds) + " |",
             "|---|---|" + "---|" * len(speeds)]
    for case in cases:
        cells = []
        for speed in speeds:
            r = by.get((case["name"], speed))
            if r is None:
                cells.append("-")
            elif "error" in r:
                cells.append("error")
            else:
                stop = {"converged": "conv.", "leak": "leak",
                        "iteration_limit": "cap"}.get(r["stop_reason"], r["stop_reason"])
                mark = "**" if r["dice"] >= GOALS[case["goal"]] else ""
                cells.append(f"{mark}{r['dice']:.3f}{mark} ({stop}, {r['wall_seconds']:.0f} s)")
        lines.append(f"| {case['what']} | {GOALS[case['goal']]:.2f} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steerseg", required=True, type=Path)
    ap.add_argument("--data", type=Path,
                    default=Path(os.environ.get("STEERSEG_DATA_DIR", HERE / "../../../shared/data")))
    ap.add_argument("--out", type=Path, default=Path("out/accuracy"))
    ap.add_argument("--cases", type=Path, default=HERE / "cases.toml")
    ap.add_argument("--only", default="")
    ap.add_argument("--speeds", default="threshold,edge,classify")
    ap.add_argument("--max-iterations", type=int, default=5000)
    ap.add_argument("--bound", type=Path, help="bench/accuracy_bound: add the label-fitted bounds")
    ap.add_argument("--bound-only", action="store_true", help="the bounds alone, no segmentation")
    a = ap.parse_args()
    if a.bound_only and not a.bound:
        sys.exit("accuracy: --bound-only needs --bound BIN")

    cases = tomllib.loads(a.cases.read_text())["case"]
    for case in cases:
        check_case(case)
    if a.only:
        wanted = set(a.only.split(","))
        unknown = wanted - {c["name"] for c in cases}
        if unknown:
            sys.exit(f"accuracy: no case named {sorted(unknown)}")
        cases = [c for c in cases if c["name"] in wanted]
    speeds = a.speeds.split(",")
    for s in speeds:
        if s not in RULES:
            sys.exit(f"accuracy: unknown speed '{s}' ({', '.join(RULES)})")
    missing = [c["name"] for c in cases
               if not (a.data / c["scan"]).exists() or not (a.data / c["label"]).exists()]
    if missing:
        print(f"accuracy: SKIPPED {', '.join(missing)}: scans not under {a.data} "
              "(STEERSEG_DATA_DIR)", file=sys.stderr)
        if os.environ.get("STEERSEG_REQUIRE_DATA") == "1":
            sys.exit(1)
        cases = [c for c in cases if c["name"] not in missing]

    a.out.mkdir(parents=True, exist_ok=True)
    bounds = []
    if a.bound:
        for case in cases:
            b = bound_one(a.bound, case, a.data, a.out, a.max_iterations)
            bounds.append(b)
            shown = b.get("error") or (f"interval {b['interval']['dice']:.3f}, classifier "
                                       f"{b['classifier']['dice_connected']:.3f}, with the level "
                                       f"set {b['level_set']['dice']:.3f}")
            print(f"accuracy: {case['name']} bound: {shown}", file=sys.stderr, flush=True)
        md = bound_table(cases, bounds)
        (a.out / "bounds.md").write_text(
            f"Dice against the label of each speed's ingredient fitted to that label "
            f"(bench/accuracy_bound; bold: at or above the goal), "
            f"{datetime.date.today().isoformat()}.\n\n{md}\n")
        print(md)
    if a.bound_only:
        (a.out / "accuracy.json").write_text(json.dumps(
            {"date": datetime.date.today().isoformat(), "bounds": bounds}, indent=1))
        return 1 if any("error" in b for b in bounds) else 0
    rows = []
    for case in cases:
        for speed in speeds:
            row = run_one(a.steerseg, case, speed, a.data, a.out, a.max_iterations)
            rows.append(row)
            shown = row.get("error") or f"Dice {row['dice']:.3f}, {row['stop_reason']}, " \
                f"{row['iterations']} iterations, {row['wall_seconds']:.1f} s"
            print(f"accuracy: {case['name']} {speed}: {shown}", file=sys.stderr, flush=True)
            # Written after each run, so an interrupted benchmark keeps what it measured.
            result = {"date": datetime.date.today().isoformat(), "rules": RULES,
                      "max_iterations": a.max_iterations, "rows": rows, "bounds": bounds}
            (a.out / "accuracy.json").write_text(json.dumps(result, indent=1))
    md = table(cases, rows, speeds)
    renderer = next((r["renderer"] for r in rows if "renderer" in r), "?")
    (a.out / "accuracy.md").write_text(
        f"Dice against the label (bold: the goal met), the solver's stop and the command's wall "
        f"time; {renderer}, {datetime.date.today().isoformat()}.\n\n{md}\n")
    print(md)
    errors = [r for r in rows + bounds if "error" in r]
    for r in errors:
        print(f"accuracy: {r['case']} {r.get('speed', 'bound')} failed: {r['error']}",
              file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
