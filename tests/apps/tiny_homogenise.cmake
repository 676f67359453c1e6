# A homogenisation small enough for a CLI test (a 32² patch of the thesis-like self-affine surface
# under a flat pin, its solid solves on 64² and 32²): write_tiny_homogenise_config(FILE REALISATIONS SPEEDS) writes its config.
function(write_tiny_homogenise_config file realisations speeds)
  file(WRITE ${file}
    "[surface]\nkind = \"gaussian\"\nspectrum = \"self_affine\"\nrms_height_m = 4.35e-7\nhurst = 0.8\n"
    "rolloff_wavelength_m = 6.25e-5\ncutoff_wavelength_m = 1.5625e-5\nseed = 1\n"
    "[domain]\nsize_m = 2.5e-4\ngrid = 32\n"
    "[pin]\nshape = \"flat\"\nradius_m = 4.7625e-3\nnormal_load_N = 93.86\n"
    "[speeds]\nmin_m_per_s = 1e-5\nmax_m_per_s = 0.1\ncount = ${speeds}\n"
    "[homogenise]\nrealisations = ${realisations}\nmin_contact_grid = 64\n")
endfunction()

# Runs `tribo homogenise CONFIG --out OUT --no-plots` and checks that law.json's provenance counts
# EXPECTED under FIELD (realisations_reused, ball_film_speeds_reused); WHAT names the run. Sets LAW
# in the caller to law.json's text.
function(expect_homogenise_reused config out field expected what)
  execute_process(COMMAND ${TRIBO} homogenise ${config} --out ${out} --no-plots RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what}: tribo homogenise failed (${status}): ${err}")
  endif()
  file(READ ${out}/law.json law)
  string(JSON n GET "${law}" provenance ${field})
  if(NOT n EQUAL expected)
    message(FATAL_ERROR "${what}: expected ${field} ${expected}, got ${n}")
  endif()
  set(LAW "${law}" PARENT_SCOPE)
endfunction()
