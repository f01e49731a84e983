"""What the benchmarks' Python tests share: bench/steering on the import path, and Debian's
packages they need, skipped (CTest's 77) where missing but a failure (1) under
STEERSEG_REQUIRE_DATA=1 or CI, where tools/install-deps.sh installs them."""
import importlib
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def require(modules, debian):
    """Imports `modules` or exits saying which Debian packages (`debian`) hold them; then puts
    bench/steering on the path."""
    try:
        for name in modules:
            importlib.import_module(name)
    except ImportError as missing:
        if os.environ.get("STEERSEG_REQUIRE_DATA") == "1" or os.environ.get("CI"):
            print(f"FAILED: {missing} (Debian: {debian}, tools/install-deps.sh)",
                  file=sys.stderr)
            sys.exit(1)
        print(f"skipped: {missing} (Debian: {debian})")
        sys.exit(77)
    sys.path.insert(0, str(ROOT / "bench" / "steering"))
