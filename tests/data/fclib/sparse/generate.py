#!/usr/bin/python3
"""Writes the storage-type-2 (sparse W) .dat files of this folder with Siconos' own writer.

Usage (python3-siconos, Siconos numerics 4.4): /usr/bin/python3 generate.py
Each file is a problem of ../local or ../global (dense or sparse-block W, M, H) read by Siconos'
reader, its matrices handed back to Siconos as scipy.sparse matrices (coo gives a triplet, csc
a compressed-column NumericsSparseMatrix) and written by frictionContact_printInFilename /
globalFrictionContact_printInFileName. Siconos prints sparse entries with %g (6 significant
digits); q, b and mu keep all their digits. One more problem is built here: two contacts whose
W has an empty column (a zero r_T direction), to exercise an empty run ("locations 3 to 2").
"""
import os
import warnings

import numpy as np
import scipy.sparse as sp
import siconos.numerics as sn

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.dirname(HERE)


def dense(M):
    if isinstance(M, np.ndarray):
        return np.asarray(M, dtype=float)
    if isinstance(M, sn.NumericsMatrix):
        D = np.zeros((M.size0, M.size1))
        for i in range(M.size0):
            for j in range(M.size1):
                D[i, j] = sn.NM_get_value(M, i, j)
        return D
    return np.asarray(sn.SBM_to_dense(M), dtype=float)


def as_sparse(D, kind):
    S = sp.coo_matrix(D) if kind == "coo" else sp.csc_matrix(D)
    # Siconos' 64-bit indices (avoids its conversion warning)
    if kind == "coo":
        return sp.coo_matrix((S.data, (S.row.astype(np.int64), S.col.astype(np.int64))), S.shape)
    return sp.csc_matrix((S.data, S.indices.astype(np.int64), S.indptr.astype(np.int64)), S.shape)


def local(name, kind):
    p = sn.frictionContact_new_from_filename(os.path.join(DATA, "local", name + ".dat"))
    out = sn.FrictionContactProblem(3, as_sparse(dense(p.M), kind), np.array(p.q), np.array(p.mu))
    sn.frictionContact_printInFilename(out, os.path.join(HERE, f"{name}_{kind}.dat"))


def global_(name, kind):
    p = sn.globalFrictionContact_new_from_filename(os.path.join(DATA, "global", name + ".dat"))
    out = sn.GlobalFrictionContactProblem()
    out.dimension = 3
    out.numberOfContacts = p.numberOfContacts
    out.M = as_sparse(dense(p.M), kind)
    out.H = as_sparse(dense(p.H), kind)
    out.q = np.array(p.q)
    out.b = np.array(p.b)
    out.mu = np.array(p.mu)
    sn.globalFrictionContact_printInFileName(out, os.path.join(HERE, f"{name}_{kind}.dat"))


def empty_column():
    W = np.array([[2.0, 0.25, 0, 0.5, 0, 0],
                  [0.25, 1.5, 0, 0, 0, 0],
                  [0, 0, 0, 0, 0, 0],
                  [0.5, 0, 0, 3.0, 0.125, 0],
                  [0, 0, 0, 0.125, 1.0, 0],
                  [0, 0, 0, 0, 0, 1.0]])
    out = sn.FrictionContactProblem(3, as_sparse(W, "csc"), np.array([-1.0, 0.5, 0.0, -2.0, 0.25, 0.125]),
                                    np.array([0.5, 0.3]))
    sn.frictionContact_printInFilename(out, os.path.join(HERE, "empty_column_csc.dat"))


if __name__ == "__main__":
    warnings.filterwarnings("ignore", message="Performance warning")
    local("FC3D_Example1", "csc")
    local("FC3D_Example1", "coo")
    local("Rover4396", "coo")
    local("Rover1039", "csc")
    local("FrictionContact3D_RR_1c", "csc")
    global_("GFC3D_Example1", "csc")
    empty_column()
