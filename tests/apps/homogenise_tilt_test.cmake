# `tribo homogenise` with a tilted pin face ([pin] tilt_rad, docs/homogenise.md): a slight tilt runs
# and writes its tilt and a table whose first row is the face centre's film, the cells' first
# separation plus θR (the trailing edge on it); a face tilted so far that only a strip at its
# trailing edge touches cannot carry W on the table: exit 2, a message naming the config, the load
# and the tilt, and no law.json. Inputs: TRIBO, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/tiny_homogenise.cmake)
write_tiny_homogenise_config(${WORK}/hom.toml 1 3)
file(READ ${WORK}/hom.toml text)
# The tiny config with [pin] tilt_rad = TILT, homogenised into WORK/NAME: its exit status and stderr.
function(homogenise_tilted name tilt)
  string(REPLACE "normal_load_N = 93.86\n" "normal_load_N = 93.86\ntilt_rad = ${tilt}\n" config "${text}")
  file(WRITE ${WORK}/${name}.toml "${config}")
  execute_process(COMMAND ${TRIBO} homogenise ${WORK}/${name}.toml --out ${WORK}/${name} --no-plots
                  RESULT_VARIABLE s ERROR_VARIABLE e)
  set(status "${s}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

homogenise_tilted(slight 1e-5)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "a slight tilt should homogenise (${status}): ${err}")
endif()
file(READ ${WORK}/slight/law.json law)
string(JSON tilt GET "${law}" pin tilt_rad)
string(JSON first GET "${law}" table separation_m 0)
string(JSON cell GET "${law}" cells separation_m 0)
# θR = 1e-5 × 4.7625e-3 m = 4.7625e-8 m. CMake has no floating point: Python compares.
execute_process(COMMAND ${PYTHON} -c
                "import sys; t, a, b = map(float, sys.argv[1:]); sys.exit(0 if t == 1e-5 and abs(a - b - 4.7625e-8) < 1e-15 else 1)"
                ${tilt} ${first} ${cell} RESULT_VARIABLE rows_ok)
if(NOT rows_ok EQUAL 0)
  message(FATAL_ERROR "expected pin.tilt_rad 1e-5 and the first row at the cells' first separation + 4.7625e-8 m; "
                      "got tilt ${tilt}, first row ${first}, cells' first ${cell}")
endif()

homogenise_tilted(steep 0.009)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "a face touching on a strip only should exit 2, got ${status}: ${err}")
endif()
foreach(part "steep.toml" "normal_load_N = 93.86 N exceeds the solid load at the table's smallest separation"
        "a crowned or tilted face touches over part of it only")
  string(FIND "${err}" "${part}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the message should say '${part}', got: ${err}")
  endif()
endforeach()
if(EXISTS ${WORK}/steep/law.json)
  message(FATAL_ERROR "no law.json should be written when the face cannot carry the load")
endif()
