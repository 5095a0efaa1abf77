#!/usr/bin/python3
"""Writes the .npy test files of tests/core/test_io_npy.cpp with numpy itself (run from this
folder: /usr/bin/python3 make_npy.py). The values are literals here and in the test."""
import numpy as np

# A 3 x 3 LCP with the unique solution z = (1, 0, 0), w = (0, 1, 3) (M = [[2, 1, 0], [1, 3, 1],
# [0, 1, 4]] is positive definite; q = -M z + w).
M = np.array([[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]])
q = np.array([-2.0, 0.0, 3.0])
# A non-symmetric matrix, so that C and Fortran order differ in the file.
A = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.5], [-7.0, 8.25, 1e-300]])

np.save("lcp3.npy", M)                     # C order, format 1.0
np.save("lcp3.q.npy", q)                   # q beside M: lcp3.q.npy
np.save("A_c.npy", np.ascontiguousarray(A))
np.save("A_f.npy", np.asfortranarray(A))   # fortran_order: True
np.save("q_column.npy", q.reshape(3, 1))   # shape (3, 1)
with open("A_v2.npy", "wb") as f:          # format 2.0 (4-byte header length)
    np.lib.format.write_array(f, A, version=(2, 0))
with open("A_v3.npy", "wb") as f:          # format 3.0 (UTF-8 header)
    np.lib.format.write_array(f, A, version=(3, 0))
np.save("A_big_endian.npy", A.astype(">f8"))
np.save("A_int64.npy", np.array([[1, 2], [3, 4]], dtype="<i8"))
np.save("A_float32.npy", A.astype("<f4"))
np.save("rect_2x3.npy", np.ones((2, 3)))
np.save("q_2d.npy", np.ones((2, 2)))
np.save("A_3d.npy", np.ones((2, 2, 2)))
