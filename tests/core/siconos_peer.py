#!/usr/bin/env python3
"""Siconos' own .dat reader and writer, as the peer of cpkit's reader (tests/core/test_io_siconos_peer.cpp).

  siconos_peer.py write DIR             writes LCP files with Siconos' writer into DIR: seeded
                                        random non-symmetric problems, dense (storage 0) and
                                        sparse block (storage 1), with extreme values
  siconos_peer.py write-reference DIR   writes the two hand-checked files of tests/data/siconos/
  siconos_peer.py decode OUT FILE...    writes OUT = {"FILE": {"M": [[...]], "q": [...]}, ...}:
                                        each FILE as Siconos' linearComplementarity_newFromFilename
                                        decodes it (M row-major, floats exact)

Exits 77 (ctest: skipped), printing the reason, when python3-siconos is not importable.

The matrix is written by Siconos' NM_write_in_filename. linearComplementarity_printInFile cannot
be called from Python (its FILE* typemap opens files for reading only), so its three other lines
are reproduced here exactly: "%d\\n" with n before M, "%32.24e " for each q_i after it.
"""
import json
import os
import sys
import warnings

try:
    import numpy as np
    import scipy.sparse as sp
    import siconos.numerics as sn
except ImportError as e:  # pragma: no cover - depends on the machine
    print(f"python3-siconos is not importable ({e}); "
          "install it with scripts/setup-deps.sh --tests")
    sys.exit(77)

warnings.simplefilter("ignore")  # Siconos warns about int32 sparse indices


def write_lcp(path, numerics_matrix, q):
    """n, then M by Siconos' own writer, then q as linearComplementarity_printInFile does."""
    tmp = path + ".M"
    sn.NM_write_in_filename(numerics_matrix, tmp)
    with open(tmp) as f:
        m_text = f.read()
    os.remove(tmp)
    with open(path, "w") as f:
        f.write("%d\n" % len(q))
        f.write(m_text)
        f.write("".join("%32.24e " % v for v in q))


def sparse_block(dense, blocksize):
    """A Siconos SparseBlockStructuredMatrix with square blocks of `blocksize` (zero blocks left out)."""
    csc = sp.csc_matrix(dense)
    csc.indices = csc.indices.astype(np.int64)
    csc.indptr = csc.indptr.astype(np.int64)
    info, sbm = sn.SBM_from_csparse(blocksize, csc)
    assert info == 0
    return sbm


def extreme(rng, shape):
    """Random values over the whole double range, with zeros, signed zeros and subnormals."""
    v = rng.standard_normal(shape) * 10.0 ** rng.integers(-300, 300, shape)
    special = np.array([0.0, -0.0, 5e-324, -2.2250738585072014e-308, 1.7976931348623157e308, 1.0, -1.0])
    mask = rng.random(shape) < 0.25
    v[mask] = rng.choice(special, size=int(mask.sum()))
    return v


def write_all(out_dir):
    rng = np.random.default_rng(20261123)
    os.makedirs(out_dir, exist_ok=True)
    for n in (1, 2, 3, 5, 8):
        M = rng.standard_normal((n, n)).round(3)
        write_lcp(os.path.join(out_dir, f"gen_dense_{n}.dat"), sn.NumericsMatrix(M),
                  rng.standard_normal(n).round(3))
    write_lcp(os.path.join(out_dir, "gen_dense_extreme_6.dat"), sn.NumericsMatrix(extreme(rng, (6, 6))),
              extreme(rng, 6))
    for n, bs in ((4, 2), (6, 2), (6, 3), (7, 1), (9, 3), (12, 4)):
        M = rng.standard_normal((n, n)).round(3)
        nb = n // bs
        for bi in range(nb):  # knock out some off-diagonal blocks: a sparse block pattern
            for bj in range(nb):
                if bi != bj and rng.random() < 0.5:
                    M[bi * bs:(bi + 1) * bs, bj * bs:(bj + 1) * bs] = 0.0
        write_lcp(os.path.join(out_dir, f"gen_block_{n}_bs{bs}.dat"),
                  sn.NumericsMatrix(sparse_block(M, bs)), rng.standard_normal(n).round(3))
    E = extreme(rng, (6, 6))
    E[0:3, 3:6] = 0.0
    write_lcp(os.path.join(out_dir, "gen_block_extreme_6_bs3.dat"),
              sn.NumericsMatrix(sparse_block(E, 3)), extreme(rng, 6))


def write_reference(out_dir):
    """The two non-symmetric files of tests/data/siconos/ whose M the tests state by hand."""
    M = np.array([[1.0, 2.0, 0.0], [3.0, 4.0, 5.0], [0.0, 6.0, 7.0]])
    write_lcp(os.path.join(out_dir, "siconos_writer_dense_3x3.dat"), sn.NumericsMatrix(M),
              np.array([-1.0, -2.0, -3.0]))
    B = np.array([[1.0, 2.0, 0.0, 0.0], [3.0, 4.0, 0.0, 0.0], [0.0, 0.0, 5.0, 6.0],
                  [7.0, 0.0, 8.0, 9.0]])
    write_lcp(os.path.join(out_dir, "siconos_writer_block_4x4.dat"),
              sn.NumericsMatrix(sparse_block(B, 2)), np.array([-1.0, -2.0, -3.0, -4.0]))


def decode(path):
    problem = sn.LCP(np.eye(1), np.zeros(1))
    sn.linearComplementarity_newFromFilename(problem, path)
    M = problem.M
    dense = np.asarray(M if isinstance(M, np.ndarray) else sn.SBM_to_dense(M), dtype=float)
    return {"M": dense.tolist(), "q": np.asarray(problem.q, dtype=float).tolist()}


def main(argv):
    if len(argv) == 3 and argv[1] == "write":
        write_all(argv[2])
        return 0
    if len(argv) >= 3 and argv[1] == "decode":
        decoded = {os.path.basename(f): decode(f) for f in argv[3:]}
        with open(argv[2], "w") as f:  # one file per line; repr(float) round-trips exactly
            f.write("{\n" + ",\n".join(json.dumps(k) + ": " + json.dumps(decoded[k])
                                       for k in sorted(decoded)) + "\n}\n")
        return 0
    if len(argv) == 3 and argv[1] == "write-reference":
        write_reference(argv[2])
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
