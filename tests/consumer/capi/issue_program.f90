! The Fortran program of issue 37, as written there, with the two lines that print its answer:
! it must print 0 and z = (4/3, 7/3) (M z = -q with z > 0).
use iso_c_binding
use cpkit
real(c_double) :: M(4) = [2d0, 1d0, 1d0, 2d0], q(2) = [-5d0, -6d0], z(2), w(2)
integer(c_int) :: s
s = cpkit_lcp_solve(2_c_int, M, q, "lemke"//c_null_char, c_null_ptr, z, w, c_null_ptr)
print *, s
print *, z
end
