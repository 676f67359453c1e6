# Every dependency comes from a Debian 12 package (tools/install-deps.sh).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(tomlplusplus REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 QUIET)
find_package(SUNDIALS 6 REQUIRED COMPONENTS cvode nvecserial sunmatrixdense sunlinsoldense)
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
find_library(FFTW3_OMP_LIB fftw3_omp REQUIRED)

# SuiteSparse 5.x on Debian 12 ships no CMake config: locate headers and libraries directly.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
foreach(lib cholmod umfpack amd colamd suitesparseconfig)
  find_library(SUITESPARSE_${lib}_LIB ${lib} REQUIRED)
  list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${lib}_LIB})
endforeach()
add_library(tribo_suitesparse INTERFACE)
target_include_directories(tribo_suitesparse INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(tribo_suitesparse INTERFACE ${SUITESPARSE_LIBRARIES})

add_library(tribo_fftw INTERFACE)
target_link_libraries(tribo_fftw INTERFACE PkgConfig::FFTW3 ${FFTW3_OMP_LIB} OpenMP::OpenMP_CXX)

if(NOT TARGET CLI11::CLI11)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
endif()
