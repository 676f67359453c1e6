#include "lubrication/hypre_runtime.h"

#include <HYPRE.h>

#include <cstdlib>

namespace tribo::lubrication::detail {

HypreRuntime& hypre_runtime() {
  static HypreRuntime runtime;
  return runtime;
}

namespace {

void finalize_hypre() {
  HypreRuntime& rt = hypre_runtime();
  std::lock_guard<std::mutex> lock(rt.mutex);
  if (!rt.ready || rt.finalized) return;
  rt.finalized = true;
  HYPRE_Finalize();
  int mpi_finalized = 0;
  MPI_Finalized(&mpi_finalized);
  if (rt.started_mpi && !mpi_finalized) MPI_Finalize();
}

}  // namespace

std::string start_hypre_locked() {
  HypreRuntime& rt = hypre_runtime();
  if (rt.ready) return rt.finalized ? "hypre: already finalised (solve after program exit began)" : "";
  if (!rt.error.empty()) return rt.error;
  int initialized = 0;
  if (MPI_Initialized(&initialized) != MPI_SUCCESS) return rt.error = "hypre: MPI_Initialized failed";
  if (!initialized) {
    int provided = MPI_THREAD_SINGLE;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
      return rt.error = "hypre: MPI_Init_thread failed (hypre on this system is built with MPI)";
    rt.started_mpi = true;
    if (provided < MPI_THREAD_SERIALIZED)
      return rt.error = "hypre: MPI provides thread level " + std::to_string(provided) +
                        " < MPI_THREAD_SERIALIZED; the hypre backends may be called from any thread";
  } else {
    int provided = MPI_THREAD_SINGLE;
    MPI_Query_thread(&provided);
    if (provided < MPI_THREAD_SERIALIZED)
      return rt.error = "hypre: the program initialised MPI with thread level " + std::to_string(provided) +
                        " < MPI_THREAD_SERIALIZED";
  }
  if (const HYPRE_Int e = HYPRE_Init(); e != 0) return rt.error = "hypre: HYPRE_Init failed, code " + std::to_string(e);
  rt.ready = true;
  std::atexit(finalize_hypre);
  return "";
}

std::string hypre_error(const char* routine, HYPRE_Int code) {
  char text[256] = {0};
  HYPRE_DescribeError(code, text);
  HYPRE_ClearAllErrors();
  return std::string(routine) + " failed, hypre error " + std::to_string(code) + " (" + text + ")";
}

}  // namespace tribo::lubrication::detail
