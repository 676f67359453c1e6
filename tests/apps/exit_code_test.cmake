# Runs `tribo rig` on a config with a negative mass: expects exit status 2, a message naming the
# key, and no output directory.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/bad.toml "[rig]\nmass_kg = -1.0\n")
execute_process(COMMAND ${TRIBO} rig ${WORK}/bad.toml --out ${WORK}/out
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "expected exit status 2, got ${status}: ${err}")
endif()
if(NOT err MATCHES "rig.mass_kg")
  message(FATAL_ERROR "error does not name the key rig.mass_kg: ${err}")
endif()
if(EXISTS ${WORK}/out)
  message(FATAL_ERROR "output directory was created for a bad config")
endif()
execute_process(COMMAND ${TRIBO} rig ${WORK}/missing.toml --out ${WORK}/out RESULT_VARIABLE status2 ERROR_VARIABLE err2)
if(NOT status2 EQUAL 2 OR NOT err2 MATCHES "missing.toml")
  message(FATAL_ERROR "missing config: expected status 2 naming the file, got ${status2}: ${err2}")
endif()

# The same contract for the contact and Reynolds commands.
file(WRITE ${WORK}/bad_contact.toml "[surface]\nkind = \"sphere\"\nradius_m = -0.01\n[domain]\nsize_m = 1e-3\ngrid = 64\n"
  "[material]\ne_star_Pa = 1.137e11\n[load]\nnormal_load_N = 1.0\n")
execute_process(COMMAND ${TRIBO} contact ${WORK}/bad_contact.toml --out ${WORK}/out_contact
                RESULT_VARIABLE status3 ERROR_VARIABLE err3)
if(NOT status3 EQUAL 2 OR NOT err3 MATCHES "radius_m" OR EXISTS ${WORK}/out_contact)
  message(FATAL_ERROR "tribo contact, negative radius: expected status 2 naming radius_m and no output, got ${status3}: ${err3}")
endif()
# A key renamed by issue 18 is refused with the name to use now, not taken for a typo.
file(WRITE ${WORK}/old_key_contact.toml "[surface]\nkind = \"sphere\"\nradius_m = 0.01\n[domain]\nsize_m = 1e-3\ngrid = 64\n"
  "[material]\ne_star_Pa = 1.137e11\n[load]\nnormal_N = 1.0\n")
execute_process(COMMAND ${TRIBO} contact ${WORK}/old_key_contact.toml --out ${WORK}/out_old_key
                RESULT_VARIABLE status5 ERROR_VARIABLE err5)
if(NOT status5 EQUAL 2 OR NOT err5 MATCHES "old_key_contact.toml: key 'load.normal_N'.*'load.normal_load_N'"
   OR EXISTS ${WORK}/out_old_key)
  message(FATAL_ERROR "tribo contact, old key normal_N: expected status 2 naming load.normal_load_N and no output, got ${status5}: ${err5}")
endif()
file(WRITE ${WORK}/bad_reynolds.toml "[geometry]\nkind = \"parallel_discs\"\ngap_m = 0.0\n")
execute_process(COMMAND ${TRIBO} reynolds ${WORK}/bad_reynolds.toml --out ${WORK}/out_reynolds
                RESULT_VARIABLE status4 ERROR_VARIABLE err4)
if(NOT status4 EQUAL 2 OR NOT err4 MATCHES "gap_m" OR EXISTS ${WORK}/out_reynolds)
  message(FATAL_ERROR "tribo reynolds, zero gap: expected status 2 naming gap_m and no output, got ${status4}: ${err4}")
endif()

# `tribo gap diagnose --test DIR`: a test bundle that cannot be read is refused before any fit,
# naming it, and nothing is written.
execute_process(COMMAND ${TRIBO} gap diagnose --experiment ${EXAMPLES}/gap-thesis-observations --model ${EXAMPLES}/gap-thesis-baseline.toml
                        --test ${WORK}/no-such-bundle --out ${WORK}/out_gap
                RESULT_VARIABLE status6 ERROR_VARIABLE err6)
if(NOT status6 EQUAL 2 OR NOT err6 MATCHES "no-such-bundle" OR EXISTS ${WORK}/out_gap)
  message(FATAL_ERROR "tribo gap diagnose, missing test bundle: expected status 2 naming it and no output, got ${status6}: ${err6}")
endif()

# `--candidates`: an effect the catalogue does not know, or adding and replacing mixed, is refused
# before any fit, naming it, and nothing is written.
foreach(given "+no_such_effect" "+rate_and_state,viscous_friction")
  execute_process(COMMAND ${TRIBO} gap diagnose --experiment ${EXAMPLES}/gap-thesis-observations --model ${EXAMPLES}/gap-thesis-baseline.toml
                          --candidates ${given} --out ${WORK}/out_gap_candidates
                  RESULT_VARIABLE status8 ERROR_VARIABLE err8)
  if(NOT status8 EQUAL 2 OR NOT err8 MATCHES "--candidates: .*(no_such_effect|viscous_friction)" OR EXISTS ${WORK}/out_gap_candidates)
    message(FATAL_ERROR "tribo gap diagnose --candidates ${given}: expected status 2 naming it and no output, got ${status8}: ${err8}")
  endif()
endforeach()

# An output folder that exists but takes no files (/proc/self, even for root) is refused before
# the run, naming it.
execute_process(COMMAND ${TRIBO} rig ${EXAMPLES}/rig-coulomb.toml --out /proc/self RESULT_VARIABLE status7 ERROR_VARIABLE err7)
if(NOT status7 EQUAL 2 OR NOT err7 MATCHES "/proc/self: output directory is not writable")
  message(FATAL_ERROR "tribo rig --out /proc/self: expected status 2 saying it is not writable, got ${status7}: ${err7}")
endif()

# A selftest journal whose row another build diagnosed is not resumed silently: status 2 before any
# diagnosis, naming the journal and --mix-builds; the journal is left as it was.
file(MAKE_DIRECTORY ${WORK}/selftest)
set(row "{\"generator\":\"rig\",\"true_effect\":\"slip_transient\",\"model_effects\":[],\"seed\":1,\"quick\":true,\"verdict\":\"slip_transient\",\"heldout_gap_before\":0.1,\"heldout_gap_after\":0.002,\"confidence\":0.9,\"correct\":true,\"wall_s\":100,\"git_commit\":\"0123456789ab\"}\n")
file(WRITE ${WORK}/selftest/cases.jsonl "${row}")
execute_process(COMMAND ${TRIBO} gap selftest --quick --out ${WORK}/selftest RESULT_VARIABLE status8 ERROR_VARIABLE err8)
file(READ ${WORK}/selftest/cases.jsonl journal)
if(NOT status8 EQUAL 2 OR NOT err8 MATCHES "cases.jsonl: the case slip_transient .*0123456789ab.*--mix-builds" OR NOT journal STREQUAL row)
  message(FATAL_ERROR "tribo gap selftest on another build's journal: expected status 2 naming --mix-builds and the journal untouched, got ${status8}: ${err8}")
endif()

# `tribo gap generate` with an effect the chosen generator does not write: status 2 naming the
# option and the generator's reason, and no output folder.
execute_process(COMMAND ${TRIBO} gap generate --kind slide_hold_slide --effect viscous_friction --out ${WORK}/out_generate
                RESULT_VARIABLE status9 ERROR_VARIABLE err9)
if(NOT status9 EQUAL 2 OR NOT err9 MATCHES "--effect viscous_friction .*slide_hold_slide" OR EXISTS ${WORK}/out_generate)
  message(FATAL_ERROR "tribo gap generate, unknown effect: expected status 2 naming --effect and no output, got ${status9}: ${err9}")
endif()
