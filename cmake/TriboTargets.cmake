# Standard install directories (lib, include, share, bin): tribo_add_library names the installed
# include root, cmake/TriboInstall.cmake the rest.
include(GNUInstallDirs)

# tribo_add_library(name SOURCES ... DEPENDS ...): one library target per folder, also known as
# tribo::<name without "tribo_"> — the name it is exported under (cmake/TriboInstall.cmake), so
# that code in this tree and a project using the installed package link the same names.
# Headers are included by their path from the repository root ("contact/grid.h"); installed,
# that root is <prefix>/include/tribo.
function(tribo_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  string(REGEX REPLACE "^tribo_" "" export_name ${name})
  add_library(tribo::${export_name} ALIAS ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${export_name})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/tribo>)
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
  # Sanitized static libraries need the sanitizer runtimes wherever they are linked, including a
  # consumer of the installed package — and the consumer must compile with the same flags: they
  # change header code both sides share (Eigen allocates by hand-aligned malloc under ASan and
  # frees accordingly; a consumer compiled without it frees such a block with plain free()). In
  # this tree every target already compiles with them (add_compile_options), hence install only.
  if(TRIBO_SANITIZE)
    target_link_options(${name} INTERFACE -fsanitize=address,undefined)
    target_compile_options(${name} INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined -fno-omit-frame-pointer>)
  endif()
  tribo_header_check(${name} ${ARG_SOURCES})
endfunction()

# tribo_header_check(library SOURCES ...): every header beside the library's sources (and in its
# folder's subfolders that hold headers only) compiled alone, in a source that includes nothing
# else — built by target tribo_header_check only (CI). The builds compile in unity batches, where
# a header or source that misses an include compiles on what an earlier file of its batch
# included; a header an installed package's user includes first must not depend on that.
function(tribo_header_check name)
  set(dirs "")
  foreach(source ${ARGN})
    if(NOT IS_ABSOLUTE ${source})
      get_filename_component(dir ${CMAKE_CURRENT_SOURCE_DIR}/${source} DIRECTORY)
      list(APPEND dirs ${dir})
    endif()
  endforeach()
  file(GLOB subdirs LIST_DIRECTORIES true ${CMAKE_CURRENT_SOURCE_DIR}/*)
  foreach(dir ${subdirs})
    file(GLOB sources_there ${dir}/*.cpp)
    if(IS_DIRECTORY ${dir} AND NOT sources_there)
      list(APPEND dirs ${dir})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES dirs)
  set(sources "")
  foreach(dir ${dirs})
    file(GLOB headers RELATIVE ${PROJECT_SOURCE_DIR} ${dir}/*.h)
    # Not the library's: the MPI include guard of the sources that link Open MPI (not installed).
    list(REMOVE_ITEM headers numerics/mpi.h)
    foreach(header ${headers})
      string(MAKE_C_IDENTIFIER ${header} stem)
      set(source ${CMAKE_BINARY_DIR}/header_check/${stem}.cpp)
      file(CONFIGURE OUTPUT ${source} CONTENT "#include \"${header}\"\n")
      list(APPEND sources ${source})
    endforeach()
  endforeach()
  add_library(${name}_header_check OBJECT EXCLUDE_FROM_ALL ${sources})
  set_target_properties(${name}_header_check PROPERTIES UNITY_BUILD OFF)
  target_link_libraries(${name}_header_check PRIVATE ${name})
  if(NOT TARGET tribo_header_check)
    add_custom_target(tribo_header_check)
  endif()
  add_dependencies(tribo_header_check ${name}_header_check)
endfunction()

# GoogleTest's header parsed once per build instead of once per test source (some 60 of them, a
# few seconds each, twice in CI): a precompiled header every test executable reuses. Its holder is
# an executable like them, so that it is compiled with their flags (-fPIE, the sanitizers).
function(tribo_test_pch)
  if(TARGET tribo_test_pch)
    return()
  endif()
  file(WRITE ${CMAKE_BINARY_DIR}/tribo_test_pch.cpp "int main() { return 0; }\n")
  add_executable(tribo_test_pch ${CMAKE_BINARY_DIR}/tribo_test_pch.cpp)
  target_link_libraries(tribo_test_pch PRIVATE GTest::gtest OpenMP::OpenMP_CXX)
  target_precompile_headers(tribo_test_pch PRIVATE <gtest/gtest.h>)
endfunction()

# Open MPI's start-up leaks by design: its tests run under the sanitizers with every check but
# leaks (set per test, so that one ctest run takes them beside the others).
set(TRIBO_MPI_ASAN_OPTIONS "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")

# tribo_add_test(name SOURCES ... DEPENDS ... [LABELS slow|mpi] [TIMEOUT s] [COST c] [PROCESSORS n]
#                [READS_SOURCE_TREE]):
# one GoogleTest executable registered with CTest. Label `slow` marks tests the sanitizer build
# skips (ctest -LE slow), `mpi` those that start Open MPI (sanitized without leak detection);
# TIMEOUT overrides ctest's --timeout for a test known to run long; COST orders them (below);
# PROCESSORS n reserves n of ctest -j's slots for each test — for tests whose OpenMP loops or
# Eigen products use every core: beside another test their threads spin at each barrier for a
# thread that is not running (a 47-s BEM convergence test took 843 s so under ctest -j2);
# READS_SOURCE_TREE defines TRIBO_SOURCE_DIR, the checkout, for tests that read its files.
function(tribo_add_test name)
  cmake_parse_arguments(ARG "READS_SOURCE_TREE" "TIMEOUT;COST;PROCESSORS" "SOURCES;DEPENDS;LABELS" ${ARGN})
  # Without TRIBO_SLOW_TESTS (the sanitizer build, which runs `-LE slow` anyway) a slow test's
  # executable is not even built.
  if(ARG_LABELS STREQUAL "slow" AND NOT TRIBO_SLOW_TESTS)
    return()
  endif()
  add_executable(${name} ${ARG_SOURCES})
  # OpenMP for all: most tests have it through the libraries, and a header precompiled with it
  # (it defines _OPENMP) serves only sources compiled with it.
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main OpenMP::OpenMP_CXX)
  tribo_test_pch()
  target_precompile_headers(${name} REUSE_FROM tribo_test_pch)
  if(ARG_READS_SOURCE_TREE)
    target_compile_definitions(${name} PRIVATE TRIBO_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  endif()
  # gtest_discover_tests cannot pass a list through PROPERTIES: one label per target.
  if(ARG_LABELS)
    set(label ${ARG_LABELS})
  else()
    set(label unit)
  endif()
  set(properties LABELS ${label})
  # Open MPI 4.1 singletons started at the same moment race for one session directory and one of
  # them aborts in MPI_Init ("File exists", orte/util/session_dir.c; seen with ctest -j2): the
  # tests that start it take turns, beside the others.
  if(label STREQUAL "mpi")
    list(APPEND properties RESOURCE_LOCK open_mpi_session)
  endif()
  # One variable each (the list limit above). A test that shares the cores with another one (no
  # PROCESSORS) has its OpenMP threads sleep at a barrier instead of spinning for a thread the other
  # test holds (libgomp spins 300 000 times by default): two diagnosis tests side by side, 30.6 s
  # → 26.0 s (2026-12-01, Diagnosis.StaticPointsOnlyCalibrateMuSAndAnswerNone twice at once, two
  # runs each). No result depends on it.
  if(label STREQUAL "mpi" AND TRIBO_SANITIZE)
    list(APPEND properties ENVIRONMENT "${TRIBO_MPI_ASAN_OPTIONS}")
  elseif(NOT ARG_PROCESSORS)
    list(APPEND properties ENVIRONMENT OMP_WAIT_POLICY=passive)
  endif()
  if(ARG_TIMEOUT)
    list(APPEND properties TIMEOUT ${ARG_TIMEOUT})
  endif()
  if(ARG_PROCESSORS)
    list(APPEND properties PROCESSORS ${ARG_PROCESSORS})
  endif()
  # CTest -j starts tests in descending COST: on a clean clone (no timings recorded yet) the long
  # ones must start first, or one of them runs alone at the end while the other core idles.
  if(ARG_COST)
    list(APPEND properties COST ${ARG_COST})
  elseif(label STREQUAL "slow")
    list(APPEND properties COST 100)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES ${properties})
endfunction()

# tribo_add_bench(name SOURCES ... DEPENDS ... [READS_SOURCE_TREE]): one Google Benchmark
# executable (not a test); READS_SOURCE_TREE as for tribo_add_test.
function(tribo_add_bench name)
  cmake_parse_arguments(ARG "READS_SOURCE_TREE" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} benchmark::benchmark)
  if(ARG_READS_SOURCE_TREE)
    target_compile_definitions(${name} PRIVATE TRIBO_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  endif()
endfunction()
