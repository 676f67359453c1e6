// The MPI C API, for the code that calls it: lubrication/linear_solver.cpp (hypre) and
// apps/cmd_sweep.cpp (`tribo sweep` under mpirun). Include it before anything else that includes
// mpi.h. Header only, and it needs MPI's include directories, which tribo::hypre and MPI::MPI_CXX
// give but tribo_numerics does not: not installed (cmake/TriboInstall.cmake).
#pragma once

// hypre's headers include mpi.h; keep Open MPI / MPICH from pulling in their C++ bindings.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#ifndef MPICH_SKIP_MPICXX
#define MPICH_SKIP_MPICXX 1
#endif
#include <mpi.h>
