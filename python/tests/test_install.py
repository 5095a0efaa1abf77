"""`cmake --install` into a temporary prefix, then `import cpkit` from there with nothing but
PYTHONPATH=<prefix>/<CPKIT_PYTHON_INSTALL_DIR> (docs/python.md), in a fresh interpreter."""
import os
import subprocess
import sys

import pytest


def test_install_to_a_prefix_and_import(tmp_path):
    build = os.environ.get("CPKIT_BINARY_DIR")
    if not build:
        pytest.skip("CPKIT_BINARY_DIR unset (run through ctest)")
    prefix = tmp_path / "prefix"
    p = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    # The default of python/CMakeLists.txt, whatever the prefix.
    v = sys.version_info
    sub = os.environ.get("CPKIT_PYTHON_INSTALL_DIR", f"lib/python{v.major}.{v.minor}/dist-packages")
    site = prefix / sub
    assert (site / "cpkit" / "__init__.py").exists()
    code = ("import cpkit, numpy as np; r = cpkit.solve([[2, 1], [1, 2]], [-5, -6]); "
            "print(cpkit.__file__); print(r.status, *np.round(r.z * 3, 9))")
    env = {"PATH": os.environ.get("PATH", "/usr/bin"), "PYTHONPATH": str(site)}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       cwd=str(tmp_path), timeout=60)
    assert p.returncode == 0, p.stderr
    where, answer = p.stdout.splitlines()
    assert where.startswith(str(site))
    assert answer == "solved 4.0 7.0"  # z = (4/3, 7/3) by hand
    # Without PYTHONPATH the temporary prefix is not found (the variable is what makes it work).
    env.pop("PYTHONPATH")
    p = subprocess.run([sys.executable, "-c", "import cpkit; print(cpkit.__file__)"],
                       capture_output=True, text=True, env=env, cwd=str(tmp_path), timeout=60)
    assert p.returncode != 0 or not p.stdout.startswith(str(site))
