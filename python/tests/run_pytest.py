"""ctest driver of one pytest file (python/CMakeLists.txt; ctest's SKIP_RETURN_CODE is 77).
Exits 77, skipped, with the reasons printed, when pytest or numpy is not importable, when the
module cpkit is not built, or when every test that ran passed but some were skipped
(pytest.skip for a missing peer: python3-siconos, libfclib, the cpkit program; pytest -rs lists
them). Where peers are required (CI=true or CPKIT_REQUIRE_PEERS=1, tests/scripts/peer_skip.py)
each of those is a failure (exit 1). Otherwise pytest's own exit code.
Usage: python3 run_pytest.py TEST_FILE [pytest args...]"""
import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "scripts"))
import peer_skip  # noqa: E402

try:
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    peer_skip.skip(f"{e.name} is not importable by {sys.executable} (Debian: apt-get install "
                   "python3-pytest python3-numpy; scripts/setup-deps.sh --tests)")

build = os.environ.get("CPKIT_BINARY_DIR")
if build and not glob.glob(os.path.join(build, "python", "cpkit", "_cpkit*")):
    peer_skip.skip(f"the Python module cpkit is not built in {build} (build the target "
                   "cpkit_python)")


class SkipCounter:
    """Counts the tests (and test files) pytest skipped; an expected failure is not a skip."""

    def __init__(self):
        self.skipped = 0

    def pytest_runtest_logreport(self, report):
        if report.skipped and not hasattr(report, "wasxfail"):
            self.skipped += 1

    def pytest_collectreport(self, report):
        if report.skipped:
            self.skipped += 1


counter = SkipCounter()
rc = pytest.main(["-q", "-rs", "-p", "no:cacheprovider", *sys.argv[1:]], plugins=[counter])
# 5: nothing collected, which a file skipped whole also gives.
if counter.skipped and rc in (pytest.ExitCode.OK, pytest.ExitCode.NO_TESTS_COLLECTED):
    peer_skip.skip(f"{counter.skipped} test(s) skipped for a missing peer (the SKIPPED lines "
                   "above say why); every other test passed")
sys.exit(rc)
