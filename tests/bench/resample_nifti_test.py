#!/usr/bin/env python3
"""bench/kiosk/resample_nifti.py, which makes the finer-resampled scans that stand in for 512 x
512 series (docs/steering-log.md): a scan and its label resampled alike stay on one grid, the
label's values 0 and 1 only, the spacing scaled to cover the same millimetres.

Exit 77 (CTest's skip) without nibabel, but 1 (a failure) under STEERSEG_REQUIRE_DATA=1 or CI.
"""
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_python import ROOT, require  # noqa: E402

require(["numpy", "nibabel"], "python3-nibabel")
import nibabel as nib  # noqa: E402
import numpy as np  # noqa: E402

SCRIPT = ROOT / "bench" / "kiosk" / "resample_nifti.py"


def write(path, data, spacing):
    image = nib.Nifti1Image(data, np.diag(list(spacing) + [1.0]))
    image.set_qform(image.affine, 1)
    nib.save(image, str(path))


def resample(src, dst, size, *extra):
    return subprocess.run([sys.executable, str(SCRIPT), str(src), str(dst), *map(str, size),
                           *extra], capture_output=True, text=True)


class Resample(unittest.TestCase):
    def test_a_label_stays_zero_and_one_on_the_scans_grid(self):
        with tempfile.TemporaryDirectory() as tmp:
            tmp = Path(tmp)
            label = np.zeros((9, 9, 5), np.int16)
            label[2:7, 3:6, 1:4] = 1
            scan = label.astype(np.float32) * 100.0 + 7.0
            write(tmp / "label.nii.gz", label, (1.0, 1.0, 3.0))
            write(tmp / "scan.nii.gz", scan, (1.0, 1.0, 3.0))
            for name, extra in (("label", ["--label"]), ("scan", [])):
                run = resample(tmp / f"{name}.nii.gz", tmp / f"{name}2.nii.gz", (17, 17, 5),
                               *extra)
                self.assertEqual(run.returncode, 0, run.stderr)
            fine = nib.load(str(tmp / "label2.nii.gz"))
            values = np.asarray(fine.dataobj)
            self.assertEqual(values.shape, (17, 17, 5))
            self.assertEqual(set(np.unique(values)), {0.0, 1.0})
            np.testing.assert_allclose(fine.header.get_zooms()[:3], (0.5, 0.5, 3.0))
            # The end voxels' centres kept: voxel 2i of the fine grid is voxel i of the coarse.
            np.testing.assert_array_equal(values[::2, ::2, :], label)
            scan2 = np.asarray(nib.load(str(tmp / "scan2.nii.gz")).dataobj)
            np.testing.assert_array_equal(scan2 >= 57.0, values > 0)  # the cut at one half
            # Without --label the same label is interpolated: halves on its edges.
            run = resample(tmp / "label.nii.gz", tmp / "plain.nii.gz", (17, 17, 5))
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertIn(0.5, np.unique(np.asarray(nib.load(str(tmp / "plain.nii.gz")).dataobj)))

    def test_a_bad_size_is_refused_with_the_usage(self):
        run = resample("a.nii.gz", "b.nii.gz", (1, 2))
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("usage", run.stderr)


if __name__ == "__main__":
    unittest.main()
