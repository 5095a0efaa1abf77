"""read_fclib on the hostile FCLIB files of issue 34 (tests/data/fclib/hostile; its README gives
each file's expected answer). Each read runs in a child interpreter, so a crash or an exit(1)
inside the reader (what libfclib did: SIGSEGV, "free(): invalid size", exit 1) fails this test
instead of ending pytest."""
import json
import os
import subprocess
import sys

import pytest

import cpkit  # noqa: F401  (the child imports the same module: fail here if it is missing)
from conftest import DATA_DIR

HOSTILE = os.path.join(DATA_DIR, "fclib", "hostile")

CHILD = """
import json, sys
import cpkit
try:
    p = cpkit.read_fclib(sys.argv[1])
except ValueError as e:
    print(json.dumps({"error": str(e)}))
else:
    print(json.dumps({"name": p.name, "contacts": int(p.mu.size), "q": p.q.tolist(),
                      "mu": p.mu.tolist(), "W": p.W.toarray().tolist()}))
"""


def read_in_child(name):
    """read_fclib(name) in a child interpreter: its exit code and its JSON line."""
    p = subprocess.run([sys.executable, "-c", CHILD, os.path.join(HOSTILE, name)],
                       capture_output=True, text=True, timeout=60)
    return p.returncode, (json.loads(p.stdout) if p.stdout.strip() else None), p.stderr


@pytest.mark.parametrize("name,dataset", [
    ("title_array.hdf5", "/fclib_local/info/title"),
    ("description_vlen_array.hdf5", "/fclib_local/info/description"),
    ("q_lzf.hdf5", "/fclib_local/vectors/q"),
    ("q_gzip_corrupt.hdf5", "/fclib_local/vectors/q"),
    ("amp.hdf5", "/fclib_local"),
])
def test_hostile_file_is_a_value_error_naming_the_dataset(name, dataset):
    code, out, err = read_in_child(name)
    assert code == 0, f"the interpreter ended with {code}: {err}"
    assert out is not None and "error" in out, out
    assert name in out["error"] and dataset in out["error"], out["error"]


def test_string_titles_read_as_written():
    # The README: "a vlen title" (h5py's str), "hostile" (np.bytes_, no NUL).
    for name, title in (("title_vlen.hdf5", "a vlen title"), ("title_fixed_h5py.hdf5", "hostile")):
        code, out, err = read_in_child(name)
        assert code == 0, err
        assert out["name"] == title


def test_undamaged_gzip_file_reads_as_its_readme_says():
    # 100 contacts, W = I, q = (-1, 0, 0), mu = 0.5 per contact.
    code, out, err = read_in_child("q_gzip_ok.hdf5")
    assert code == 0, err
    assert out["contacts"] == 100
    assert out["q"] == [-1.0, 0.0, 0.0] * 100
    assert out["mu"] == [0.5] * 100
    W = out["W"]
    assert all(W[i][j] == (1.0 if i == j else 0.0) for i in range(300) for j in range(300))
