# `pip install .` as a user runs it (issue 37 item 5), offline: a virtual environment of Debian's
# python3 that sees Debian's NumPy, the package installed by setuptools driving CMake
# (setup.py, pyproject.toml) with nothing downloaded, then the binding tests and
# examples/python_study.py against the installed package — no PYTHONPATH, run from outside the
# source tree's python/. TRIBO_CMAKE_BUILD_DIR points setup.py at this build tree, so the module
# is copied, not compiled again. Arguments: PYTHON, SOURCE_DIR (the project), BUILD_DIR, WORK, TRIBO_EXE.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/../run_checked.cmake)

set(venv ${WORK}/venv)
run("python3 -m venv" ${PYTHON} -m venv --system-site-packages ${venv})
run("pip install ." ${CMAKE_COMMAND} -E env --unset=PYTHONPATH TRIBO_CMAKE_BUILD_DIR=${BUILD_DIR}
    ${venv}/bin/pip install --no-build-isolation --no-index --disable-pip-version-check ${SOURCE_DIR})

# The package imported is the installed one.
run("import tribo" ${CMAKE_COMMAND} -E env --unset=PYTHONPATH ${venv}/bin/python -c "import tribo\nprint(tribo.__file__)")
string(STRIP "${last_output}" imported)
string(FIND "${imported}" "${venv}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "import tribo found ${imported}, not the package installed in ${venv}")
endif()

run("binding tests against the installed package"
    ${CMAKE_COMMAND} -E env --unset=PYTHONPATH TRIBO_EXE=${TRIBO_EXE} TRIBO_SOURCE_DIR=${SOURCE_DIR} PYTHONDONTWRITEBYTECODE=1
    ${venv}/bin/python -m unittest test_arrays test_lubrication test_cli_match test_sweep_results
    WORKING_DIRECTORY ${SOURCE_DIR}/tests/python)
run("examples/python_study.py" ${CMAKE_COMMAND} -E env --unset=PYTHONPATH MPLBACKEND=Agg
    ${venv}/bin/python ${SOURCE_DIR}/examples/python_study.py WORKING_DIRECTORY ${WORK})
message(STATUS "pip install . : ${imported}; binding tests and python_study.py passed")
