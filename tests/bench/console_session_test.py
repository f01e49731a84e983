#!/usr/bin/env python3
"""Where bench/steering/console_session.py taps (issue 51's held-out session on our own cases):
on a synthetic anisotropic ellipsoid the probe and seed go to its deepest voxel and the three
outside marks lie outside it, 3 mm beyond its edge on that slice; the session's script says the
taps in the operator's order. The kiosk run itself is the benchmark's, not this test's.

Exit 77 (CTest's skip) without nibabel or scipy, but 1 (a failure) under
STEERSEG_REQUIRE_DATA=1 or CI, where they must be installed (tools/install-deps.sh).
"""
import math
import sys
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_python import require  # noqa: E402

require(["numpy", "nibabel", "scipy"], "python3-nibabel python3-scipy")
import numpy as np  # noqa: E402
import console_session as session  # noqa: E402


def ellipsoid(dims, centre, radii_mm, spacing):
    idx = np.indices(dims).astype(float)
    q = sum(((idx[a] - centre[a]) * spacing[a] / radii_mm[a]) ** 2 for a in range(3))
    return q <= 1.0


class Taps(unittest.TestCase):
    def test_probe_at_the_deepest_voxel_and_marks_just_beyond_the_edge(self):
        spacing = np.array([1.0, 1.0, 3.0])
        dims, centre = (48, 48, 16), (20, 24, 8)
        label = ellipsoid(dims, centre, (12.0, 9.0, 15.0), spacing)
        # A small second part: the taps follow the largest.
        label[40:43, 40:43, 2:4] = True
        deepest, marks = session.taps(label, spacing)
        self.assertEqual(deepest, centre)
        self.assertEqual(len(marks), 3)
        for degrees, mark in zip((0, 120, 240), marks):
            self.assertEqual(mark[2], centre[2])  # on the seed's slice
            self.assertFalse(label[mark], mark)
            # 3 mm beyond the edge along its direction: the ellipse's radius there plus 3.
            a = math.radians(degrees)
            edge = 1.0 / math.hypot(math.cos(a) / 12.0, math.sin(a) / 9.0)
            got = math.hypot(mark[0] - centre[0], mark[1] - centre[1])
            self.assertAlmostEqual(got, edge + 3.0, delta=1.5)

    def test_an_empty_label_is_refused(self):
        with self.assertRaises(SystemExit):
            session.taps(np.zeros((8, 8, 8), dtype=bool), np.ones(3))

    def test_the_script_taps_in_the_operators_order(self):
        text = session.session_text("/scan.nii.gz", (1, 2, 3), [(4, 5, 3), (6, 7, 3), (8, 9, 3)],
                                    None, "/out/mask.nii.gz")
        lines = text.splitlines()
        self.assertEqual(lines[:5], ["load /scan.nii.gz", "wait loaded timeout 600",
                                     "speed classify", "probe 1 2 3", "seed 1 2 3"])
        self.assertEqual(lines[5:8], ["outside 4 5 3", "outside 6 7 3", "outside 8 9 3"])
        self.assertEqual(lines[8], "run")
        self.assertIn("export /out/mask.nii.gz", lines)
        self.assertEqual(lines[-1], "quit")
        sized = session.session_text("/s", (1, 2, 3), [], 10.0, "/m")
        self.assertIn("seed 1 2 3 10.0", sized.splitlines())


if __name__ == "__main__":
    unittest.main(verbosity=2)
