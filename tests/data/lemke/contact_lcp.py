#!/usr/bin/python3
"""Generator of polyhedral-friction-cone contact LCPs (a rigid body resting on the ground).

Formulation of Stewart & Trinkle (1996) / Anitescu & Potra (1997), one time step, with m contacts
and a friction cone approximated by 4 directions per contact. Unknowns (size 6 m):
  c_n (m normal impulses), beta (4 m friction impulses), lambda (m, ~ sliding speed).
  M = [[N'AN, N'AD, 0], [D'AN, D'AD, E], [mu, -E', 0]],  q = [N'v; D'v; 0]
with A the inverse of the body's mass matrix (world frame), N (6 x m) and D (6 x 4m) the
normal / tangential Jacobians (transposed), E (4m x m) the block of ones, mu = diag(mu_c) and
v = v_minus + h A f_ext the predicted velocity (here drawn directly, of size `vscale`).
A resting contact has a tiny v: q ~ vscale while M ~ 1 (unit mass and lever arms), and the
lambda rows have q = 0 exactly: a degenerate LCP.

Usage: contact_lcp.py SEED [--contacts m] [--vscale s] [--symmetric] > problem.json
  --symmetric: contact points symmetric about the centre of mass, normal exactly vertical,
               no tangential velocity (the most degenerate member of the family).
  --mixed:     seeded exact degeneracies: contact points on a half-unit grid, the normal
               vertical in half of the draws, each velocity component zero with probability 0.6.
The output is cpkit's LCP JSON ({"name", "M", "q", "source"}); numbers are written with
repr() so that the file holds exactly the doubles computed here.
"""
import json
import sys

import numpy as np


def skew(r):
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def contact_lcp(seed, contacts=2, vscale=1e-10, symmetric=False, mixed=False):
    rng = np.random.default_rng(seed)
    m = contacts
    mass = rng.uniform(0.5, 2.0)
    inertia = np.diag(rng.uniform(0.1, 1.0, 3))
    # Random orientation (QR of a Gaussian matrix, sign-fixed).
    Q, R = np.linalg.qr(rng.standard_normal((3, 3)))
    Q = Q * np.sign(np.diag(R))
    A = np.zeros((6, 6))
    A[:3, :3] = np.eye(3) / mass
    A[3:, 3:] = Q @ np.linalg.inv(inertia) @ Q.T
    N = np.zeros((6, m))
    D = np.zeros((6, 4 * m))
    for c in range(m):
        if symmetric:
            normal = np.array([0.0, 0.0, 1.0])
            ang = 2 * np.pi * c / m
            r = np.array([np.cos(ang), np.sin(ang), -0.5])
        elif mixed:
            # Seeded choice of exact degeneracies: vertical normal, points on a grid.
            normal = np.array([0.0, 0.0, 1.0])
            if rng.uniform() < 0.5:
                normal = normal + 0.1 * rng.standard_normal(3)
                normal /= np.linalg.norm(normal)
            r = rng.integers(-2, 3, 3) / 2.0
        else:
            normal = np.array([0.0, 0.0, 1.0]) + 0.1 * rng.standard_normal(3)
            normal /= np.linalg.norm(normal)
            r = rng.uniform(-1.0, 1.0, 3)
        t1 = np.cross(normal, [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0])
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(normal, t1)
        N[:3, c] = normal
        N[3:, c] = skew(r) @ normal  # r x n
        for k, d in enumerate([t1, t2, -t1, -t2]):
            D[:3, 4 * c + k] = d
            D[3:, 4 * c + k] = skew(r) @ d
    E = np.zeros((4 * m, m))
    for c in range(m):
        E[4 * c:4 * c + 4, c] = 1.0
    mu = np.diag(rng.uniform(0.2, 1.0, m))
    v = vscale * rng.standard_normal(6)
    if mixed:
        keep = rng.uniform(size=6) < 0.4
        v = np.where(keep, v, 0.0)
        v[2] = -vscale * rng.integers(1, 3)
    elif symmetric:
        v[:] = 0.0
        v[2] = -vscale  # falling straight down, no spin
    else:
        v[2] = -abs(v[2]) - vscale  # approaching the ground
    M = np.block([[N.T @ A @ N, N.T @ A @ D, np.zeros((m, m))],
                  [D.T @ A @ N, D.T @ A @ D, E],
                  [mu, -E.T, np.zeros((m, m))]])
    q = np.concatenate([N.T @ v, D.T @ v, np.zeros(m)])
    return M, q


def main(argv):
    seed = int(argv[1])
    contacts, vscale, symmetric, mixed = 2, 1e-10, False, False
    a = 2
    while a < len(argv):
        if argv[a] == "--contacts":
            contacts = int(argv[a + 1]); a += 2
        elif argv[a] == "--vscale":
            vscale = float(argv[a + 1]); a += 2
        elif argv[a] == "--symmetric":
            symmetric = True; a += 1
        elif argv[a] == "--mixed":
            mixed = True; a += 1
        else:
            sys.exit("unknown argument " + argv[a])
    M, q = contact_lcp(seed, contacts, vscale, symmetric, mixed)
    out = {
        "name": "contact_%dc_seed%d%s" % (contacts, seed, "_sym" if symmetric else "_mixed" if mixed else ""),
        "source": "tests/data/lemke/contact_lcp.py %s" % " ".join(argv[1:]),
        "M": [[float(x) for x in row] for row in M],
        "q": [float(x) for x in q],
    }
    # json writes floats with repr(): the shortest string that round-trips to the same double.
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main(sys.argv)
