#!/usr/bin/python3
"""Writes siconos_reference.json: Siconos numerics' lcp_lexicolemke on every contact_*.json,
engine_*.json and cycling_*.json here
(pivot limit 50 (n + 1) + 1000, as cpkit's default), with its z and whether that z is a solution
by a componentwise check done here: min(z_i, w_i) within 1e-9 of (|M||z| + |q|)_i.
Used by tests/lcp/test_lemke_degenerate.cpp and test_lemke_engines.cpp as the peer's answer (run
again after adding files). Siconos' pivot count ("pivots", its SICONOS_IPARAM_ITER_DONE) does not
count the initial z0 pivot that cpkit counts (engine_dart_lemke_12d: Siconos 7, cpkit 8, exact
lexicographic Lemke 8 with that pivot).
"""
import glob
import json
import os

import numpy as np
import siconos.numerics as sn

here = os.path.dirname(os.path.abspath(__file__))
out = {}
paths = [p for pat in ("contact_*.json", "engine_*.json", "cycling_*.json")
         for p in glob.glob(os.path.join(here, pat))]
for path in sorted(paths):
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
