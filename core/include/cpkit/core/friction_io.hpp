#pragma once
/// \file friction_io.hpp
/// Reading and writing 3-D frictional contact problems in the files other contact codes write:
/// FCLIB (HDF5, through Debian's libfclib) and Siconos' FrictionContact / GlobalFrictionContact
/// `.dat` text files (as Siconos numerics 4.4 reads them: dense or sparse-block matrices). The
/// format is chosen by content (the HDF5 signature), not by the file name.
/// Conventions are friction_problem.hpp's (FCLIB's and Siconos'): contact i owns rows
/// 3i..3i+2, normal first; u = W r + q; globally M v = H r + f, u = H^T v + w (Siconos' q and b
/// are cpkit's f and w).
#include <string>

#include <Eigen/Dense>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit {

/// A local problem (W, q, mu) from an FCLIB local file (/fclib_local) or a Siconos
/// FrictionContact .dat file (dimension 3). Throws InputError naming the file and what is wrong
/// (unreadable, neither format, truncated, inconsistent or huge sizes, non-finite numbers,
/// negative mu, 2-D problems, FCLIB's optional V/R constraints); never allocates from a declared
/// size before checking it against what the file holds, never ends the process.
/// The file is read once: a .dat file may come through a pipe or FIFO (`<(cat F.dat)`); an HDF5
/// file must be a regular file (HDF5 seeks); HDF5 after a user block is found (at 512, 1024, ...
/// bytes, as HDF5 looks for it). FCLIB datasets are refused (InputError naming the dataset)
/// when their data is not in the file or cannot be decoded: external storage or links, virtual
/// datasets, chunks never written, a filter this HDF5 lacks (h5py's LZF), a damaged chunk, or
/// more data than the file's size can plausibly hold (64 times it + 16 MiB). The title and
/// description are one string each (fixed-length with any padding, or variable-length as h5py
/// writes a str); an array of strings there is refused.
FrictionContactProblem read_friction_problem(const std::string& path);

/// The Siconos FrictionContact .dat reader on text already in memory; `origin` names it in
/// messages (the fuzz target's entry point).
FrictionContactProblem parse_friction_dat(const std::string& text, const std::string& origin);
/// The Siconos GlobalFrictionContact .dat reader on text in memory.
GlobalFrictionContactProblem parse_global_friction_dat(const std::string& text,
                                                       const std::string& origin);

/// A global problem (M, H, f, w, mu) from an FCLIB global file (/fclib_global, without the
/// optional G) or a Siconos GlobalFrictionContact .dat file. Errors as read_friction_problem.
GlobalFrictionContactProblem read_global_friction_problem(const std::string& path);

/// What a friction problem file holds: a local problem, or a global one (is_global).
struct FrictionProblemFile {
  bool is_global = false;
  FrictionContactProblem local;         ///< when !is_global
  GlobalFrictionContactProblem global;  ///< when is_global
};

/// A local or a global problem, whichever the file holds, read once (so a pipe holding either
/// kind reads). FCLIB: the /fclib_global group makes it global. A .dat file is read as a local
/// problem, else as a global one; when neither reads, the InputError is that of the reading
/// that got further into the file (a damaged global file is reported as a global one).
FrictionProblemFile read_friction_problem_file(const std::string& path);

/// Writes `problem` and a solution (r, u = W r + q, each 3 n_c) as an FCLIB local file that
/// libfclib (fclib_read_local, fclib_read_solution) reads back. W is stored compressed by
/// columns. The solution group also holds `/solution/status`, one 32-bit integer a contact:
/// 0 separated, 1 stick, 2 slip (friction_contacts(problem, r), the state `fc solve --json`
/// prints in per_contact; the key is in its string attribute "states"); libfclib and Siconos
/// ignore that extra dataset. An existing file at `path` is replaced. InputError on
/// inconsistent sizes or when the file cannot be written.
void write_friction_solution(const std::string& path, const FrictionContactProblem& problem,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u);

}  // namespace cpkit
