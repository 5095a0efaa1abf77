"""What Siconos' own readers (python3-siconos, Siconos numerics 4.4) decode from FrictionContact
and GlobalFrictionContact .dat files, as JSON, for tests/core/test_friction_io_siconos_peer.cpp.

Usage: friction_siconos_peer.py local|global OUT.json FILE...
Matrices are given as their non-zero entries [row, column, value]. Exits 77 when siconos.numerics
is not importable (the test is then reported as skipped, with this message).
"""
import json
import os
import sys

try:
    import numpy as np
    import scipy.sparse  # noqa: F401 -- Siconos hands sparse (storage 2) matrices over as scipy's
    import siconos.numerics as sn
except Exception as e:  # noqa: BLE001 -- any import failure means: no peer here
    print("python3-siconos (siconos.numerics) not importable:", e)
    sys.exit(77)


def dense(M):
    if isinstance(M, np.ndarray):
        return np.asarray(M, dtype=float)
    if hasattr(M, "toarray"):  # a scipy.sparse matrix (storage 2)
        return np.asarray(M.toarray(), dtype=float)
    if isinstance(M, sn.NumericsMatrix):
        D = np.zeros((M.size0, M.size1))
        for i in range(M.size0):
            for j in range(M.size1):
                D[i, j] = sn.NM_get_value(M, i, j)
        return D
    return np.asarray(sn.SBM_to_dense(M), dtype=float)


def entries(M):
    D = dense(M)
    rows, cols = np.nonzero(D)
    return {"rows": int(D.shape[0]), "cols": int(D.shape[1]),
            "entries": [[int(i), int(j), float(D[i, j])] for i, j in zip(rows, cols)]}


def vec(v):
    return [float(x) for x in np.asarray(v, dtype=float).ravel()]


def local(path):
    p = sn.frictionContact_new_from_filename(path)
    return {"dimension": int(p.dimension), "contacts": int(p.numberOfContacts),
            "W": entries(p.M), "q": vec(p.q), "mu": vec(p.mu)}


def global_(path):
    p = sn.globalFrictionContact_new_from_filename(path)
    return {"dimension": int(p.dimension), "contacts": int(p.numberOfContacts),
            "M": entries(p.M), "H": entries(p.H), "q": vec(p.q), "b": vec(p.b), "mu": vec(p.mu)}


def main(argv):
    if len(argv) < 4 or argv[1] not in ("local", "global"):
        print(__doc__)
        return 2
    decode = local if argv[1] == "local" else global_
    out = {os.path.basename(f): decode(f) for f in argv[3:]}
    with open(argv[2], "w") as f:
        json.dump(out, f)  # repr(float) round-trips exactly
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
