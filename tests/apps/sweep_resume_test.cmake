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

# Per-point files only on request: by default a rig point runs on its config in memory and leaves no
# folder, unless it fails — then its folder holds the config.toml and log.txt its error names.
# With `[sweep] artefacts = true` every point keeps its folder, trace.csv and events.csv included,
# and the rows (config hashes too) are the same.
file(GLOB point_folders LIST_DIRECTORIES true RELATIVE ${WORK}/full/points ${WORK}/full/points/*)
if(NOT point_folders STREQUAL "00002;00005;00008;00011")
  message(FATAL_ERROR "a default sweep must leave folders for its 4 failed points only, found: ${point_folders}")
endif()
file(STRINGS ${WORK}/full/points/00002/log.txt log)
file(STRINGS ${WORK}/full/results.csv row REGEX "^2,")
file(READ ${WORK}/full/points/00002/config.toml config)
string(FIND "${row}" ",\"${log}\"," at)
if(NOT log MATCHES "^tribo: error: .*/points/00002/config.toml: key 'rig.mass_kg'" OR at LESS 0
   OR NOT config MATCHES "mass_kg = -1")
  message(FATAL_ERROR "failed point 2: its log (${log}) must be its row's error (${row}) and its config hold mass -1:\n${config}")
endif()
file(READ ${WORK}/spec.toml spec)
string(REPLACE "[sweep]\n" "[sweep]\nartefacts = true\n" spec "${spec}")
file(WRITE ${WORK}/spec_artefacts.toml "${spec}")
execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec_artefacts.toml --out ${WORK}/artefacts RESULT_VARIABLE status ERROR_VARIABLE err)
rows_without_wall(${WORK}/artefacts/results.csv with_artefacts)
rows_without_wall(${WORK}/full/results.csv full)
if(NOT status EQUAL 0 OR NOT EXISTS ${WORK}/artefacts/points/00000/trace.csv
   OR NOT EXISTS ${WORK}/artefacts/points/00000/events.csv OR NOT with_artefacts STREQUAL full)
  message(FATAL_ERROR "artefacts = true: expected the same rows and each point's trace.csv and events.csv (${status}): ${err}")
endif()

foreach(t 0.3 0.6 0.9 1.2)
  execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/killed TIMEOUT ${t} RESULT_VARIABLE ignored)
  if(t STREQUAL "0.3" AND EXISTS ${WORK}/killed/results.csv)  # the first kill must land mid-sweep
    rows_without_wall(${WORK}/killed/results.csv first)
    list(LENGTH first nfirst)
    if(NOT nfirst LESS 13)
      message(FATAL_ERROR "the sweep finished before its first kill at ${t} s: make the points dearer")
    endif()
  endif()
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

# The finished table says how it was made, and the first start made it: the provenance beside it
# is sweep.json's, date included, though the last of five starts wrote the file; the table itself
# starts with its column header.
file(READ ${WORK}/killed/sweep.json made)
string(JSON first_date GET "${made}" date_utc)
string(JSON spec_hash GET "${made}" spec_hash)
file(READ ${WORK}/killed/results.csv.provenance.json beside)
string(JSON date GET "${beside}" provenance date_utc)
string(JSON hash GET "${beside}" provenance spec_hash)
string(JSON version GET "${beside}" provenance tribo_version)
string(JSON commit GET "${beside}" provenance git_commit)
if(NOT date STREQUAL first_date OR NOT hash STREQUAL spec_hash OR NOT version MATCHES "^[0-9]" OR commit STREQUAL "")
  message(FATAL_ERROR "results.csv.provenance.json does not match sweep.json (date ${first_date}): ${beside}")
endif()
file(STRINGS ${WORK}/killed/results.csv first LIMIT_COUNT 1)
if(NOT first MATCHES "^point_id,")
  message(FATAL_ERROR "results.csv should start with its column header, got '${first}'")
endif()

file(APPEND ${WORK}/spec.toml "# changed\n")
execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/killed RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "different spec")
  message(FATAL_ERROR "a changed spec on resume: expected status 2 saying so, got ${status}: ${err}")
endif()
