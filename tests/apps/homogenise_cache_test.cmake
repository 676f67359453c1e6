# `tribo homogenise` keeps each finished realisation in DIR/patches/ under a key of the config's
# hash and the build's commit: run again with the same config and build, it reuses them all; a
# patch another build made is solved again (realisations_reused counts what was taken). The law it
# writes is then an input of a rig run, listed with its hash. Inputs: TRIBO, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/hom.toml
  "[surface]\nkind = \"gaussian\"\nspectrum = \"self_affine\"\nrms_height_m = 4.35e-7\nhurst = 0.8\n"
  "rolloff_wavelength_m = 6.25e-5\ncutoff_wavelength_m = 1.5625e-5\nseed = 1\n"
  "[domain]\nsize_m = 2.5e-4\ngrid = 32\n"
  "[pin]\nshape = \"flat\"\nradius_m = 4.7625e-3\nnormal_load_N = 93.86\n"
  "[speeds]\nmin_m_per_s = 1e-5\nmax_m_per_s = 0.1\ncount = 3\n"
  "[homogenise]\nrealisations = 2\n")
function(reused expected what)
  execute_process(COMMAND ${TRIBO} homogenise ${WORK}/hom.toml --out ${WORK}/out --no-plots RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "tribo homogenise failed (${status}): ${err}")
  endif()
  file(READ ${WORK}/out/law.json law)
  string(JSON n GET "${law}" provenance realisations_reused)
  if(NOT n EQUAL expected)
    message(FATAL_ERROR "${what}: expected ${expected} realisations reused, got ${n}")
  endif()
endfunction()
reused(0 "first run")
reused(2 "the same config and build")
file(READ ${WORK}/out/patches/realisation-0.json patch)
string(JSON key GET "${patch}" cache_key)
string(REGEX REPLACE "@.*$" "@0123456789ab" other "${key}")
string(JSON patch SET "${patch}" cache_key "\"${other}\"")
file(WRITE ${WORK}/out/patches/realisation-0.json "${patch}")
reused(1 "one patch from another build")

file(WRITE ${WORK}/rig.toml "[rig]\ndrive_speed_m_per_s = 1e-2\n[friction]\nlaw = \"homogenised\"\ntable = \"out/law.json\"\n[run]\nduration_s = 1.0\n")
execute_process(COMMAND ${TRIBO} rig ${WORK}/rig.toml --out ${WORK}/rig RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo rig on the law failed (${status}): ${err}")
endif()
file(READ ${WORK}/rig/summary.json summary)
string(JSON law_path GET "${summary}" provenance inputs 1 path)
string(JSON law_hash GET "${summary}" provenance inputs 1 hash)
if(NOT law_path STREQUAL "${WORK}/out/law.json" OR NOT law_hash MATCHES "^[0-9a-f]+$")
  message(FATAL_ERROR "the rig's provenance should list the law table with its hash, got ${law_path} ${law_hash}")
endif()
