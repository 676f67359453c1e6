# `tribo homogenise` with a ball keeps each speed node's films in DIR/ball-film/ as it finishes, under
# the patches' key: run again, it reuses every node (ball_film_speeds_reused); with two nodes lost
# — a run killed before they finished —, one written by another build and one solved for another
# thinnest film, it solves those four again and keeps them. Inputs: TRIBO, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/ball.toml
  "[surface]\nkind = \"gaussian\"\nspectrum = \"self_affine\"\nrms_height_m = 5e-8\nhurst = 0.8\n"
  "rolloff_wavelength_m = 5e-6\ncutoff_wavelength_m = 6.25e-7\nseed = 1\n"
  "[domain]\nsize_m = 2e-5\ngrid = 32\n"
  "[material]\ne_star_Pa = 1.154e11\nhardness_Pa = 6e9\n"
  "[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2e-8\n"
  "[pin]\nshape = \"ball\"\nradius_m = 9.525e-3\nnormal_load_N = 10.0\nfilm_grid = 17\n"
  "[speeds]\nmin_m_per_s = 1e-3\nmax_m_per_s = 1.0\ncount = 4\n"
  "[homogenise]\nrealisations = 1\nmin_contact_grid = 64\n"
  "[micro_ehl]\nmin_speed_m_per_s = 1e-2\nmax_speed_m_per_s = 3.0\nspeeds_per_decade = 2\n")
include(${CMAKE_CURRENT_LIST_DIR}/tiny_homogenise.cmake)
function(run_ball expected what)
  expect_homogenise_reused(${WORK}/ball.toml ${WORK}/out ball_film_speeds_reused ${expected} "${what}")
  string(JSON films GET "${LAW}" ball_film films)
  set(films "${films}" PARENT_SCOPE)
endfunction()
run_ball(0 "first run")
set(first "${films}")
file(GLOB nodes ${WORK}/out/ball-film/node-*.json)
list(LENGTH nodes count)
if(count LESS 4)
  message(FATAL_ERROR "expected a kept node for each of the ball's film speeds, found ${count}")
endif()
run_ball(${count} "the same config and build")
if(NOT films STREQUAL first)
  message(FATAL_ERROR "the reused nodes gave other films:\n${films}\nagainst\n${first}")
endif()

file(REMOVE ${WORK}/out/ball-film/node-1.json ${WORK}/out/ball-film/node-3.json)
file(READ ${WORK}/out/ball-film/node-2.json node)
string(JSON key GET "${node}" cache_key)
string(REGEX REPLACE "@.*$" "@0123456789ab" other "${key}")
string(JSON node SET "${node}" cache_key "\"${other}\"")
file(WRITE ${WORK}/out/ball-film/node-2.json "${node}")
# One with this key but solved for another rest separation (a changed patch): ball_film refuses it.
file(READ ${WORK}/out/ball-film/node-4.json node)
string(JSON node SET "${node}" node thinnest_film_m "1.0")
file(WRITE ${WORK}/out/ball-film/node-4.json "${node}")
math(EXPR expected "${count} - 4")
run_ball(${expected} "two nodes lost, one from another build, one for another thinnest film")
# The four were solved again and kept under this build's key (their films against the first run's:
# tests/homogenise/ball_film_test.cpp, AKilledRunResumesFromTheSpeedNodesItKept).
foreach(k 1 2 3 4)
  file(READ ${WORK}/out/ball-film/node-${k}.json node)
  string(JSON k_key GET "${node}" cache_key)
  if(NOT k_key STREQUAL key)
    message(FATAL_ERROR "node ${k} should be kept again under ${key}, found ${k_key}")
  endif()
endforeach()
run_ball(${count} "after the resume")
