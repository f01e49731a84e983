#!/usr/bin/env python3
"""The steering benchmark (docs/steering.md): the clicks protocol on every labelled case of
bench/accuracy/cases.toml, the product (through the kiosk's workflow) and paint only in the same
run of bench/steering_bench per case, and after it the classical peer on the same prompts:
scikit-image's random walker replaying the level set's clicks (bench/steering/
random_walker_peer.py; --no-peer skips it). Writes steering.json (every report, the peer's under
"peer"), steering.md (the tables) and steering.png (Dice against clicks, level set, random
walker and paint only, one panel a case) to --out.

  run_steering.py --bench BIN [--data DIR] [--out DIR] [--cases FILE] [--only NAME[,NAME]]
                  [--clicks N] [--max-iterations N] [--box] [--no-peer]

The cases file's operator inputs (seeds, probes) are not used: the robot makes every click.
"""
import argparse
import datetime
import json
import subprocess
import sys
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent

# The goals after 5 corrections (issue 27): tumours 0.85 (0.88 after 10), liver and the head
# MR's brain 0.92, the MNI152 tissue classes 0.85; and the level set >= paint only + 0.10.
GOAL_5 = {"tumour": 0.85, "tissue": 0.92}
GOAL_5_TISSUE_CLASS = 0.85
GOAL_10_TUMOUR = 0.88
MARGIN = 0.10


def goal_after_5(case):
    if case["name"].startswith("mni152"):
        return GOAL_5_TISSUE_CLASS
    return GOAL_5[case["goal"]]


def run_case(args, case, data, out):
    report = out / f"{case['name']}.json"
    cmd = [str(args.bench), "--input", str(data / case["scan"]), "--reference",
           str(data / case["label"]), "--clicks", str(args.clicks), "--max-iterations",
           str(args.max_iterations), "--report", str(report)]
    if args.box:
        cmd.append("--box")
    if "label_value" in case:
        cmd += ["--reference-label", str(case["label_value"])]
    print(f"== {case['name']}", file=sys.stderr, flush=True)
    start = time.monotonic()
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL)
    if done.returncode != 0:
        return {"name": case["name"], "error": f"steering_bench exited {done.returncode}"}
    result = json.loads(report.read_text())
    result["name"] = case["name"]
    result["what"] = case.get("what", "")
    result["wall_seconds"] = time.monotonic() - start
    if not args.no_peer:
        result["peer"] = run_peer(case, data, report, out)
    return result


def run_peer(case, data, report, out):
    """The random walker on the level set's prompts of `report` (random_walker_peer.py), in its
    own process: its figures, or {"error": ...} (the table says so; the level set's stand)."""
    peer = out / f"{case['name']}.peer.json"
    cmd = [sys.executable, "-W", "ignore::UserWarning", str(HERE / "random_walker_peer.py"),
           "--scan", str(data / case["scan"]), "--reference", str(data / case["label"]),
           "--report", str(report), "--out", str(peer)]
    if "label_value" in case:
        cmd += ["--reference-label", str(case["label_value"])]
    print("   random walker on its prompts", file=sys.stderr, flush=True)
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    sys.stderr.write(done.stderr)
    if done.returncode != 0:
        last = done.stderr.strip().splitlines()[-1:] or [f"exited {done.returncode}"]
        return {"error": f"random_walker_peer: {last[0]}"}
    return json.loads(peer.read_text())


def fmt(x):
    return "-" if x is None else f"{x:.3f}"


def median(xs):
    xs = sorted(xs)
    if not xs:
        return None
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def table(results, cases):
    lines = [
        "| case | Dice 0 | after 5 | after 10 | paint only after 5 | goal after 5 | AUC (6) | "
        "challenge: final DSC / NSD, DSC_AUC / NSD_AUC, s (paint only) | "
        "median s to stop | median s to first change | stops |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in results:
        case = cases[r["name"]]
        if "error" in r:
            lines.append(f"| {r['name']} | {r['error']} ||||||||||")
            continue
        s, b = r["summary"], r["baseline"]["summary"]
        clicks = r["clicks"][1:] or r["clicks"]
        stops = {}
        for c in r["clicks"]:
            stops[c["stop_reason"]] = stops.get(c["stop_reason"], 0) + 1
        lines.append(
            f"| {r['name']} | {fmt(s['dice_initial'])} | {fmt(s['dice_after_5'])} | "
            f"{fmt(s['dice_after_10'])} | {fmt(b['dice_after_5'])} | {goal_after_5(case):.2f} | "
            f"{s['dice_auc_6']:.2f} | {challenge(s)} ({challenge(b)}) | "
            f"{median([c['seconds'] for c in clicks]):.1f} | "
            f"{median([c['first_change_seconds'] for c in clicks]):.2f} | "
            + ", ".join(f"{k} {v}" for k, v in sorted(stops.items())) + " |")
    return "\n".join(lines)


def peers_table(results):
    """Level set, random walker (same prompts) and paint only side by side, the challenge's
    scores after 5 corrections and the seconds of each (steps 0-5; paint only has no solver)."""
    lines = [
        "| case | walker region | final DSC: level set / walker / paint | "
        "final NSD: level set / walker / paint | DSC_AUC: level set / walker / paint | "
        "NSD_AUC: level set / walker / paint | s: level set / walker |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in results:
        if "error" in r or "peer" not in r:
            continue
        s, b, p = r["summary"], r["baseline"]["summary"], r["peer"]
        if "error" in p:
            lines.append(f"| {r['name']} | {p['error']} ||||||")
            continue
        w = p["summary"]

        def three(key):
            return " / ".join(f"{x[key]:.3f}" if "final" in key else f"{x[key]:.2f}"
                              for x in (s, w, b))
        lines.append(
            f"| {r['name']} | {p['region']}, beta {p['beta']:g} | {three('final_dsc')} | "
            f"{three('final_nsd')} | {three('dsc_auc')} | {three('nsd_auc')} | "
            f"{s['total_seconds']:.1f} / {w['total_seconds']:.1f} |")
    if len(lines) == 2:
        return ""
    return ("Level set, random walker (scikit-image, the level set's prompts replayed: "
            "random_walker_peer.py) and paint only, after 5 corrections. Without a box the "
            "walker's region comes from the label (oracle).\n\n" + "\n".join(lines))


def challenge(s):
    """The interactive challenge's scores of a summary (steering_bench: bench::challengeScores)."""
    if "final_dsc" not in s:
        return "-"
    return (f"{s['final_dsc']:.3f} / {s['final_nsd']:.3f}, {s['dsc_auc']:.2f} / {s['nsd_auc']:.2f}, "
            f"{s['total_seconds']:.0f}")


def plot(results, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib (Debian: python3-matplotlib): no plot", file=sys.stderr)
        return False
    ok = [r for r in results if "error" not in r]
    if not ok:
        return False
    cols = min(4, len(ok))
    rows = (len(ok) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 3.0 * rows), squeeze=False)
    for ax, r in zip(axes.flat, ok):
        ax.plot([c["click"] for c in r["clicks"]], [c["dice"] for c in r["clicks"]], "o-",
                label=f"level set {r['summary']['total_seconds']:.0f} s")
        peer = r.get("peer", {})
        if "clicks" in peer:
            ax.plot([c["click"] for c in peer["clicks"]], [c["dice"] for c in peer["clicks"]],
                    "^-.", label=f"random walker {peer['summary']['total_seconds']:.0f} s")
        base = r["baseline"]["clicks"]
        ax.plot([c["click"] for c in base], [c["dice"] for c in base], "s--", label="paint only")
        ax.set_title(r["name"], fontsize=9)
        ax.set_ylim(0, 1)
        ax.set_xlabel("corrections")
        ax.set_ylabel("Dice")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)  # each panel's own seconds
    for ax in list(axes.flat)[len(ok):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bench", required=True)
    ap.add_argument("--data", default=str(HERE.parent.parent.parent / "shared" / "data"))
    ap.add_argument("--out", default="out/steering")
    ap.add_argument("--cases", default=str(HERE.parent / "accuracy" / "cases.toml"))
    ap.add_argument("--only", default="")
    ap.add_argument("--clicks", type=int, default=10)
    ap.add_argument("--max-iterations", type=int, default=3000)
    ap.add_argument("--box", action="store_true",
                    help="the challenge's protocol: start from the label's bounding box, "
                    "then click where the challenge's evaluation does (voxel steps)")
    ap.add_argument("--no-peer", action="store_true",
                    help="skip the random walker on the level set's prompts")
    args = ap.parse_args()
    data, out = Path(args.data), Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    cases = tomllib.loads(Path(args.cases).read_text())["case"]
    if args.only:
        wanted = set(args.only.split(","))
        cases = [c for c in cases if c["name"] in wanted]
    if not args.no_peer:
        try:
            import nibabel  # noqa: F401
            import skimage  # noqa: F401
        except ImportError as e:
            sys.exit(f"the random walker peer needs scikit-image and nibabel (Debian: "
                     f"python3-skimage python3-nibabel; {e}), or give --no-peer")
    for c in cases:
        if not (data / c["scan"]).exists():
            sys.exit(f"{c['name']}: {data / c['scan']} is missing (--data, STEERSEG_DATA_DIR)")
    results = [run_case(args, c, data, out) for c in cases]
    by_name = {c["name"]: c for c in cases}
    (out / "steering.json").write_text(json.dumps(results, indent=1) + "\n")
    protocol = "Box protocol (the label's bounding box first)" if args.box else "Clicks protocol"
    md = (f"{protocol}, {datetime.date.today()}: {args.clicks} corrections, at most "
          f"{args.max_iterations} iterations after each.\n\n{table(results, by_name)}\n")
    peers = peers_table(results)
    if peers:
        md += f"\n{peers}\n"
    (out / "steering.md").write_text(md)
    plotted = plot(results, out / "steering.png")
    print(md)
    if plotted:
        print(f"plot: {out / 'steering.png'}")
    failed = any("error" in r or "error" in r.get("peer", {}) for r in results)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
