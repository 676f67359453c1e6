# `tribo homogenise` with a tilted pin face ([pin] tilt_rad, docs/homogenise.md): a slight tilt runs
# and writes its tilt and a table whose first row is the face centre's film, the cells' first
# separation plus θR (the trailing edge on it); a face tilted so far that only a strip at its
# trailing edge touches cannot carry W on the table: exit 2, a message naming the config, the load
# and the tilt, and no law.json. Beside it, the thermal crown bound of the Stribeck points. Inputs:
# TRIBO, PYTHON, WORK.
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

# The bound on the face's thermal crown beside each Stribeck point (contact/thermoelastic.h): all of
# μWU into a steel slider, Δ = (1 + ν) α Q / (4π k) with the defaults α = 11.5e-6 /K, ν = 0.3 and
# k = 46 W/(m K); in law.json and, the same, in stribeck.csv's last column.
execute_process(COMMAND ${PYTHON} -c "
import csv, json, math, sys
d = sys.argv[1]
points = json.load(open(d + '/law.json'))['stribeck']
rows = list(csv.DictReader(l for l in open(d + '/stribeck.csv') if not l.startswith('#')))
assert len(points) == len(rows) > 0, (len(points), len(rows))
for p, r in zip(points, rows):
    crown = 1.3 * 11.5e-6 * p['mu'] * 93.86 * p['U_m_per_s'] / (4 * math.pi * 46.0)
    assert abs(p['thermal_crown_bound_m'] / crown - 1) < 1e-12, (p, crown)
    assert abs(float(r['thermal_crown_bound_m']) / crown - 1) < 1e-6, (r, crown)
" ${WORK}/slight RESULT_VARIABLE crown_ok)
if(NOT crown_ok EQUAL 0)
  message(FATAL_ERROR "thermal_crown_bound_m does not follow (1 + ν) α μ W U / (4π k) in ${WORK}/slight")
endif()

# An earlier run's results in the same folder go before the run starts: a failed run leaves none.
file(COPY ${WORK}/slight/law.json ${WORK}/slight/stribeck.csv DESTINATION ${WORK}/steep)
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
  message(FATAL_ERROR "no law.json should be left when the face cannot carry the load")
endif()
if(EXISTS ${WORK}/steep/stribeck.csv)
  message(FATAL_ERROR "an earlier run's stribeck.csv should be removed when the run starts")
endif()
