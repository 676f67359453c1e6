# See tests/install/CMakeLists.txt. Arguments: BUILD_DIR, SOURCE_DIR (tests/install), WORK,
# VERSION, GENERATOR, CXX, LAUNCHER, BUILD_TYPE, BINDIR, DATADIR.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/../run_checked.cmake)

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/installed)
# A prefix must work wherever it ends up (triboConfig.cmake computes its paths from its own place).
file(RENAME ${WORK}/installed ${WORK}/moved)
set(prefix ${WORK}/moved)

foreach(f ${BINDIR}/tribo ${DATADIR}/tribo/tribo_plots.py ${DATADIR}/tribo/examples/rig-coulomb.toml
          include/tribo/contact/grid.h include/tribo/rig/parameters.h include/tribo/gap/bundle.h)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

# The consumer project, built as a user would: find_package(tribo) through CMAKE_PREFIX_PATH.
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/consumer -B ${WORK}/consumer -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} ${launcher} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_PREFIX_PATH=${prefix}
    -DEXPECTED_TRIBO_VERSION=${VERSION})
if(NOT last_output MATCHES "tribo ${VERSION} from ${prefix}/")
  message(FATAL_ERROR "the consumer did not find the moved prefix's tribo ${VERSION}:\n${last_output}")
endif()
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK}/consumer)
run("running the consumer" ${WORK}/consumer/consumer)
message(STATUS "${last_output}")
if(NOT last_output MATCHES "consumer: ok")
  message(FATAL_ERROR "consumer checks failed:\n${last_output}")
endif()

# The installed program: version from project(), and the plotting script taken from beside it —
# replaced here by a stand-in that leaves a mark, so the source tree's copy cannot pass for it.
run("tribo --version" ${prefix}/${BINDIR}/tribo --version)
if(NOT last_output MATCHES "^tribo ${VERSION}")
  message(FATAL_ERROR "tribo --version: expected 'tribo ${VERSION}', got '${last_output}'")
endif()
file(WRITE ${prefix}/${DATADIR}/tribo/tribo_plots.py
     "import pathlib, sys\npathlib.Path(sys.argv[2], 'plotted-by-installed-script').write_text(sys.argv[1])\n")
run("installed tribo rig --plot" ${prefix}/${BINDIR}/tribo rig ${prefix}/${DATADIR}/tribo/examples/rig-coulomb.toml
    --out ${WORK}/rig --plot)
if(NOT EXISTS ${WORK}/rig/plotted-by-installed-script)
  message(FATAL_ERROR "the installed tribo did not run the plotting script installed beside it")
endif()
file(READ ${WORK}/rig/summary.json summary)
string(JSON version GET "${summary}" provenance tribo_version)
if(NOT version STREQUAL VERSION)
  message(FATAL_ERROR "installed tribo's summary.json says version '${version}', expected ${VERSION}")
endif()
