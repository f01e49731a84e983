#!/usr/bin/env python3
"""The random walker peer's reading of prompts (bench/steering/random_walker_peer.py) on
synthetic volumes whose answers are known: the product's sphere rule at chosen voxels, the box's
outside as background, the walker finding a bright ellipsoid on an anisotropic grid from a box
and a few clicks, Dice, NSD and the challenge's scores worked out by hand on tiny masks.

  random_walker_peer_test.py [STEERING_BENCH]

With STEERING_BENCH (CTest passes build's bench/steering_bench where benchmarks are built), the
C++ bench's own figures too: `steering_bench --paint-only` (no GPU) on a synthetic anisotropic
NIfTI pair, whose every step's Dice and NSD the peer must recompute exactly.

Exit 77 (CTest's skip) without scikit-image, nibabel or scipy, but 1 (a failure) under
STEERSEG_REQUIRE_DATA=1 or CI, where they must be installed (tools/install-deps.sh).
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_python import require  # noqa: E402

require(["numpy", "nibabel", "scipy", "skimage"], "python3-skimage python3-nibabel")
import numpy as np  # noqa: E402
import random_walker_peer as peer  # noqa: E402

STEERING_BENCH = None


def cube(dims, lo, hi):
    m = np.zeros(dims, dtype=bool)
    m[lo[0]:hi[0] + 1, lo[1]:hi[1] + 1, lo[2]:hi[2] + 1] = True
    return m


def sphere_set(centre, radius, spacing, dims, rule="product"):
    lo, inside = peer.sphere_voxels(centre, radius, spacing, dims, rule)
    return {tuple(int(x) for x in lo + idx) for idx in np.argwhere(inside)}


class Spheres(unittest.TestCase):
    def test_round_in_mm_with_radius_along_the_finest_axis(self):
        # 1 x 1 x 3 mm: radius 6 spans 6 pixels and 2 slices (model::Sphere's example).
        dims, c = (40, 40, 20), (20, 20, 10)
        s = sphere_set(c, 6, (1.0, 1.0, 3.0), dims)
        at = lambda di, dj, dk: (c[0] + di, c[1] + dj, c[2] + dk)  # noqa: E731
        self.assertIn(at(6, 0, 0), s)       # 6 on the surface: inside
        self.assertNotIn(at(7, 0, 0), s)
        self.assertIn(at(0, 0, 2), s)       # 2 slices = 6 mm
        self.assertNotIn(at(0, 0, 3), s)    # 9 mm
        self.assertIn(at(4, 3, 1), s)       # 16 + 9 + 9 = 34 <= 36
        self.assertNotIn(at(4, 4, 1), s)    # 16 + 16 + 9 = 41
        self.assertEqual(max(v[2] for v in s) - min(v[2] for v in s), 4)

    def test_scale_in_float32_as_the_product_holds_it(self):
        # 2.1 / 0.7 is 3.0000000000000004 in double, 3 in float32 (glm::vec3): the voxel one
        # slice off a radius-3 centre lies exactly on the product's sphere, outside a double one.
        dims, c = (16, 16, 8), (8, 8, 4)
        s = sphere_set(c, 3, (0.7, 0.7, 2.1), dims)
        self.assertGreater((2.1 / 0.7) ** 2, 9.0)  # the edge is real in double
        self.assertIn((8, 8, 5), s)
        self.assertIn((8, 8, 3), s)
        self.assertNotIn((8, 8, 6), s)
        # The radius too is the product's float: 2.9999999 rounds to 3.0 in float32.
        self.assertIn((11, 8, 4), sphere_set(c, 2.9999999, (1.0, 1.0, 1.0), dims))
        self.assertNotIn((11, 8, 4), sphere_set(c, 2.9999999, (1.0, 1.0, 1.0), dims, "paint"))

    def test_clipped_at_the_grid(self):
        s = sphere_set((0, 0, 0), 2, (1.0, 1.0, 1.0), (5, 5, 5))
        self.assertEqual(len(s), 11)  # the octant of a radius-2 ball: 1 + 3 + 3 + 3 + 1
        self.assertTrue(all(min(v) >= 0 for v in s))


class Scores(unittest.TestCase):
    # a: the cube 1..4 (64 voxels, surface 56), b: the cube 1..3 (27, surface 26) in 6^3.
    dims = (6, 6, 6)

    def masks(self):
        return cube(self.dims, (1, 1, 1), (4, 4, 4)), cube(self.dims, (1, 1, 1), (3, 3, 3))

    def test_dice(self):
        a, b = self.masks()
        self.assertAlmostEqual(peer.dice(a, b), 54 / 91, places=15)
        self.assertEqual(peer.dice(np.zeros(self.dims, bool), np.zeros(self.dims, bool)), 1.0)

    def test_surface_counts_the_grid_edge(self):
        a, b = self.masks()
        self.assertEqual(int(peer.surface(a).sum()), 56)
        self.assertEqual(int(peer.surface(b).sum()), 26)
        whole = np.ones((3, 3, 3), dtype=bool)
        self.assertEqual(int(peer.surface(whole).sum()), 26)  # the centre alone is inside

    def test_surface_dice_by_hand(self):
        a, b = self.masks()
        one = (1.0, 1.0, 1.0)
        # 0.5 mm: the 19 voxels both surfaces share (a coordinate 1), from each side: 38 / 82.
        self.assertAlmostEqual(peer.surface_dice(a, b, one, 0.5), 38 / 82, places=15)
        # 1 mm: a's voxels with two or three coordinates 4 are sqrt(2), sqrt(3) from b (10 of
        # them); every b voxel is within 1 of a's surface: (46 + 26) / 82.
        self.assertAlmostEqual(peer.surface_dice(a, b, one, 1.0), 72 / 82, places=15)
        # 1 x 1 x 2 mm, 1.5 mm: a's surface voxel is sqrt(#(i = 4) + #(j = 4) + 4 #(k = 4))
        # from b's; far are the 16 of the face k = 4 (i = j = 4 below it: sqrt 2, close). Every
        # b voxel is 1 mm from a's surface along i: (56 - 16 + 26) / 82.
        self.assertAlmostEqual(peer.surface_dice(a, b, (1.0, 1.0, 2.0), 1.5), 66 / 82,
                               places=15)
        empty = np.zeros(self.dims, dtype=bool)
        self.assertEqual(peer.surface_dice(empty, b, one, 2.0), 0.0)
        self.assertEqual(peer.surface_dice(empty, empty, one, 2.0), 1.0)

    def test_challenge_scores(self):
        dices = [0.1, 0.15, 0.5, 0.6, 0.7, 0.8, 0.9]
        nsds = [0.9, 0.9, 0.2, 0.3, 0.4, 0.5, 0.6]
        s = peer.summary(dices, nsds, [1.0] * 7)
        # Steps 1..5: the trapezoid over 0.15, 0.5, 0.6, 0.7, 0.8; NSD 0 where Dice <= 0.2.
        self.assertAlmostEqual(s["dsc_auc"], 0.325 + 0.55 + 0.65 + 0.75, places=12)
        self.assertAlmostEqual(s["nsd_auc"], 0.1 + 0.25 + 0.35 + 0.45, places=12)
        self.assertEqual((s["final_dsc"], s["final_nsd"]), (0.8, 0.5))
        self.assertEqual(s["total_seconds"], 6.0)
        self.assertEqual(s["dice_after_10"], 0.9)  # fewer steps: the last


def ellipsoid_case():
    """A bright ellipsoid (semi-axes 12, 9, 10 mm) in noise on a 0.8 x 0.8 x 2.5 mm grid."""
    dims, spacing = (48, 40, 16), (0.8, 0.8, 2.5)
    idx = np.indices(dims).astype(float)
    centre = (24, 20, 8)
    r = sum(((idx[a] - centre[a]) * spacing[a] / semi) ** 2
            for a, semi in enumerate((12.0, 9.0, 10.0)))
    label = r <= 1.0
    rng = np.random.default_rng(51)
    scan = np.where(label, 100.0, 20.0) + rng.normal(0.0, 10.0, dims)
    return scan, label, spacing, centre


class PaintCheck(unittest.TestCase):
    def test_a_box_step_is_the_box_filled(self):
        # The label is a cube and the box its bounding box: paint only's box is the label
        # (Dice 1, NSD 1); a radius-1 erase at (3, 3, 3) takes 7 voxels of 64 (Dice 114/121),
        # and every surface voxel of either stays within 2 mm of the other's (the hole is at
        # most 1 voxel from the cube's shell): NSD 1.
        dims = (8, 8, 8)
        label = cube(dims, (2, 2, 2), (5, 5, 5))
        clicks = [{"click": 0, "kind": "box", "box": [2, 2, 2, 5, 5, 5], "dice": 1.0,
                   "nsd": 1.0},
                  {"click": 1, "kind": "negative", "voxel": [3, 3, 3], "radius": 1.0,
                   "dice": 114 / 121, "nsd": 1.0}]
        one = (1.0, 1.0, 1.0)
        self.assertEqual(peer.check_paint(clicks, label, one, 2.0, dims), 0.0)
        clicks[0]["dice"] = 0.9
        self.assertAlmostEqual(peer.check_paint(clicks, label, one, 2.0, dims), 0.1)


class Prompts(unittest.TestCase):
    def setUp(self):
        self.scan, self.label, self.spacing, self.centre = ellipsoid_case()
        where = np.argwhere(self.label)
        lo, hi = where.min(axis=0) - 2, where.max(axis=0) + 2
        self.box = [*map(int, lo), *map(int, hi)]
        i, j, k = self.centre
        self.report = {"box": self.box, "nsd_tolerance_mm": 2.0, "clicks": [
            {"click": 0, "kind": "box"},
            {"click": 1, "kind": "positive", "voxel": [i, j, k], "radius": 4.0},
            {"click": 2, "kind": "negative", "voxel": [int(lo[0]) + 1, int(lo[1]) + 1, k],
             "radius": 2.0},
            {"click": 3, "kind": "positive", "voxel": [i + 8, j, k], "radius": 2.0}]}

    def test_check_prompts_reads_kinds_against_the_label(self):
        peer.check_prompts(self.report, self.label)
        wrong = json.loads(json.dumps(self.report))
        wrong["clicks"][2]["kind"] = "positive"  # its voxel lies outside the label
        with self.assertRaises(ValueError):
            peer.check_prompts(wrong, self.label)
        # A label read flipped along i (a reader that reorients) fails: a blob on one side
        # only, clicked, lies on the other side then.
        lopsided = self.label.copy()
        lopsided[2:5, 18:22, 6:10] = True
        clicked = {"clicks": [{"click": 0, "kind": "positive", "voxel": [3, 20, 8],
                               "radius": 1.0}]}
        peer.check_prompts(clicked, lopsided)
        with self.assertRaises(ValueError):
            peer.check_prompts(clicked, np.ascontiguousarray(lopsided[::-1]))

    def test_box_outside_is_background_and_spheres_are_the_products(self):
        margin = 3
        lo, hi, seeds = peer.step_seeds(self.report, 3, self.label, self.spacing, margin)
        b = np.asarray(self.box)
        np.testing.assert_array_equal(lo, np.maximum(b[:3] - margin, 0))
        np.testing.assert_array_equal(hi, np.minimum(b[3:] + margin,
                                                     np.asarray(self.label.shape) - 1))
        inside_box = np.zeros(seeds.shape, dtype=bool)
        inside_box[b[0] - lo[0]:b[3] - lo[0] + 1, b[1] - lo[1]:b[4] - lo[1] + 1,
                   b[2] - lo[2]:b[5] - lo[2] + 1] = True
        self.assertTrue(np.all(seeds[~inside_box] == 2))
        # Inside the box: exactly the product's spheres, foreground and background, and the
        # box's centre ball (a quarter of its smallest side in mm), which the negative click
        # may overwrite.
        fg = {tuple(int(x) for x in v + lo) for v in np.argwhere(seeds == 1)}
        side_mm = min((b[a + 3] - b[a] + 1) * self.spacing[a] for a in range(3))
        neg = self.report["clicks"][2]
        expect_fg = sphere_set([0.5 * (b[a] + b[a + 3]) for a in range(3)],
                               0.25 * side_mm / min(self.spacing), self.spacing,
                               self.label.shape)
        expect_fg -= sphere_set(neg["voxel"], neg["radius"], self.spacing, self.label.shape)
        for c in self.report["clicks"]:
            if c["kind"] == "positive":
                expect_fg |= sphere_set(c["voxel"], c["radius"], self.spacing, self.label.shape)
        self.assertEqual(fg, expect_fg)
        bg_in_box = {tuple(int(x) for x in v + lo) for v in np.argwhere((seeds == 2) & inside_box)}
        self.assertEqual(bg_in_box, {v for v in sphere_set(neg["voxel"], neg["radius"],
                                                           self.spacing, self.label.shape)
                                     if all(b[a] <= v[a] <= b[a + 3] for a in range(3))})
        # Known voxels of the first click (radius 4 along 0.8 mm: 3.2 mm; 2.5 mm slices):
        # (i + 4, j, k) on its surface, one slice up at (i + 2, j, k + 1): 1.6^2 + 2.5^2 <= 3.2^2.
        # (The box's centre ball covers these too: the first click's own sphere is checked.)
        i, j, k = self.centre
        first = self.report["clicks"][1]
        own = sphere_set(first["voxel"], first["radius"], self.spacing, self.label.shape)
        self.assertLessEqual(own, fg)
        for v in [(i + 4, j, k), (i, j - 4, k), (i + 2, j, k + 1), (i, j, k - 1)]:
            self.assertIn(v, own)
        for v in [(i + 5, j, k), (i, j, k + 2), (i + 3, j, k + 1)]:
            self.assertNotIn(v, own)

    def test_the_products_box_spheres_replace_the_centre_ball(self):
        # A bench that reports what the level set took from the box: exactly those spheres are
        # the box step's foreground, and no centre ball.
        report = json.loads(json.dumps(self.report))
        taken = [[20.0, 18.0, 8.0, 2.0], [23.0, 20.0, 8.0, 1.5]]
        report["clicks"][0]["box_inside"] = taken
        lo, hi, seeds = peer.step_seeds(report, 0, self.label, self.spacing, peer.MARGIN)
        fg = {tuple(int(x) for x in v + lo) for v in np.argwhere(seeds == 1)}
        expect = set()
        for e in taken:
            expect |= sphere_set(e[:3], e[3], self.spacing, self.label.shape)
        self.assertEqual(fg, expect)

    def test_the_box_alone_finds_the_ellipsoid_from_its_centre(self):
        out = peer.replay(self.scan, self.label, self.spacing, self.report, beta=peer.BETA,
                          margin=peer.MARGIN, mode="cg_j")
        steps = out["clicks"]
        self.assertEqual([c["kind"] for c in steps], ["box", "positive", "negative", "positive"])
        self.assertGreater(steps[0]["dice"], 0.95, steps)  # from the box's centre ball alone
        self.assertGreater(steps[1]["dice"], 0.95, steps)
        self.assertGreater(steps[3]["dice"], 0.95, steps)
        self.assertTrue(out["region"].startswith("box"))
        # The walker never reaches outside the box.
        b = self.box
        outside = np.ones(self.label.shape, dtype=bool)
        outside[b[0]:b[3] + 1, b[1]:b[4] + 1, b[2]:b[5] + 1] = False
        mask = np.zeros(self.label.shape, dtype=bool)
        # Recompute the last step's mask to check it: the seeds and the walker as replay does.
        lo, hi, seeds = peer.step_seeds(self.report, 3, self.label, self.spacing, peer.MARGIN)
        mask[lo[0]:hi[0] + 1, lo[1]:hi[1] + 1, lo[2]:hi[2] + 1] = peer.segment(
            self.scan, lo, hi, seeds, self.spacing, peer.BETA, "cg_j")
        self.assertFalse(np.any(mask & outside))
        self.assertEqual(int(mask.sum()), steps[3]["mask_voxels"])
        s = out["summary"]
        self.assertAlmostEqual(s["final_dsc"], steps[3]["dice"])
        self.assertAlmostEqual(s["dsc_auc"], 0.5 * (steps[1]["dice"] + steps[2]["dice"]) +
                               0.5 * (steps[2]["dice"] + steps[3]["dice"]))

    def test_click_only_region_is_the_labels_box_with_background_faces(self):
        report = {k: v for k, v in self.report.items() if k != "box"}
        report["clicks"] = [dict(self.report["clicks"][1], click=0, kind="initial")]
        lo, hi, seeds = peer.step_seeds(report, 0, self.label, self.spacing, 2)
        where = np.argwhere(self.label)
        np.testing.assert_array_equal(lo, np.maximum(where.min(axis=0) - 2, 0))
        np.testing.assert_array_equal(hi, np.minimum(where.max(axis=0) + 2,
                                                     np.asarray(self.label.shape) - 1))
        for face in (seeds[0], seeds[-1], seeds[:, 0], seeds[:, -1], seeds[:, :, 0],
                     seeds[:, :, -1]):
            self.assertTrue(np.all(face == 2))
        self.assertEqual(int((seeds[1:-1, 1:-1, 1:-1] == 2).sum()), 0)
        out = peer.replay(self.scan, self.label, self.spacing, report, mode="cg_j")
        self.assertIn("oracle", out["region"])
        self.assertGreater(out["clicks"][0]["dice"], 0.95)


class AgainstTheCppBench(unittest.TestCase):
    def test_paint_only_figures_recomputed_exactly(self):
        import nibabel as nib
        if not os.environ.get("STEERING_BENCH"):
            self.skipTest("no steering_bench given (a build without benchmarks)")
        scan, label, spacing, _ = ellipsoid_case()
        # Spacing anisotropic, as the 3 mm cases; label value 3, as the multi-label ones.
        with tempfile.TemporaryDirectory() as tmp:
            affine = np.diag([*spacing, 1.0])
            nib.save(nib.Nifti1Image(scan.astype(np.float32), affine), f"{tmp}/scan.nii.gz")
            nib.save(nib.Nifti1Image(label.astype(np.uint8) * 3, affine), f"{tmp}/label.nii.gz")
            report = Path(tmp) / "r.json"
            subprocess.run([os.environ["STEERING_BENCH"], "--input", f"{tmp}/scan.nii.gz",
                            "--reference", f"{tmp}/label.nii.gz", "--reference-label", "3",
                            "--paint-only", "--clicks", "4", "--report", str(report)],
                           check=True, stdout=subprocess.DEVNULL)
            r = json.loads(report.read_text())
            values, read_spacing = peer.load(f"{tmp}/label.nii.gz")
            np.testing.assert_allclose(read_spacing, spacing, rtol=1e-6)
            ref = peer.reference_voxels(values, 3)
            peer.check_prompts(r, ref)
            self.assertGreaterEqual(len(r["clicks"]), 3)
            worst = peer.check_paint(r["clicks"], ref, read_spacing, r["nsd_tolerance_mm"],
                                     ref.shape)
            self.assertLessEqual(worst, 1e-12)
            # The C++ NSD is not trivially 0 or 1 somewhere: the check compares real figures.
            self.assertTrue(any(0.0 < c["nsd"] < 1.0 for c in r["clicks"]), r["clicks"])
            # And the peer replays the report's own prompts.
            out = peer.replay(scan, ref, read_spacing, r, mode="cg_j")
            self.assertEqual(len(out["clicks"]), len(r["clicks"]))


if __name__ == "__main__":
    if len(sys.argv) > 1 and not sys.argv[1].startswith("-"):
        os.environ["STEERING_BENCH"] = sys.argv.pop(1)
    unittest.main(verbosity=2)
