# `tribo sweep` under MPI: the same 12-point rig sweep run serially and by `mpirun -np 2` gives the
# same results.csv (the wall_s column aside) — the failed rows included; and an MPI run resumes a
# sweep whose results.csv holds some rows and a torn last line, recomputing only the rest.
# Inputs: TRIBO, MPIEXEC, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/sweep_test_common.cmake)
# jobs = 1: one point per rank, so both ranks (rank 0 too) run points.
write_rig_sweep(1)
set(MPIRUN ${MPIEXEC} -np 2 --oversubscribe --allow-run-as-root)

execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/serial RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "serial sweep failed (${status}): ${err}")
endif()
execute_process(COMMAND ${MPIRUN} ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/mpi
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT status EQUAL 0 OR NOT out MATCHES "on 2 MPI ranks")
  message(FATAL_ERROR "MPI sweep failed (${status}): ${out}\n${err}")
endif()
rows_without_wall(${WORK}/serial/results.csv serial)
rows_without_wall(${WORK}/mpi/results.csv mpi)
list(LENGTH mpi n)
if(NOT n EQUAL 13 OR NOT serial STREQUAL mpi)
  message(FATAL_ERROR "MPI results differ from the serial ones:\n${serial}\n---\n${mpi}")
endif()
file(READ ${WORK}/mpi/sweep.json provenance)
if(NOT provenance MATCHES "\"mpi_ranks\": 2")
  message(FATAL_ERROR "sweep.json does not record the 2 ranks: ${provenance}")
endif()

# Resume under MPI: 5 rows kept and a torn sixth, as a kill mid-write leaves them.
file(MAKE_DIRECTORY ${WORK}/resumed)
file(COPY ${WORK}/serial/sweep.json DESTINATION ${WORK}/resumed)
file(STRINGS ${WORK}/serial/results.csv lines)
list(FILTER lines EXCLUDE REGEX "^#")
list(SUBLIST lines 0 6 kept)
list(GET lines 6 torn)
string(SUBSTRING "${torn}" 0 7 torn)
list(JOIN kept "\n" text)
string(REPLACE "${WORK}/serial" "${WORK}/resumed" text "${text}")  # as if this folder had written them
file(WRITE ${WORK}/resumed/results.csv "${text}\n${torn}")
execute_process(COMMAND ${MPIRUN} ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/resumed
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "resumed MPI sweep failed (${status}): ${out}\n${err}")
endif()
rows_without_wall(${WORK}/resumed/results.csv resumed)
if(NOT serial STREQUAL resumed)
  message(FATAL_ERROR "MPI-resumed results differ from the serial ones:\n${serial}\n---\n${resumed}")
endif()
file(GLOB resumed_points LIST_DIRECTORIES true ${WORK}/resumed/points/*)
list(LENGTH resumed_points recomputed)
if(NOT recomputed EQUAL 7)
  message(FATAL_ERROR "the resumed sweep should run only the 7 missing points, ran ${recomputed}")
endif()

# A changed spec is refused once, by rank 0, with status 2.
file(APPEND ${WORK}/spec.toml "# changed\n")
execute_process(COMMAND ${MPIRUN} ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/mpi
                RESULT_VARIABLE status ERROR_VARIABLE err TIMEOUT 120)
if(status EQUAL 0 OR NOT err MATCHES "different spec")
  message(FATAL_ERROR "a changed spec on an MPI resume: expected a refusal, got ${status}: ${err}")
endif()

# Points that start MPI themselves (hypre's BoomerAMG: a 256² Reynolds solve takes the multigrid
# path) run as singletons, not as members of the sweep's job: the launcher's variables are
# stripped from their environment.
file(WRITE ${WORK}/discs.toml "[geometry]\nkind = \"parallel_discs\"\nradius_m = 4.7625e-3\ngap_m = 1e-6\n"
  "gap_rate_m_per_s = -1e-6\n[lubricant]\nviscosity_Pa_s = 0.021\n[motion]\nsliding_speed_m_per_s = 0.0\n[grid]\nn = 256\n")
file(WRITE ${WORK}/discs-spec.toml "[base]\ncommand = \"reynolds\"\nconfig = \"discs.toml\"\n"
  "[[axis]]\nkey = \"geometry.gap_m\"\nvalues = [1e-6, 2e-6]\n[sweep]\njobs = 1\n"
  "[outputs]\ncolumns = [\"reynolds.json:linear_solver\", \"reynolds.json:load_N\"]\n")
execute_process(COMMAND ${MPIRUN} ${TRIBO} sweep ${WORK}/discs-spec.toml --out ${WORK}/discs
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
file(STRINGS ${WORK}/discs/results.csv lines REGEX ",ok,,[^,]*,boomeramg-pcg,")
list(LENGTH lines ok)
if(NOT status EQUAL 0 OR NOT ok EQUAL 2)
  file(READ ${WORK}/discs/results.csv all)
  message(FATAL_ERROR "hypre points under mpirun (${status}): ${err}\n${all}")
endif()
# The same points in a serial sweep, whose points are forked children of the sweep: hypre starts
# MPI in each child afresh, and the loads equal the MPI run's.
execute_process(COMMAND ${TRIBO} sweep ${WORK}/discs-spec.toml --out ${WORK}/discs-serial
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
rows_without_wall(${WORK}/discs/results.csv discs_mpi 1)
rows_without_wall(${WORK}/discs-serial/results.csv discs_serial 1)
if(NOT status EQUAL 0 OR NOT discs_mpi STREQUAL discs_serial)
  message(FATAL_ERROR "hypre points in a serial sweep (${status}): ${err}\n${discs_serial}\n---\n${discs_mpi}")
endif()
