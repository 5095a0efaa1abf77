! cpkit from Fortran (docs/library.md): compile the installed module, then link with
!   gfortran -c PREFIX/include/cpkit/cpkit.f90
!   gfortran capi_example.f90 cpkit.o $(pkg-config --libs cpkit) -o capi_example_f
! Hand answer: M = [[2, 1], [1, 2]], q = (-5, -6) has z = (4/3, 7/3), w = 0 (M z = -q, z > 0).
program capi_example
  use, intrinsic :: iso_c_binding
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use cpkit
  implicit none
  real(c_double) :: M(4) = [2d0, 1d0, 1d0, 2d0], q(2) = [-5d0, -6d0], z(2), w(2)
  integer(c_int) :: s
  type(cpkit_info), target :: info

  s = cpkit_lcp_solve(2_c_int, M, q, "lemke"//c_null_char, c_null_ptr, z, w, c_null_ptr)
  print *, s
  print *, z
  if (s /= 0 .or. abs(z(1) - 4d0 / 3) > 1d-12 .or. abs(z(2) - 7d0 / 3) > 1d-12) error stop 1

  ! Bad input is a status with a message (c_loc(info): wanted), never a crash or an exit.
  s = cpkit_lcp_solve(-1_c_int, M, q, "lemke"//c_null_char, c_null_ptr, z, w, c_loc(info))
  print '(a, i0, 2a)', 'n = -1: status ', s, ': ', cpkit_message(info)
  if (s /= 2) error stop 1
  q(1) = ieee_value(q(1), ieee_quiet_nan)
  s = cpkit_lcp_solve(2_c_int, M, q, "lemke"//c_null_char, c_null_ptr, z, w, c_loc(info))
  print '(a, i0, 2a)', 'NaN in q: status ', s, ': ', cpkit_message(info)
  if (s /= 2) error stop 1
end program capi_example
