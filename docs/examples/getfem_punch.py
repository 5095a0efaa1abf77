#!/usr/bin/env python3
"""An elastic body meshed and assembled by GetFEM, condensed onto its contact nodes, and handed
to cpkit: for which friction coefficients mu does the rate problem of the body on a rigid
foundation have several solutions? (docs/python.md, "A real client: GetFEM")

The body: a plane-strain linear-elastic rectangle (width x height, Young's modulus E, Poisson's
ratio nu), bilinear Q1 elements, clamped on top to a rigid punch, resting on a rigid
foundation. The load is a motion of the punch (top edge) in the direction
(cos theta, -sin theta): theta = 90 deg presses straight down, theta = 0 shears to the right.

1. GetFEM assembles the stiffness K (isotropic linearized elasticity brick).
2. scipy condenses K onto the contact DOFs: with c the contact DOFs, D the clamped top DOFs and
   i all others, A = K_cc - K_ci K_ii^-1 K_ic and B = K_cD - K_ci K_ii^-1 K_iD, where K_ii^-1
   is applied by a sparse LU factorization (splu), never formed. A top motion d gives the
   contact-node load F = -B d.
3. cpkit's conventions (docs/model.md, "N contact points"): DOFs interleaved per point
   (T_1, N_1, T_2, N_2, ...), T = +x, N = -y (into the foundation, so that w_N > 0 penetrates),
   every contact point grazing (state b: touching, no force yet).

4. The whole bottom in contact (N = nx + 1 nodes, all grazing): for each mesh, the first mu at
   which cpkit's N-point rate problem has several solutions for some punch motion direction
   (sampled directions; a coarse mu grid, then bisection to 1e-3). Directions where the
   enumeration cannot decide (several nodes lifting off at once: a piece of dimension >= 2)
   are counted and reported; the solutions found there are verified, so "several" remains
   proven, but "unique" is not claimed for them.

Checks (exit code 1 when one fails):
- one contact node (the body touches the foundation at its bottom-left corner only): the
  condensed 2 x 2 block [[a11, a12], [a12, a22]] gives the one-point criterion "unique for every
  load direction iff a11 > mu |a12|", i.e. the threshold mu* = a11 / |a12|; cpkit's
  (mu x direction) count map of that node must switch from "one solution everywhere" to
  "three solutions somewhere" exactly there;
- refining the mesh changes that threshold smoothly (successive changes shrink);
- the same node through the N-point route (its 3 x 3 Schur-complement LCP) gives the one-point
  map's counts cell by cell.

Run: python3 docs/examples/getfem_punch.py [--quick] [--plot PNG]   (PYTHONPATH=<build>/python
for a build tree). --plot draws the body (mesh, punch, foundation, contact nodes, load
direction) and both thresholds against the mesh (docs/images/getfem_punch.png; matplotlib). Needs Debian's python3-getfem; exits 77 saying so when GetFEM is not installed.
"""
import argparse
import math
import sys

try:
    import getfem as gf
except ImportError:
    print("getfem_punch.py needs GetFEM's Python interface: apt-get install python3-getfem "
          "(Debian 12), or scripts/setup-deps.sh --tests")
    sys.exit(77)
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import cpkit

gf.util_trace_level(0)  # GetFEM's assembly trace lines are not this example's output


def assemble(width, height, nx, ny, E, nu):
    """Stiffness (scipy CSC) of the plane-strain body and the coordinates of its mesh nodes.
    DOFs come in (x, y) pairs per node: DOF 2k is x of node k, 2k + 1 is y."""
    mesh = gf.Mesh("cartesian", np.linspace(0, width, nx + 1), np.linspace(0, height, ny + 1))
    mfu = gf.MeshFem(mesh, 2)
    mfu.set_classical_fem(1)
    mim = gf.MeshIm(mesh, 4)
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    lame_lambda = E * nu / ((1 + nu) * (1 - 2 * nu))  # plane strain
    lame_mu = E / (2 * (1 + nu))
    md.add_initialized_data("lambda", [lame_lambda])
    md.add_initialized_data("mu", [lame_mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    md.assembly("build_matrix")
    K = md.tangent_matrix()
    jc, ir = K.csc_ind()
    K = sp.csc_matrix((K.csc_val(), ir, jc), shape=tuple(K.size()))
    dof_xy = mfu.basic_dof_nodes()
    nodes = dof_xy[:, 0::2].T
    assert np.array_equal(dof_xy[:, 0::2], dof_xy[:, 1::2]), "DOFs are not (x, y) pairs"
    return K, nodes


def condense(K, contact, top):
    """(A, e_T, e_N) in cpkit's coordinates: A the condensed stiffness on the contact nodes
    (2N x 2N, interleaved (T, N)), e_T / e_N the contact loads of a unit punch motion to the
    right / downwards (both 2N-vectors)."""
    dofs = lambda nodes: np.array([[2 * k, 2 * k + 1] for k in nodes]).ravel()
    c, D = dofs(contact), dofs(top)
    i = np.setdiff1d(np.arange(K.shape[0]), np.concatenate([c, D]))
    K = K.tocsr()
    Kci = K[c][:, i]
    lu = spla.splu(K[i][:, i].tocsc())  # K_ii^-1 applied by LU solves, never formed
    A = K[c][:, c].toarray() - Kci @ lu.solve(K[i][:, c].toarray())
    B = K[c][:, D].toarray() - Kci @ lu.solve(K[i][:, D].toarray())
    right = np.tile([1.0, 0.0], len(top))
    down = np.tile([0.0, -1.0], len(top))
    flip = np.tile([1.0, -1.0], len(contact))  # (x, y) -> (T, N) = (x, -y)
    A = flip[:, None] * A * flip[None, :]
    return 0.5 * (A + A.T), flip * (-B @ right), flip * (-B @ down)


def body(nx, args, contact="bottom"):
    """Assemble and condense the body with nx x nx/2 elements; contact: "bottom" (every bottom
    node) or "corner" (the bottom-left node only)."""
    ny = max(1, int(round(nx * args.height / args.width)))
    K, nodes = assemble(args.width, args.height, nx, ny, args.E, args.nu)
    tol = 1e-9 * max(args.width, args.height)
    bottom = [k for k in range(len(nodes)) if abs(nodes[k, 1]) < tol]
    bottom.sort(key=lambda k: nodes[k, 0])
    top = [k for k in range(len(nodes)) if abs(nodes[k, 1] - args.height) < tol]
    chosen = bottom[:1] if contact == "corner" else bottom
    return condense(K, chosen, top) + (nodes[chosen, 0],)


def one_node_threshold_from_map(A, mus, theta_n):
    """First mu of `mus` at which cpkit's one-point count map of the node (state b) has more
    than one solution for some direction, or None."""
    p = cpkit.ContactParameters(a11=A[0, 0], a12=A[0, 1], a22=A[1, 1], mu=1.0)
    m = cpkit.param_direction_map(p, "b", "mu", mus[0], mus[-1], len(mus), theta_n)
    several = (m.count > 1) | (m.count < 0)
    rows = np.nonzero(several.any(axis=1))[0]
    return (m.x[rows[0]] if rows.size else None), m


def check_one_node(args, failures):
    print("== one contact node (bottom-left corner) ==")
    print(f"{'nx':>4} {'a11':>10} {'a12':>10} {'a22':>10} {'mu* = a11/|a12|':>16}")
    thresholds, sampled = [], []
    for nx in args.meshes:
        A, e_T, e_N, _ = body(nx, args, contact="corner")
        # One node: a uniform motion of the top is a rigid motion relative to the node, so the
        # load of a unit punch motion is A times that motion: F = A (1, 0) and A (0, 1).
        assert np.allclose(e_T, A[:, 0], atol=1e-10 * abs(A).max())
        assert np.allclose(e_N, A[:, 1], atol=1e-10 * abs(A).max())
        mu_star = A[0, 0] / abs(A[0, 1])
        thresholds.append(mu_star)
        print(f"{nx:4d} {A[0, 0]:10.6f} {A[0, 1]:10.6f} {A[1, 1]:10.6f} {mu_star:16.6f}")
        # cpkit's mu x direction map of the node on a mu grid straddling mu* (not on it): its
        # analytic critical value must be mu* and no cell below mu* may have several solutions
        # (a sampled direction grid sees the three-solution wedge only once it is wider than a
        # cell, so its first such row lies a little above mu*, or beyond the grid).
        h = 0.01
        mus = mu_star + h * (np.arange(-20, 21) + 0.5)
        first, m = one_node_threshold_from_map(A, mus, args.theta_n)
        sampled.append(first)
        crit = [c["x"] for c in m.critical_values if c["name"] in ("D+=0", "D-=0")]
        ok = (first is None or first > mu_star) and \
            len(crit) == 1 and abs(crit[0] - mu_star) <= 1e-12 * mu_star
        # Exact direction maps (every sector, no sampling) just below and above mu*: one
        # solution for every direction / three in a sector.
        p = lambda mu: cpkit.ContactParameters(a11=A[0, 0], a12=A[0, 1], a22=A[1, 1], mu=mu)
        below = cpkit.direction_map(p(mu_star * (1 - 1e-9)), "b").counts
        above = cpkit.direction_map(p(mu_star * (1 + 1e-9)), "b").counts
        ok = ok and below.max() == 1 and below.min() == 1 and above.max() == 3
        crit_text = ", ".join(f"{c:.6f}" for c in crit) or "none"
        print(f"     map: critical value {crit_text}; exact direction maps: max count "
              f"{below.max()} below, {above.max()} above; sampled grid ({args.theta_n} "
              f"directions): first non-unique mu "
              f"{'%.4f' % first if first is not None else 'beyond mu* + 0.2'}")
        if not ok:
            failures.append(f"one node, nx = {nx}: map threshold {first} vs a11/|a12| = {mu_star}")
    diffs = np.abs(np.diff(thresholds))
    print("changes under refinement:", " ".join(f"{d:.4f}" for d in diffs))
    if len(diffs) >= 2 and not (diffs[1:] < diffs[:-1]).all():
        failures.append(f"one-node threshold does not settle under refinement: {thresholds}")
    return thresholds, sampled


def system_of(A, mu, patterns):
    """Every contact point grazing (state b) with friction coefficient mu."""
    return cpkit.ContactSystem(A, [{"state": "b", "mu": float(mu)} for _ in range(A.shape[0] // 2)],
                               patterns=patterns)


def directions_at(A, e_T, e_N, mu, theta):
    """Counts of the N-point rate problem at mu for the punch motions theta (radians):
    dF = cos theta e_T + sin theta e_N. Returns (several, undecided, counts): does some direction
    have several solutions (verified: a lower bound even where the enumeration is incomplete),
    how many directions the enumeration could not decide completely, and the counts."""
    c = cpkit.system_direction_counts(system_of(A, mu, (e_T, e_N)), theta)
    several = bool(((c["count"] > 1) | (c["count"] < 0)).any())
    return several, int((~c["reliable"]).sum()), c["count"]


def threshold(A, e_T, e_N, theta, mu_grid, tol):
    """The first mu of mu_grid with several solutions for some sampled direction, refined by
    bisection to tol (the property is monotone in mu on every case tried here). Returns
    (mu, undecided directions met below it) or (None, ...)."""
    undecided, lo = 0, None
    for mu in mu_grid:
        several, und, _ = directions_at(A, e_T, e_N, mu, theta)
        if several:
            hi = mu
            break
        undecided += und
        lo = mu
    else:
        return None, undecided
    if lo is None:
        return hi, undecided
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        several, und, _ = directions_at(A, e_T, e_N, mid, theta)
        if several:
            hi = mid
        else:
            lo, undecided = mid, undecided + und
    return hi, undecided


def check_body(args, failures):
    theta = (np.arange(args.theta_n) + 0.5) * 2 * math.pi / args.theta_n
    mu_grid = np.arange(0.25, 3.0 + 1e-12, 0.25)
    print(f"== cpkit's N-point rate problem, every contact node grazing (state b), "
          f"{args.theta_n} punch motion directions ==")
    # One node through the N-point machinery (the Schur-complement LCP of size 3) must give
    # the one-point map cell by cell (a different route: the one-point LCP / closed forms).
    A, e_T, e_N, _ = body(args.meshes[0], args, contact="corner")
    mus = np.linspace(0.5, 3.0, 11)
    one = cpkit.param_direction_map(cpkit.ContactParameters(a11=A[0, 0], a12=A[0, 1], a22=A[1, 1]),
                                    "b", "mu", mus[0], mus[-1], len(mus), args.theta_n)
    # Same loads as the one-point map: force directions (dF_T, dF_N) = (cos, sin).
    agree = True
    for i, mu in enumerate(mus):
        c = cpkit.system_direction_counts(system_of(A, mu, (np.array([1.0, 0.0]), np.array([0.0, 1.0]))),
                                          one.theta)
        agree &= bool((c["count"] == one.count[i]).all())
    print(f"  one node (nx = {args.meshes[0]}): N-point counts equal the one-point map on all "
          f"{one.count.size} cells: {agree}")
    if not agree:
        failures.append("one node: the N-point counts differ from the one-point map")
    print(f"{'nx':>4} {'N':>3} {'first mu with several solutions':>32} "
          f"{'min_i a11/|a12| (blocks)':>25}  undecided cells below it")
    firsts, block_values = [], []
    for nx in args.body_meshes:
        A, e_T, e_N, x = body(nx, args, contact="bottom")
        mu1, undecided = threshold(A, e_T, e_N, theta, mu_grid, 1e-3)
        firsts.append(mu1)
        # For comparison: each point's own one-point criterion, from its diagonal 2 x 2 block of A
        # (the other contact nodes held fixed).
        blocks = min(A[2 * i, 2 * i] / abs(A[2 * i, 2 * i + 1]) if A[2 * i, 2 * i + 1] != 0
                     else math.inf for i in range(len(x)))
        block_values.append(blocks)
        print(f"{nx:4d} {len(x):3d} {('%.3f' % mu1) if mu1 is not None else 'none <= 3':>32} "
              f"{blocks:25.3f}  {undecided}")
    return firsts, block_values


def plot(path, args, one_node, whole):
    """The body as meshed (the finest whole-bottom mesh), its contact nodes and the load, and
    both thresholds against the mesh: what a user wants to see before trusting the numbers."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyArrowPatch, Rectangle

    fig, (ax0, ax1, ax2) = plt.subplots(1, 3, figsize=(16, 6.6), constrained_layout=True,
                                        gridspec_kw={"width_ratios": [1.3, 1, 1]})
    nx = args.body_meshes[-1]
    ny = max(1, int(round(nx * args.height / args.width)))
    W, H = args.width, args.height
    for x in np.linspace(0, W, nx + 1):
        ax0.plot([x, x], [0, H], color="0.55", lw=0.8)
    for y in np.linspace(0, H, ny + 1):
        ax0.plot([0, W], [y, y], color="0.55", lw=0.8)
    ax0.add_patch(Rectangle((-0.1 * W, H), 1.2 * W, 0.12 * H, facecolor="0.3", edgecolor="k",
                            hatch="///", label="rigid punch (clamped top, moves)"))
    ax0.add_patch(Rectangle((-0.1 * W, -0.12 * H), 1.2 * W, 0.12 * H, facecolor="0.85",
                            edgecolor="k", hatch="\\\\", label="rigid foundation"))
    xs = np.linspace(0, W, nx + 1)
    ax0.plot(xs, np.zeros_like(xs), "o", color="tab:blue", ms=8, zorder=5,
             label=f"contact nodes, whole bottom (N = {nx + 1})")
    ax0.plot([0], [0], "s", color="tab:red", ms=12, mfc="none", mew=2.5, zorder=6,
             label="one contact node (corner)")
    drawn = 60  # the arrow shows one direction; the maps sample every theta
    t = math.radians(drawn)
    ax0.add_patch(FancyArrowPatch((0.5 * W, 1.3 * H), (0.5 * W + 0.35 * math.cos(t),
                                                       1.3 * H - 0.35 * math.sin(t)),
                                  arrowstyle="-|>", mutation_scale=18, color="tab:green",
                                  lw=2, label=f"punch motion (cos theta, -sin theta), drawn at "
                                              f"theta = {drawn} deg;\nthe maps: {args.theta_n} "
                                              f"directions theta in [0, 360) deg"))
    ax0.set_xlim(-0.15 * W, 1.15 * W)
    ax0.set_ylim(-0.2 * H, 1.55 * H)
    ax0.set_aspect("equal")
    ax0.set_xticks([])
    ax0.set_yticks([])
    ax0.set_title(f"the body: {W:g} x {H:g}, plane strain, E = {args.E:g}, nu = {args.nu:g},\n"
                  f"Q1 mesh {nx} x {ny} (GetFEM), condensed onto the contact nodes")
    ax0.legend(loc="upper center", bbox_to_anchor=(0.5, -0.02), ncol=2, fontsize=8.5,
               frameon=False)

    thresholds, sampled = one_node
    ax1.plot(args.meshes, thresholds, "o-", color="tab:red",
             label="exact: mu* = a11/|a12| (= critical value of the map)")
    s = [(m, v) for m, v in zip(args.meshes, sampled) if v is not None]
    if s:
        ax1.plot(*zip(*s), "x--", color="0.4", ms=8,
                 label=f"first non-unique row of a sampled map ({args.theta_n} directions):\n"
                       "the wedge is seen only once wider than a cell")
    missing = [m for m, v in zip(args.meshes, sampled) if v is None]
    if missing:
        ax1.plot([], [], " ", label=f"sampled map ({args.theta_n} directions): no non-unique row "
                                    f"up to mu* + 0.2 at {', '.join(map(str, missing))} elements")
    ax1.set_xscale("log", base=2)
    ax1.set_xticks(args.meshes)
    ax1.set_xticklabels([str(m) for m in args.meshes])
    ax1.set_xlabel("elements along the width")
    ax1.set_ylabel("mu threshold (several solutions above)")
    ax1.set_title("one contact node (corner):\nthreshold under mesh refinement")
    ax1.legend(fontsize=8.5, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    ax1.grid(alpha=0.3)

    firsts, blocks = whole
    pts = [(m, v) for m, v in zip(args.body_meshes, firsts) if v is not None]
    if pts:
        ax2.plot(*zip(*pts), "o-", color="tab:blue",
                 label="N-point rate problem: first mu with\nseveral solutions (sampled, bisected)")
    ax2.plot(args.body_meshes, blocks, "s--", color="0.45",
             label="min over points of a11/|a12|\nof their own 2 x 2 blocks")
    ax2.set_xticks(args.body_meshes)
    ax2.set_xticklabels([f"{m}\n(N = {m + 1})" for m in args.body_meshes])
    ax2.set_xlabel("elements along the width (contact nodes N)")
    ax2.set_ylabel("mu threshold")
    ax2.set_title("the whole bottom in contact:\ncoupling lowers the threshold")
    ax2.legend(fontsize=8.5, loc="upper center", bbox_to_anchor=(0.5, -0.2), frameon=False)
    ax2.grid(alpha=0.3)
    fig.savefig(path, dpi=100)
    print(f"wrote {path}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--width", type=float, default=2.0)
    ap.add_argument("--height", type=float, default=1.0)
    ap.add_argument("--E", type=float, default=1.0, help="Young's modulus")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio")
    ap.add_argument("--meshes", type=int, nargs="+", default=[4, 8, 16, 32, 64],
                    help="elements along the width, one body per value")
    ap.add_argument("--theta-n", type=int, default=360, help="load directions of the maps")
    ap.add_argument("--body-meshes", type=int, nargs="+", default=[2, 3, 4],
                    help="elements along the width for the whole-bottom contact (N = value + 1; "
                         "the enumeration grows fast with N: N = 6 takes minutes per mesh)")
    ap.add_argument("--quick", action="store_true", help="smaller meshes and maps (the test)")
    ap.add_argument("--plot", metavar="PNG", help="draw the body and the thresholds (matplotlib)")
    args = ap.parse_args(argv)
    if args.quick:
        args.meshes = [4, 8, 16, 32]
        args.body_meshes = [2, 3]
        args.theta_n = 72
    failures = []
    one_node = check_one_node(args, failures)
    whole = check_body(args, failures)
    if args.plot:
        plot(args.plot, args, one_node, whole)
    for f in failures:
        print("CHECK FAILED:", f)
    print("all checks passed" if not failures else f"{len(failures)} check(s) failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
