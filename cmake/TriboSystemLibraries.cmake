# The system libraries Debian 12 ships without a usable CMake package — FFTW (pkg-config, double
# and single precision, plus its OpenMP threads library), SuiteSparse 5 and hypre (neither a
# pkg-config nor a CMake file) — and LAPACK (CMake's FindLAPACK), as imported targets
# tribo::fftw, tribo::suitesparse, tribo::hypre and tribo::lapack. One file for both uses: the
# build includes it from TriboDependencies.cmake, and the installed triboConfig.cmake includes it
# so that a consumer's find_package(tribo) re-finds them on its own machine instead of trusting
# paths recorded at tribo's build. Expects OpenMP::OpenMP_CXX to exist (found before).
if(TARGET tribo::fftw AND TARGET tribo::suitesparse AND TARGET tribo::hypre AND TARGET tribo::lapack)
  return()
endif()

find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
# Single precision (the normal solve's products far from its tolerance): the same Debian package.
pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
find_library(FFTW3_OMP_LIB fftw3_omp REQUIRED)
add_library(tribo::fftw INTERFACE IMPORTED)
target_link_libraries(tribo::fftw INTERFACE PkgConfig::FFTW3 PkgConfig::FFTW3F ${FFTW3_OMP_LIB} OpenMP::OpenMP_CXX)

find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
set(TRIBO_SUITESPARSE_LIBRARIES "")
foreach(lib cholmod umfpack amd colamd suitesparseconfig)
  find_library(SUITESPARSE_${lib}_LIB ${lib} REQUIRED)
  list(APPEND TRIBO_SUITESPARSE_LIBRARIES ${SUITESPARSE_${lib}_LIB})
endforeach()
add_library(tribo::suitesparse INTERFACE IMPORTED)
target_include_directories(tribo::suitesparse INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(tribo::suitesparse INTERFACE ${TRIBO_SUITESPARSE_LIBRARIES})

# hypre (BoomerAMG, the multigrid backend of lubrication/linear_solver.h) is built with Open MPI:
# link MPI too (the backend calls MPI_Init_thread itself). Found through MPI's CXX component
# without the deprecated C++ bindings (the C API is what hypre and linear_solver.cpp call); plain
# paths rather than MPI::MPI_CXX, whose scope is the directory that found it.
set(MPI_CXX_SKIP_MPICXX ON)
find_package(MPI REQUIRED COMPONENTS CXX)
find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre REQUIRED)
find_library(HYPRE_LIBRARY HYPRE REQUIRED)
add_library(tribo::hypre INTERFACE IMPORTED)
target_include_directories(tribo::hypre INTERFACE ${HYPRE_INCLUDE_DIR} ${MPI_CXX_INCLUDE_DIRS})
target_compile_definitions(tribo::hypre INTERFACE ${MPI_CXX_COMPILE_DEFINITIONS})
target_link_libraries(tribo::hypre INTERFACE ${HYPRE_LIBRARY} ${MPI_CXX_LIBRARIES})

# LAPACK (numerics/dense_solve.h): the liblapack.so.3 Debian's alternatives select — OpenBLAS's
# once libopenblas-openmp-dev is installed (tools/install-deps.sh), which SuiteSparse's BLAS calls
# then use too; the reference LAPACK otherwise (correct, several times slower).
find_package(LAPACK REQUIRED)
add_library(tribo::lapack INTERFACE IMPORTED)
target_link_libraries(tribo::lapack INTERFACE LAPACK::LAPACK)
