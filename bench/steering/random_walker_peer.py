#!/usr/bin/env python3
"""A classical peer for the clicks protocol (issue 51, docs/steering.md "A classical peer"):
scikit-image's random walker (Grady 2006) replays the level set's own prompts from a
steering_bench report, cumulatively, step by step, and is scored as the C++ bench scores.

  random_walker_peer.py --scan SCAN --reference LABEL [--reference-label N] --report R.json
                        [--out PEER.json] [--beta B] [--margin M] [--mode cg_j|cg_mg]
  random_walker_peer.py ... --sweep-beta 30,130,500 --sweep-margin 5,10,20   (the choice below)

Prompts. Foreground seeds: the spheres of the initial and positive clicks; background seeds: the
negative clicks' spheres and, with a box prompt (the report's "box": [i0, j0, k0, i1, j1, k1],
inclusive; clicks[0] of kind "box" has no sphere), every voxel outside the box. A later click's
sphere overwrites an earlier one's voxels, as the robot's clicks follow each other. A sphere's
voxels are the product's (model::Sphere, app/model/level_set_params.hpp): radius in voxels
along the finest axis, round in mm, the scale and radius in float32 as the product holds them,
sphereVoxelBox then sphereHolds. A box's step also gives foreground: the spheres the level set
took from the box as the structure (the report's box step "box_inside": its seed's probe and
the places that read the box's dominant tissue, app/workflow/workflow_box.cpp), so that both
start from the same derived prompt; a report without them (an older bench) gives a ball at the
box's centre, a quarter of its smallest side (in mm) in radius.

Region. The walker runs over a crop: the box grown by M voxels, or, without a box (the
click-only protocol), the reference label's bounding box grown by M with the crop's six faces
as background: an ORACLE region (it comes from the label), which the tables say. Either is
grown to hold every click's sphere so far (a click outside it would be lost). Outside the crop
the prediction is background. With a box, M only adds background seeds beyond the box's first
layer and changes nothing inside (the walker's unknowns see their seeded neighbours only).

Scores. Dice and the normalised surface Dice (default: the report's nsd_tolerance_mm, 2 mm)
on the whole grid, with bench/steering/click_robot.cpp's definitions (surface: inside voxels
with a face neighbour outside or on the grid's edge; exact Euclidean distance in mm compared in
float32); the summary is steering_bench's (bench::challengeScores: DSC_AUC and NSD_AUC the
trapezoid over corrections 1..5, an NSD counting 0 where its step's Dice <= 0.2; total_seconds
of steps 0..5). Seconds: the seeds and the walker's solve, one CPU process, per step from
scratch (skimage keeps nothing between calls).

Reading. The product's NIfTI reader (app/scan/nifti_reader.cpp) keeps the file's storage order
(i fastest) without reorienting, so its voxel (i, j, k) is nibabel's array [i, j, k]; spacing is
the affine's column lengths, as the reader's geometryFromAffine. Checked on every run: each
click's voxel lies in the label as its kind says, the initial prompt's component has the
report's voxel count, and the report's paint-only baseline (a box step: the box filled)
recomputed here gives the report's Dice and NSD at every step (--no-check skips this).

Beta and margin: chosen once, on liver-ct of bench/accuracy/cases.toml (the TotalSegmentator CT,
3 mm, label 5; the level set's prompts of 2026-12-03, 5 corrections), never per case. The sweep
(click-only protocol, so over the oracle region), 3-9 s for the six steps each:
  the betas at margin 10, then the margins at beta 30 and 130 (final DSC, DSC_AUC + NSD_AUC):
    beta     10: 0.727, 2.75 + 1.02    30: 0.727, 2.76 + 1.03    130: 0.718, 2.73 + 0.91
            500: 0.628, 2.46 + 0.41  2000: 0.519, 2.03 + 0.31   8000: 0.489, 1.93 + 0.33
    margin (beta 30):  1: 0.742, 2.80 + 1.15   2: 0.739, 2.82 + 1.15   3: 0.736, 2.82 + 1.13
                       5: 0.730, 2.77 + 1.04  10: 0.727, 2.76 + 1.03  20: 0.727, 2.76 + 1.04
    margin (beta 130): 1: 0.740, 2.80 + 1.08   2: 0.739, 2.83 + 1.06   3: 0.735, 2.82 + 1.02
                       5: 0.723, 2.75 + 0.91  10: 0.718, 2.73 + 0.91  20: 0.716, 2.73 + 0.92
  (beta 500 at margins 1 and 3: 2.52 + 0.50, 2.51 + 0.42.) The level set on the same prompts:
  0.944, 3.64 + 1.95. Clipping the crop's intensities to its 1-99 % or 5-95 % percentiles
  first changed the final DSC by at most 0.052 (beta 2000), 0.006 at beta 30-130: not kept.
  The criterion: the largest DSC_AUC + NSD_AUC, the challenge's two curves.
Chosen: beta 30, margin 2 voxels. From beta 500 up the scores fall; below 130 beta hardly
matters. A larger margin lowers the final DSC by at most 0.015.
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

BETA = 30.0  # chosen on liver-ct (the docstring)
MARGIN = 2  # voxels, chosen with BETA


# ---------------------------------------------------------------- reading


def load(path, squeeze=True):
    """(array indexed [i, j, k] as the product's reader, spacing in mm)."""
    import nibabel as nib
    img = nib.load(str(path))
    data = np.asanyarray(img.get_fdata(dtype=np.float64))
    while squeeze and data.ndim > 3 and data.shape[-1] == 1:
        data = data[..., 0]
    if data.ndim != 3:
        raise ValueError(f"{path}: a 3D volume expected, shape {data.shape}")
    # The reader's spacing: the index-to-world affine's column lengths (scan/affine.cpp).
    spacing = np.linalg.norm(np.asarray(img.affine, dtype=np.float64)[:3, :3], axis=0)
    return data, spacing


def reference_voxels(values, label):
    """core/mask_overlap.cpp's rule: lround(value) == label, or non-zero when label < 0."""
    if label is None or label < 0:
        return values != 0
    # std::lround rounds halves away from zero (numpy's rint would round them to even).
    rounded = np.sign(values) * np.floor(np.abs(values) + 0.5)
    return rounded == label


# ---------------------------------------------------------------- spheres


def sphere_scale(spacing):
    """model::sphereScale: a voxel step along each axis in finest-axis units, in float32."""
    s = np.asarray(spacing, dtype=np.float64)
    if not np.all(np.isfinite(s)) or np.any(s <= 0):
        return np.ones(3, dtype=np.float32)
    return (s / s.min()).astype(np.float32)


def sphere_box(centre, radius, spacing, dims):
    """model::sphereVoxelBox (inclusive lo, hi; empty where hi < lo)."""
    scale = sphere_scale(spacing).astype(np.float64)
    c = np.asarray(centre, dtype=np.float32).astype(np.float64)
    half = float(np.float32(radius)) / scale
    lo = np.maximum(np.ceil(c - half).astype(int), 0)
    hi = np.minimum(np.floor(c + half).astype(int), np.asarray(dims) - 1)
    return lo, hi


def sphere_voxels(centre, radius, spacing, dims, rule="product"):
    """The voxels (lo, boolean block over lo..hi) of a sphere edit.

    rule "product": the product's sphere (model::Sphere in float32, sphereHolds: the squared
    norm in double against the float radius squared), what a click's seed or erase holds.
    rule "paint": steering_bench's paint-only brush (bench::paintSphere: glm::length in double
    against the double radius), for checking the report's baseline."""
    scale = sphere_scale(spacing).astype(np.float64)
    if rule == "product":
        c = np.asarray(centre, dtype=np.float32).astype(np.float64)
        r = float(np.float32(radius))
        lo, hi = sphere_box(centre, radius, spacing, dims)
    else:
        c = np.asarray(centre, dtype=np.float64)
        r = float(radius)
        lo = np.maximum(np.ceil(c - r / scale).astype(int), 0)
        hi = np.minimum(np.floor(c + r / scale).astype(int), np.asarray(dims) - 1)
    if np.any(hi < lo):
        return lo, np.zeros((0, 0, 0), dtype=bool)
    dx = (np.arange(lo[0], hi[0] + 1) - c[0]) * scale[0]
    dy = (np.arange(lo[1], hi[1] + 1) - c[1]) * scale[1]
    dz = (np.arange(lo[2], hi[2] + 1) - c[2]) * scale[2]
    # glm::dot's order: x*x + y*y + z*z.
    sq = dx[:, None, None] ** 2 + dy[None, :, None] ** 2 + dz[None, None, :] ** 2
    inside = sq <= r * r if rule == "product" else np.sqrt(sq) <= r
    return lo, inside


def paint(array, lo, inside, value):
    """array[sphere] = value, for a sphere from sphere_voxels (lo in array's indices; the part
    outside the array is dropped)."""
    lo = np.asarray(lo)
    hi = lo + np.asarray(inside.shape)
    a_lo = np.maximum(lo, 0)
    a_hi = np.minimum(hi, array.shape)
    if np.any(a_hi <= a_lo):
        return
    block = inside[a_lo[0] - lo[0]:a_hi[0] - lo[0], a_lo[1] - lo[1]:a_hi[1] - lo[1],
                   a_lo[2] - lo[2]:a_hi[2] - lo[2]]
    view = array[a_lo[0]:a_hi[0], a_lo[1]:a_hi[1], a_lo[2]:a_hi[2]]
    view[block] = value


# ---------------------------------------------------------------- scores (click_robot.cpp)


def dice(a, b):
    na, nb = int(np.count_nonzero(a)), int(np.count_nonzero(b))
    both = int(np.count_nonzero(np.logical_and(a, b)))
    return 1.0 if na + nb == 0 else 2.0 * both / (na + nb)


def surface(m):
    """Inside voxels with a face neighbour outside, or on the grid's edge (bench surfaceOf)."""
    p = np.pad(np.asarray(m, dtype=bool), 1)  # the grid's edge: an outside neighbour
    c = p[1:-1, 1:-1, 1:-1]
    interior = (p[:-2, 1:-1, 1:-1] & p[2:, 1:-1, 1:-1] & p[1:-1, :-2, 1:-1] &
                p[1:-1, 2:, 1:-1] & p[1:-1, 1:-1, :-2] & p[1:-1, 1:-1, 2:])
    return c & ~interior


def surface_dice(a, b, spacing, tolerance_mm, surface_b=None):
    from scipy import ndimage
    sa = surface(a)
    sb = surface(b) if surface_b is None else surface_b
    na, nb = int(np.count_nonzero(sa)), int(np.count_nonzero(sb))
    if na + nb == 0:
        return 1.0
    if na == 0 or nb == 0:
        return 0.0
    # Every site lies in the surfaces' bounding box, so the exact distances of its voxels to
    # the nearest site are those on the whole grid.
    where = np.nonzero(sa | sb)
    box = tuple(slice(int(w.min()), int(w.max()) + 1) for w in where)
    sa_c, sb_c = sa[box], sb[box]
    sampling = np.asarray(spacing, dtype=np.float64)
    to_b = ndimage.distance_transform_edt(~sb_c, sampling=sampling)
    to_a = ndimage.distance_transform_edt(~sa_c, sampling=sampling)
    # The bench keeps the distances in float32 before comparing (distanceToSitesMm).
    tol = float(tolerance_mm)
    close = int(np.count_nonzero(to_b[sa_c].astype(np.float32).astype(np.float64) <= tol))
    close += int(np.count_nonzero(to_a[sb_c].astype(np.float32).astype(np.float64) <= tol))
    return close / (na + nb)


def dice_auc(dices, points=6):
    n = min(points, len(dices))
    return sum(0.5 * (dices[p - 1] + dices[p]) for p in range(1, n))


def challenge_scores(dices, nsds, corrections=5):
    """bench::challengeScores: steps 1..corrections, NSD 0 where the step's Dice <= 0.2."""
    steps = min(len(dices), len(nsds), corrections + 1)
    if steps < 2:
        return {"dsc_auc": 0.0, "nsd_auc": 0.0, "final_dsc": 0.0, "final_nsd": 0.0}
    dsc = list(dices[1:steps])
    nsd = [n if d > 0.2 else 0.0 for d, n in zip(dsc, nsds[1:steps])]
    return {"dsc_auc": dice_auc(dsc, len(dsc)), "nsd_auc": dice_auc(nsd, len(nsd)),
            "final_dsc": dsc[-1], "final_nsd": nsd[-1]}


def summary(dices, nsds, seconds):
    def after(k):
        return dices[min(k, len(dices) - 1)] if dices else None
    s = {"dice_initial": after(0), "dice_after_5": after(5), "dice_after_10": after(10),
         "dice_auc_6": dice_auc(dices)}
    s.update(challenge_scores(dices, nsds))
    s["total_seconds"] = sum(seconds[:6])  # the initial prompt's and five corrections' runs
    return s


# ---------------------------------------------------------------- prompts


def is_foreground(click):
    return click["kind"] in ("initial", "positive")


def check_prompts(report, label):
    """The index order: every click's voxel on the label's side its kind says, and the initial
    prompt's component of the report's size. A reader that reorients would fail here."""
    from scipy import ndimage
    problems = []
    for c in report["clicks"]:
        if c["kind"] == "box":
            continue
        i, j, k = c["voxel"]
        if not (0 <= i < label.shape[0] and 0 <= j < label.shape[1] and 0 <= k < label.shape[2]):
            problems.append(f"click {c['click']}: voxel {c['voxel']} outside {label.shape}")
        elif bool(label[i, j, k]) != is_foreground(c):
            problems.append(f"click {c['click']} ({c['kind']}): the label there is "
                            f"{int(label[i, j, k])}")
    first = report["clicks"][0] if report["clicks"] else None
    if first is not None and first["kind"] == "initial" and "component_voxels" in first:
        parts, n = ndimage.label(label, structure=np.ones((3, 3, 3), dtype=bool))
        largest = int(np.bincount(parts.ravel())[1:].max()) if n else 0
        if largest != first["component_voxels"]:
            problems.append(f"the label's largest component has {largest} voxels, the report "
                            f"{first['component_voxels']}")
    if problems:
        raise ValueError("the report's prompts do not fit the label as read: " +
                         "; ".join(problems))


def check_paint(clicks, label, spacing, tolerance_mm, dims):
    """steering_bench's paint-only masks recomputed from its clicks: the largest difference
    from the report's Dice and NSD (the metrics and the sphere rule checked against C++).
    Paint only answers a box step with the box filled (steering_bench's paintBox)."""
    mask = np.zeros(dims, dtype=bool)
    sb = surface(label)
    worst = 0.0
    for c in clicks:
        if c["kind"] == "box":
            b = c["box"]
            mask[b[0]:b[3] + 1, b[1]:b[4] + 1, b[2]:b[5] + 1] = True
        else:
            lo, inside = sphere_voxels(c["voxel"], c["radius"], spacing, dims, rule="paint")
            paint(mask, lo, inside, c["kind"] != "negative")
        d = dice(mask, label)
        n = surface_dice(mask, label, spacing, tolerance_mm, surface_b=sb)
        worst = max(worst, abs(d - c["dice"]), abs(n - c["nsd"]))
    return worst


def region_of(report, label, margin, dims):
    """(lo, hi inclusive, what): the walker's region before the clicks' spheres."""
    box = report.get("box")
    if box is not None:
        lo = np.asarray(box[:3], dtype=int)
        hi = np.asarray(box[3:], dtype=int)
        what = f"box + {margin} vx"
    else:
        where = np.argwhere(label)
        if where.size == 0:
            raise ValueError("the reference label is empty")
        lo, hi = where.min(axis=0), where.max(axis=0)
        what = f"label bbox + {margin} vx (oracle)"
    lo = np.maximum(lo - margin, 0)
    hi = np.minimum(hi + margin, np.asarray(dims) - 1)
    return lo, hi, what


def step_seeds(report, upto, label, spacing, margin):
    """The walker's crop (lo, hi inclusive) and seeds (0 unknown, 1 foreground, 2 background)
    after clicks[0..upto]."""
    dims = np.asarray(label.shape)
    lo, hi, _ = region_of(report, label, margin, dims)
    clicks = [c for c in report["clicks"][:upto + 1] if c["kind"] != "box"]
    spheres = [(c, *sphere_voxels(c["voxel"], c["radius"], spacing, dims)) for c in clicks]
    for _, s_lo, inside in spheres:  # grow the crop to hold every sphere
        if inside.size:
            lo = np.minimum(lo, s_lo)
            hi = np.maximum(hi, s_lo + np.asarray(inside.shape) - 1)
    seeds = np.zeros(tuple(hi - lo + 1), dtype=np.int32)
    box = report.get("box")
    if box is not None:
        b_lo = np.asarray(box[:3], dtype=int) - lo
        b_hi = np.asarray(box[3:], dtype=int) - lo + 1
        seeds[...] = 2
        seeds[max(b_lo[0], 0):b_hi[0], max(b_lo[1], 0):b_hi[1], max(b_lo[2], 0):b_hi[2]] = 0
        inside = report["clicks"][0].get("box_inside")
        if inside is None:
            paint(seeds, *box_centre_ball(box, spacing, dims, lo))
        for e in inside or []:
            s_lo, ball = sphere_voxels(e[:3], e[3], spacing, dims)
            paint(seeds, s_lo - lo, ball, 1)
    else:
        # The oracle region's faces are background.
        seeds[0, :, :] = seeds[-1, :, :] = 2
        seeds[:, 0, :] = seeds[:, -1, :] = 2
        seeds[:, :, 0] = seeds[:, :, -1] = 2
    for c, s_lo, inside in spheres:
        paint(seeds, s_lo - lo, inside, 1 if is_foreground(c) else 2)
    return lo, hi, seeds


def box_centre_ball(box, spacing, dims, lo):
    """(offset in the crop, voxels, 1): the foreground ball a box gives (the docstring)."""
    b_lo, b_hi = np.asarray(box[:3], dtype=float), np.asarray(box[3:], dtype=float)
    side_mm = float(np.min((b_hi - b_lo + 1.0) * np.asarray(spacing, dtype=float)))
    radius = max(0.25 * side_mm / float(np.min(spacing)), 0.5)
    s_lo, inside = sphere_voxels(list(0.5 * (b_lo + b_hi)), radius, spacing, dims)
    return s_lo - lo, inside, 1


def walker_mode():
    try:
        import pyamg  # noqa: F401  (cg_mg needs it)
        return "cg_mg"
    except ImportError:
        return "cg_j"


def segment(scan, lo, hi, seeds, spacing, beta, mode):
    """The walker's foreground over the crop (boolean, the crop's shape)."""
    from skimage.segmentation import random_walker
    if not np.any(seeds == 1):
        return np.zeros(seeds.shape, dtype=bool)  # nothing says what the foreground is
    if not np.any(seeds == 2):
        return np.ones(seeds.shape, dtype=bool)  # one label reaches everything
    data = scan[lo[0]:hi[0] + 1, lo[1]:hi[1] + 1, lo[2]:hi[2] + 1].astype(np.float64)
    # Spacing relative to the finest axis, so that beta means what it means on an isotropic
    # grid in voxel steps (skimage divides each difference by its axis's spacing).
    rel = np.asarray(spacing, dtype=np.float64) / float(np.min(spacing))
    out = random_walker(data, seeds, beta=beta, mode=mode, tol=1e-3, copy=True, spacing=rel)
    return out == 1


def replay(scan, label, spacing, report, beta=BETA, margin=MARGIN, mode=None,
           tolerance_mm=None, clicks=None):
    """The peer's entries and summary for the report's prompts (the first `clicks` + 1 steps)."""
    mode = mode or walker_mode()
    dims = label.shape
    tol = float(tolerance_mm if tolerance_mm is not None
                else report.get("nsd_tolerance_mm", 2.0))
    sb = surface(label)
    steps = report["clicks"] if clicks is None else report["clicks"][:clicks + 1]
    entries, dices, nsds, seconds = [], [], [], []
    for n, c in enumerate(steps):
        start = time.perf_counter()
        lo, hi, seeds = step_seeds(report, n, label, spacing, margin)
        crop = segment(scan, lo, hi, seeds, spacing, beta, mode)
        took = time.perf_counter() - start
        mask = np.zeros(dims, dtype=bool)
        mask[lo[0]:hi[0] + 1, lo[1]:hi[1] + 1, lo[2]:hi[2] + 1] = crop
        d = dice(mask, label)
        s = surface_dice(mask, label, spacing, tol, surface_b=sb)
        entries.append({"click": c["click"], "kind": c["kind"], "voxel": c.get("voxel"),
                        "radius": c.get("radius"), "dice": d, "nsd": s, "seconds": took,
                        "mask_voxels": int(np.count_nonzero(mask)),
                        "crop": [*map(int, lo), *map(int, hi)],
                        "foreground_seeds": int(np.count_nonzero(seeds == 1)),
                        "background_seeds": int(np.count_nonzero(seeds == 2))})
        dices.append(d)
        nsds.append(s)
        seconds.append(took)
    return {"method": "random walker", "beta": beta, "margin": margin, "mode": mode,
            "region": region_of(report, label, margin, dims)[2], "nsd_tolerance_mm": tol,
            "clicks": entries, "summary": summary(dices, nsds, seconds)}


def run(args):
    import skimage
    report = json.loads(Path(args.report).read_text())
    scan, _ = load(args.scan)
    values, spacing = load(args.reference)
    if scan.shape != values.shape:
        raise ValueError(f"the scan {scan.shape} and the reference {values.shape} differ")
    label = reference_voxels(values, args.reference_label
                             if args.reference_label is not None
                             else report.get("reference_label", -1))
    check_prompts(report, label)
    tol = args.nsd_mm if args.nsd_mm is not None else report.get("nsd_tolerance_mm", 2.0)
    check = None
    if not args.no_check:
        # A level set's report carries paint only under "baseline"; a --paint-only one is it.
        base = report.get("baseline", report)
        if base.get("clicks"):
            worst = check_paint(base["clicks"], label, spacing, tol, label.shape)
            if worst > 1e-9:
                raise ValueError(f"paint only recomputed differs from the report by {worst:g}: "
                                 "the metrics, the sphere rule or the index order differ")
            check = f"paint only recomputed: largest difference {worst:.1e}"
    if args.sweep_beta or args.sweep_margin:
        betas = [float(b) for b in (args.sweep_beta or str(args.beta)).split(",")]
        margins = [int(m) for m in (args.sweep_margin or str(args.margin)).split(",")]
        rows = []
        for b in betas:
            for m in margins:
                p = replay(scan, label, spacing, report, b, m, args.mode, tol, args.clicks)
                s = p["summary"]
                rows.append({"beta": b, "margin": m, **s})
                print(f"beta {b:g} margin {m}: final DSC {s['final_dsc']:.3f} NSD "
                      f"{s['final_nsd']:.3f} DSC_AUC {s['dsc_auc']:.2f} NSD_AUC "
                      f"{s['nsd_auc']:.2f} Dice 0 {s['dice_initial']:.3f} "
                      f"{s['total_seconds']:.1f} s", flush=True)
        if args.out:
            Path(args.out).write_text(json.dumps(rows, indent=1) + "\n")
        return 0
    peer = replay(scan, label, spacing, report, args.beta, args.margin, args.mode, tol,
                  args.clicks)
    peer["library"] = f"scikit-image {skimage.__version__}"
    peer["check"] = check
    text = json.dumps(peer, indent=1) + "\n"
    if args.out:
        Path(args.out).write_text(text)
    s = peer["summary"]
    print(f"random walker (beta {peer['beta']:g}, {peer['region']}, {peer['mode']}): "
          f"final DSC {s['final_dsc']:.3f} NSD {s['final_nsd']:.3f}, DSC_AUC "
          f"{s['dsc_auc']:.2f} NSD_AUC {s['nsd_auc']:.2f}, {s['total_seconds']:.1f} s"
          + (f"; {check}" if check else ""), file=sys.stderr)
    if not args.out:
        sys.stdout.write(text)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scan", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--reference-label", type=int, default=None,
                    help="default: the report's reference_label")
    ap.add_argument("--report", required=True, help="steering_bench's report")
    ap.add_argument("--out", help="the peer's JSON (default: stdout)")
    ap.add_argument("--beta", type=float, default=BETA)
    ap.add_argument("--margin", type=int, default=MARGIN)
    ap.add_argument("--mode", choices=["cg_j", "cg_mg", "cg", "bf"], default=None,
                    help="default: cg_mg where pyamg is installed, else cg_j")
    ap.add_argument("--nsd-mm", type=float, default=None,
                    help="default: the report's nsd_tolerance_mm")
    ap.add_argument("--clicks", type=int, default=None, help="the first N corrections only")
    ap.add_argument("--no-check", action="store_true",
                    help="skip recomputing the report's paint-only baseline")
    ap.add_argument("--sweep-beta", help="comma-separated betas: print the scores of each")
    ap.add_argument("--sweep-margin", help="comma-separated margins: print the scores of each")
    args = ap.parse_args()
    try:
        return run(args)
    except (ValueError, OSError) as e:
        print(f"random_walker_peer: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
