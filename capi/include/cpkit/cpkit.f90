! cpkit's Fortran 2003 interface: module cpkit, bind(C) interfaces of the C API (cpkit.h, whose
! comments are the reference for every argument). Installed as source: compile it with your own
! compiler (gfortran -c PREFIX/include/cpkit/cpkit.f90), then link with $(pkg-config --libs cpkit).
!
! Conventions:
!  - Matrices are column-major, as Fortran stores them: pass M(n, n) or W(3c, 3c) as they are.
!  - Strings are C strings: "lemke"//c_null_char (c_null_ptr is not a string: pass
!    "auto"//c_null_char for the default solver).
!  - options and info are type(c_ptr), value: c_null_ptr means defaults / not wanted; otherwise
!    declare type(cpkit_options), target :: opt (or type(cpkit_info)) and pass c_loc(opt).
!  - The result is the command line's exit code (0 solved, 1 no solution found, 2 bad input,
!    5 not solved / not proved); cpkit_message(info) gives info%message as a Fortran string.
!  - CSC indices (col_ptr, row_index) are 0-based, as in C.
module cpkit
  use, intrinsic :: iso_c_binding
  implicit none
  private
  public :: cpkit_options, cpkit_info, cpkit_fc3d_error_values, cpkit_fc3d_problem
  public :: cpkit_default_options, cpkit_lcp_solve, cpkit_lcp_solve_batch
  public :: cpkit_fc3d_solve, cpkit_fc3d_solve_batch, cpkit_fc3d_errors
  public :: cpkit_fc3d_read, cpkit_fc3d_problem_free, cpkit_fc3d_read_sizes, cpkit_fc3d_read_into
  public :: cpkit_system_rate, cpkit_system_step, cpkit_free, cpkit_message

  type, bind(C) :: cpkit_options
    real(c_double) :: tol = 1d-10
    integer(c_int) :: max_iter = 0
    real(c_double) :: time_limit = 0
  end type cpkit_options

  type, bind(C) :: cpkit_info
    integer(c_int) :: status = 0
    integer(c_int) :: iterations = 0
    real(c_double) :: residual = 0
    real(c_double) :: seconds = 0
    character(kind=c_char) :: message(512) = c_null_char
  end type cpkit_info

  type, bind(C) :: cpkit_fc3d_error_values
    real(c_double) :: unit_free, relative_q, relative_max
  end type cpkit_fc3d_error_values

  ! Arrays allocated by cpkit_fc3d_read (c_f_pointer them; release with cpkit_fc3d_problem_free).
  type, bind(C) :: cpkit_fc3d_problem
    integer(c_int) :: contacts, nnz
    type(c_ptr) :: col_ptr, row_index, values, q, mu
  end type cpkit_fc3d_problem

  interface
    subroutine cpkit_default_options(options) bind(C, name="cpkit_default_options")
      import :: cpkit_options
      type(cpkit_options), intent(out) :: options
    end subroutine

    integer(c_int) function cpkit_lcp_solve(n, M, q, solver, options, z, w, info) &
        bind(C, name="cpkit_lcp_solve")
      import :: c_int, c_double, c_char, c_ptr
      integer(c_int), value :: n
      real(c_double), intent(in) :: M(*), q(*)
      character(kind=c_char), intent(in) :: solver(*)
      type(c_ptr), value :: options
      real(c_double), intent(out) :: z(*), w(*)
      type(c_ptr), value :: info
    end function

    integer(c_int) function cpkit_lcp_solve_batch(count, n, M, q, solver, options, z, w, &
        status, info) bind(C, name="cpkit_lcp_solve_batch")
      import :: c_int, c_double, c_char, c_ptr
      integer(c_int), value :: count, n
      real(c_double), intent(in) :: M(*), q(*)
      character(kind=c_char), intent(in) :: solver(*)
      type(c_ptr), value :: options
      real(c_double), intent(out) :: z(*), w(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: info
    end function

    integer(c_int) function cpkit_fc3d_solve(contacts, nnz, col_ptr, row_index, values, q, mu, &
        solver, options, r, u, info) bind(C, name="cpkit_fc3d_solve")
      import :: c_int, c_double, c_char, c_ptr
      integer(c_int), value :: contacts, nnz
      integer(c_int), intent(in) :: col_ptr(*), row_index(*)
      real(c_double), intent(in) :: values(*), q(*), mu(*)
      character(kind=c_char), intent(in) :: solver(*)
      type(c_ptr), value :: options
      real(c_double), intent(out) :: r(*), u(*)
      type(c_ptr), value :: info
    end function

    integer(c_int) function cpkit_fc3d_solve_batch(count, contacts, W, q, mu, solver, options, &
        r, u, status, info) bind(C, name="cpkit_fc3d_solve_batch")
      import :: c_int, c_double, c_char, c_ptr
      integer(c_int), value :: count, contacts
      real(c_double), intent(in) :: W(*), q(*), mu(*)
      character(kind=c_char), intent(in) :: solver(*)
      type(c_ptr), value :: options
      real(c_double), intent(out) :: r(*), u(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: info
    end function

    ! errors and states: c_loc(...) or c_null_ptr (not wanted).
    integer(c_int) function cpkit_fc3d_errors(contacts, nnz, col_ptr, row_index, values, q, mu, &
        r, options, errors, states, info) bind(C, name="cpkit_fc3d_errors")
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: contacts, nnz
      integer(c_int), intent(in) :: col_ptr(*), row_index(*)
      real(c_double), intent(in) :: values(*), q(*), mu(*), r(*)
      type(c_ptr), value :: options, errors, states, info
    end function

    integer(c_int) function cpkit_fc3d_read(path, problem, info) bind(C, name="cpkit_fc3d_read")
      import :: c_int, c_char, c_ptr, cpkit_fc3d_problem
      character(kind=c_char), intent(in) :: path(*)
      type(cpkit_fc3d_problem), intent(out) :: problem
      type(c_ptr), value :: info
    end function

    subroutine cpkit_fc3d_problem_free(problem) bind(C, name="cpkit_fc3d_problem_free")
      import :: cpkit_fc3d_problem
      type(cpkit_fc3d_problem), intent(inout) :: problem
    end subroutine

    integer(c_int) function cpkit_fc3d_read_sizes(path, contacts, nnz, info) &
        bind(C, name="cpkit_fc3d_read_sizes")
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), intent(out) :: contacts, nnz
      type(c_ptr), value :: info
    end function

    integer(c_int) function cpkit_fc3d_read_into(path, contacts, nnz, col_ptr, row_index, &
        values, q, mu, info) bind(C, name="cpkit_fc3d_read_into")
      import :: c_int, c_double, c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: contacts, nnz
      integer(c_int), intent(out) :: col_ptr(*), row_index(*)
      real(c_double), intent(out) :: values(*), q(*), mu(*)
      type(c_ptr), value :: info
    end function

    ! method: "enumerate"//c_null_char, ... or c_null_ptr; solution_json receives a C string
    ! (release it with cpkit_free).
    integer(c_int) function cpkit_system_rate(system_json, n_dF, dF, method, facets, &
        solution_json, info) bind(C, name="cpkit_system_rate")
      import :: c_int, c_double, c_char, c_ptr
      character(kind=c_char), intent(in) :: system_json(*)
      integer(c_int), value :: n_dF
      real(c_double), intent(in) :: dF(*)
      type(c_ptr), value :: method
      integer(c_int), value :: facets
      type(c_ptr), intent(out) :: solution_json
      type(c_ptr), value :: info
    end function

    integer(c_int) function cpkit_system_step(system_json, n_dF, dF, solution_json, info) &
        bind(C, name="cpkit_system_step")
      import :: c_int, c_double, c_char, c_ptr
      character(kind=c_char), intent(in) :: system_json(*)
      integer(c_int), value :: n_dF
      real(c_double), intent(in) :: dF(*)
      type(c_ptr), intent(out) :: solution_json
      type(c_ptr), value :: info
    end function

    subroutine cpkit_free(p) bind(C, name="cpkit_free")
      import :: c_ptr
      type(c_ptr), value :: p
    end subroutine
  end interface

contains

  ! info%message as a Fortran string (up to the terminating NUL, trailing blanks dropped).
  function cpkit_message(info) result(text)
    type(cpkit_info), intent(in) :: info
    character(len=:), allocatable :: text
    integer :: k
    k = 0
    do while (k < size(info%message))
      if (info%message(k + 1) == c_null_char) exit
      k = k + 1
    end do
    allocate(character(len=k) :: text)
    do k = 1, len(text)
      text(k:k) = info%message(k)
    end do
  end function cpkit_message

end module cpkit
