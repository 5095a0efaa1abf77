/* cpkit's C API (C99): LCPs and 3-D frictional contact problems from C, Fortran (cpkit.f90) and
 * anything else that calls C. docs/library.md shows how a C or a Fortran code builds against it.
 *
 * Conventions (docs/conventions.md, docs/friction_contact.md):
 *  - LCP(M, q): z >= 0, w = M z + q >= 0, z . w = 0. Matrices are column-major (Fortran order).
 *  - Friction: contact i owns rows 3i..3i+2 of r, u, q and W, normal first, then the two
 *    tangential components; u = W r + q, r_i in the cone ||r_T|| <= mu_i r_N. Units are the
 *    caller's (r an impulse or a force, u a velocity); W = u per r.
 *  - Every entry point returns the command line's exit code and stores it in info->status:
 *      0 solved (verified from the data: the library's finalize() / friction verdict),
 *      1 no solution found (LCP: the solver ended without one; friction: proved none),
 *      2 bad input or misuse; info->message says which argument and why ("cpkit: bad input: ..."),
 *      5 not solved and nothing proved (friction: the solver stopped without a verified answer).
 *    cpkit_system_rate / cpkit_system_step also return 3 (the routes disagree).
 *  - info may be NULL (not wanted); options may be NULL (defaults: cpkit_default_options).
 *  - Nothing is printed, nothing exits, no C++ exception crosses this interface (every failure,
 *    out of memory included, is status 2 with a message). Every function may be called from
 *    many threads at once on different data.
 *  - Structs are plain data; their layout is part of the ABI and does not change within a
 *    major version. Sizes are int; arrays are the caller's unless a function says it allocates
 *    (then cpkit_free releases it).
 */
#ifndef CPKIT_CPKIT_H
#define CPKIT_CPKIT_H

/* The exported functions (the library is built with hidden visibility otherwise). */
#if defined(__GNUC__) && !defined(CPKIT_API)
#define CPKIT_API __attribute__((visibility("default")))
#elif !defined(CPKIT_API)
#define CPKIT_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Options of every solve. */
typedef struct {
  double tol;        /* acceptance tolerance on the unit-free residual, in (0, 1e-3]; 1e-10 */
  int max_iter;      /* iterations (pivots) allowed; 0: the solver's default */
  double time_limit; /* wall-clock limit in seconds; 0: none */
} cpkit_options;

/* What a call did. */
typedef struct {
  int status;         /* = the return value (0, 1, 2, 5; see above) */
  int iterations;     /* iterations or pivots (batched: the sum) */
  double residual;    /* the unit-free residual of the answer (batched: the largest) */
  double seconds;     /* wall time of the call */
  char message[512];  /* why, when status != 0 (empty otherwise); NUL-terminated */
} cpkit_info;

/* tol = 1e-10, max_iter = 0, time_limit = 0. */
CPKIT_API void cpkit_default_options(cpkit_options* options);

/* One LCP of size n >= 1. M: n x n column-major; q, z, w: n. solver: a registered name ("auto",
 * "lemke", "fb-newton", "ipopt", "nlopt", ...; NULL: "auto"). z and w receive the answer
 * (also the last iterate when status != 0); w = M z + q recomputed from the data.
 * n <= 4 with "auto" or "lemke": the solutions are first enumerated in closed form; when there
 * is exactly one, it is the answer (any solver that returns one returns it), verified as every
 * answer is, with iterations = 0; otherwise the named solver runs. */
CPKIT_API int cpkit_lcp_solve(int n, const double* M, const double* q, const char* solver,
                              const cpkit_options* options, double* z, double* w,
                              cpkit_info* info);

/* `count` LCPs of the same size n in one call (count >= 0): problem k is M + k n n, q + k n, its
 * answer z + k n, w + k n. Every problem is checked before any is solved (a bad one: status 2,
 * nothing solved, the message names problem k). status (count entries, may be NULL) receives each
 * problem's code. Returns 0 when every problem is solved, else the code of the first that is not
 * (info->message names it). */
CPKIT_API int cpkit_lcp_solve_batch(int count, int n, const double* M, const double* q,
                                    const char* solver, const cpkit_options* options, double* z,
                                    double* w, int* status, cpkit_info* info);

/* One friction problem with `contacts` >= 1 contacts: W (3 contacts x 3 contacts) in compressed
 * sparse columns (col_ptr: 3 contacts + 1 entries starting at 0, row_index and values: nnz
 * entries, row indices 0-based), q: 3 contacts, mu: contacts (each >= 0). solver: "auto"
 * (NULL), "nsgs", "fb-soc", "prox", "lemke" (faceted), "ipopt". r and u (3 contacts) receive the
 * answer, u = W r + q recomputed. One contact with "auto" or "nsgs": every solution is first
 * found in closed form; when there is exactly one, it is the answer (verified, iterations = 0);
 * otherwise the named solver runs. */
CPKIT_API int cpkit_fc3d_solve(int contacts, int nnz, const int* col_ptr, const int* row_index,
                               const double* values, const double* q, const double* mu,
                               const char* solver, const cpkit_options* options, double* r,
                               double* u, cpkit_info* info);

/* `count` friction problems of `contacts` contacts each, with DENSE W (3 contacts square,
 * column-major): problem k is W + k m m, q + k m, mu + k contacts (m = 3 contacts); its answer
 * r + k m, u + k m. Checks, status and return value as cpkit_lcp_solve_batch. */
CPKIT_API int cpkit_fc3d_solve_batch(int count, int contacts, const double* W, const double* q,
                                     const double* mu, const char* solver,
                                     const cpkit_options* options, double* r, double* u,
                                     int* status, cpkit_info* info);

/* The friction verdict on a candidate r (3 contacts) of the problem (W in CSC as above):
 * u = W r + q recomputed, the errors of core/friction_verdict.hpp. */
typedef struct {
  double unit_free;    /* cpkit's acceptance number (unit-free; accepted when <= tol) */
  double relative_q;   /* ||natural map|| / ||q||_2 (Acary, Bremond, Huber 2018) */
  double relative_max; /* ||natural map|| / max(||q||, ||r||, ||u||): Siconos' fc3d error */
} cpkit_fc3d_error_values;
/* Returns 0 when r is accepted (unit_free <= options->tol), 5 when not, 2 on bad input.
 * errors and states may be NULL; states (contacts entries) receive 0 separated, 1 stick,
 * 2 slip. info->residual = unit_free. */
CPKIT_API int cpkit_fc3d_errors(int contacts, int nnz, const int* col_ptr, const int* row_index,
                                const double* values, const double* q, const double* mu,
                                const double* r, const cpkit_options* options,
                                cpkit_fc3d_error_values* errors, int* states, cpkit_info* info);

/* A local friction problem read from a file: FCLIB (HDF5, .hdf5/.h5) or a Siconos
 * FrictionContact .dat file, chosen by content. W in CSC as above (0-based). */
typedef struct {
  int contacts;
  int nnz;
  int* col_ptr;     /* 3 contacts + 1 */
  int* row_index;   /* nnz */
  double* values;   /* nnz */
  double* q;        /* 3 contacts */
  double* mu;       /* contacts */
} cpkit_fc3d_problem;
/* Library-allocated: fills *problem (its arrays allocated by cpkit); release them with
 * cpkit_fc3d_problem_free. On failure (2) the struct is zeroed and nothing is allocated. */
CPKIT_API int cpkit_fc3d_read(const char* path, cpkit_fc3d_problem* problem, cpkit_info* info);
CPKIT_API void cpkit_fc3d_problem_free(cpkit_fc3d_problem* problem);
/* Caller-owned: cpkit_fc3d_read_sizes gives contacts and nnz; cpkit_fc3d_read_into fills arrays
 * of those sizes (status 2 when the sizes given differ from the file's). */
CPKIT_API int cpkit_fc3d_read_sizes(const char* path, int* contacts, int* nnz,
                                    cpkit_info* info);
CPKIT_API int cpkit_fc3d_read_into(const char* path, int contacts, int nnz, int* col_ptr,
                                   int* row_index, double* values, double* q, double* mu,
                                   cpkit_info* info);

/* The rate problem and the incremental step of a contact system. system_json: the text of a
 * system file (docs/file_formats.md: 2-D N-point or "dim": 3). dF: the load rate / increment,
 * n_dF numbers (2 or 3 per point; NULL with n_dF = 0: the file's "dF", rate problem only).
 * method (rate only): "enumerate" (NULL), "lemke", "fb-newton", "ipopt"; facets (rate only): 0,
 * or K (3..64) for the faceted route of 3-D systems (`--facets K`; N coupled 3-D points need it,
 * docs/contact_3d.md). *solution_json receives
 * the JSON text `cpkit rate --system FILE --json` / `cpkit step --system FILE --all --json`
 * print (every solution; N coupled 3-D points: the step's fb-soc chain), allocated by cpkit:
 * release it with cpkit_free (NULL on status 2). Returns the command line's exit code
 * (0 a solution, 1 none, 2 bad input, 3 the routes disagree, 5 not proved complete). */
CPKIT_API int cpkit_system_rate(const char* system_json, int n_dF, const double* dF,
                                const char* method, int facets, char** solution_json,
                                cpkit_info* info);
CPKIT_API int cpkit_system_step(const char* system_json, int n_dF, const double* dF,
                                char** solution_json, cpkit_info* info);

/* Releases memory allocated by cpkit (JSON text); NULL is allowed. */
CPKIT_API void cpkit_free(void* p);

/* "0.1.0": the library's version (static storage). */
CPKIT_API const char* cpkit_version(void);

#ifdef __cplusplus
}
#endif

#endif /* CPKIT_CPKIT_H */
