# tribo_add_library(name SOURCES ... DEPENDS ...): one library target per folder.
function(tribo_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
endfunction()

# tribo_add_test(name SOURCES ... DEPENDS ... [LABELS slow|mpi] [TIMEOUT s]): one GoogleTest
# executable registered with CTest. Label `slow` marks tests the sanitizer build skips
# (ctest -LE slow), `mpi` those that start Open MPI (sanitized without leak detection);
# TIMEOUT overrides ctest's --timeout for a test known to run long.
function(tribo_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main)
  # gtest_discover_tests cannot pass a list through PROPERTIES: one label per target.
  if(ARG_LABELS)
    set(label ${ARG_LABELS})
  else()
    set(label unit)
  endif()
  set(properties LABELS ${label})
  if(ARG_TIMEOUT)
    list(APPEND properties TIMEOUT ${ARG_TIMEOUT})
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES ${properties})
endfunction()

# tribo_add_bench(name SOURCES ... DEPENDS ...): one Google Benchmark executable (not a test).
function(tribo_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} benchmark::benchmark)
endfunction()
