# `tribo sweep` survives kills: a sweep of 12 rig points is killed (SIGKILL via TIMEOUT) four times
# at different moments and restarted, then finished; its results.csv must hold the same rows with the
# same values (the wall_s column aside) as an uninterrupted run. A point whose config is bad becomes a
# `failed` row naming the key, and the sweep goes on; a changed spec on resume is refused (status 2).
include(${CMAKE_CURRENT_LIST_DIR}/sweep_test_common.cmake)
write_rig_sweep(2)

execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/full RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "uninterrupted sweep failed (${status}): ${err}")
endif()
rows_without_wall(${WORK}/full/results.csv full)
list(LENGTH full n)
if(NOT n EQUAL 13)
  message(FATAL_ERROR "expected a header and 12 rows, got ${n}: ${full}")
endif()
list(FILTER full INCLUDE REGEX ",-1,failed,\"[^\"]*mass_kg")
list(LENGTH full nfailed)
if(NOT nfailed EQUAL 4)
  message(FATAL_ERROR "expected the 4 points with mass -1 to fail naming rig.mass_kg, found ${nfailed}")
endif()

foreach(t 0.15 0.3 0.5 0.8)
  execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/killed TIMEOUT ${t} RESULT_VARIABLE ignored)
endforeach()
execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/killed RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "resumed sweep failed (${status}): ${err}")
endif()
rows_without_wall(${WORK}/full/results.csv full)
rows_without_wall(${WORK}/killed/results.csv killed)
if(NOT full STREQUAL killed)
  message(FATAL_ERROR "killed-and-resumed results differ:\n${full}\n---\n${killed}")
endif()

# The finished table says how it was made, and the first start made it: its provenance lines are
# sweep.json's, date included, though the last of five starts wrote the file.
file(READ ${WORK}/killed/sweep.json made)
string(JSON first_date GET "${made}" date_utc)
string(JSON spec_hash GET "${made}" spec_hash)
file(STRINGS ${WORK}/killed/results.csv provenance REGEX "^# ")
if(NOT provenance MATCHES "# tribo_version: [0-9]" OR NOT provenance MATCHES "# date_utc: ${first_date}"
   OR NOT provenance MATCHES "# spec_hash: ${spec_hash}" OR NOT provenance MATCHES "# git_commit: ")
  message(FATAL_ERROR "results.csv provenance lines do not match sweep.json (date ${first_date}): ${provenance}")
endif()

file(APPEND ${WORK}/spec.toml "# changed\n")
execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/killed RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "different spec")
  message(FATAL_ERROR "a changed spec on resume: expected status 2 saying so, got ${status}: ${err}")
endif()
