// Process-wide hypre state shared by the hypre backends (linear_solver.cpp: BoomerAMG;
// struct_multigrid.cpp: PFMG). Internal to tribo_lubrication: not installed.
//
// hypre on Debian 12 is built with MPI and keeps global state (error flag, memory handle), so:
// MPI is started on first use unless the program already did (MPI_Init_thread, SERIALIZED),
// HYPRE_Init runs once, both are finalised at exit, and every hypre call in the process is made
// with hypre_runtime().mutex held.
#pragma once

#include "numerics/mpi.h"  // before hypre's headers, which include mpi.h
#include <HYPRE_utilities.h>

#include <mutex>
#include <string>

namespace tribo::lubrication::detail {

struct HypreRuntime {
  std::mutex mutex;
  bool ready = false;
  bool finalized = false;   // set by the exit handler; objects left after it are the OS's to free
  bool started_mpi = false;
  std::string error;        // why hypre cannot be used in this process (sticky)
};

HypreRuntime& hypre_runtime();

// With the mutex held: starts MPI and hypre if needed. Returns "" when hypre is usable, else why not.
std::string start_hypre_locked();

// "routine failed, hypre error N (text)"; clears hypre's global error flag.
std::string hypre_error(const char* routine, HYPRE_Int code);

}  // namespace tribo::lubrication::detail
