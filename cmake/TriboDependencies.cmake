# Every dependency comes from a Debian 12 package (tools/install-deps.sh).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(tomlplusplus REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 QUIET)
find_package(SUNDIALS 6 REQUIRED COMPONENTS cvode nvecserial sunmatrixdense sunlinsoldense sunlinsolspgmr)

# FFTW, SuiteSparse, hypre (+ Open MPI) and LAPACK: tribo::fftw, tribo::suitesparse, tribo::hypre,
# tribo::lapack, found by the file the installed package config uses too. The old names stay as aliases.
include(${CMAKE_CURRENT_LIST_DIR}/TriboSystemLibraries.cmake)
add_library(tribo_fftw ALIAS tribo::fftw)
add_library(tribo_suitesparse ALIAS tribo::suitesparse)
add_library(tribo_hypre ALIAS tribo::hypre)

if(NOT TARGET CLI11::CLI11)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
endif()
