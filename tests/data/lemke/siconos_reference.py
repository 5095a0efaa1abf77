#!/usr/bin/python3
"""Writes siconos_reference.json: Siconos numerics' lcp_lexicolemke on every contact_*.json here
(pivot limit 50 (n + 1) + 1000, as cpkit's default), with its z and whether that z is a solution
by a componentwise check done here: min(z_i, w_i) within 1e-9 of (|M||z| + |q|)_i.
Used by tests/lcp/test_lemke_degenerate.cpp as the peer's answer (run again after adding files).
"""
import glob
import json
import os

import numpy as np
import siconos.numerics as sn

here = os.path.dirname(os.path.abspath(__file__))
out = {}
for path in sorted(glob.glob(os.path.join(here, "contact_*.json"))):
    d = json.load(open(path))
    M, q = np.array(d["M"]), np.array(d["q"])
    n = len(q)
    z, w = np.zeros(n), np.zeros(n)
    so = sn.SolverOptions(sn.SICONOS_LCP_LEMKE)
    so.iparam[sn.SICONOS_IPARAM_MAX_ITER] = 50 * (n + 1) + 1000
    info = sn.lcp_lexicolemke(sn.LCP(M, q), z, w, so)
    wz = M @ z + q
    scale = np.abs(M) @ np.abs(z) + np.abs(q)
    ok = bool(np.all(np.abs(np.minimum(z, wz)) <= 1e-9 * scale) and z.min() >= -1e-9 * scale.max()
              and wz.min() >= -1e-9 * scale.max())
    out[os.path.basename(path)] = {"info": int(info), "pivots": int(so.iparam[sn.SICONOS_IPARAM_ITER_DONE]),
                                   "z": [float(x) for x in z], "z_is_solution": ok}
json.dump(out, open(os.path.join(here, "siconos_reference.json"), "w"), indent=1)
