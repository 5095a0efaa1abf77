"""ctest driver of one pytest file: exits 77 (ctest's skip code here) with the reason when
pytest or numpy is not importable, else pytest's own exit code.
Usage: python3 run_pytest.py TEST_FILE [pytest args...]"""
import sys

try:
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    print(f"SKIPPED: {e.name} is not importable by {sys.executable} "
          f"(Debian: apt-get install python3-pytest python3-numpy; scripts/setup-deps.sh --tests)")
    sys.exit(77)

sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
