# Points run on their config in memory (apps/sweep_point.h) give the rows of points run as files:
# a contact sweep whose surface is a file named relative to the base config, and a Reynolds sweep,
# each run by default (in memory) and with `artefacts = true` (a `tribo` command line per point on
# its config.toml), must give the same rows — values, errors and the config hash in the JSON's
# provenance — and the in-memory run must leave a folder for its failed point only. The values must
# also be those of the command run by hand on the same config, and a [base.set] string must reach
# the points and sweep.json. Inputs: TRIBO, EXAMPLES, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/sweep_rows.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(COPY ${EXAMPLES}/contact-file.toml ${EXAMPLES}/contact-surface-um.txt DESTINATION ${WORK})
file(WRITE ${WORK}/discs.toml "[geometry]\nkind = \"parallel_discs\"\nradius_m = 4.7625e-3\ngap_m = 1e-6\n"
  "gap_rate_m_per_s = -1e-6\n[lubricant]\nviscosity_Pa_s = 0.021\n[motion]\nsliding_speed_m_per_s = 0.0\n[grid]\nn = 32\n")
# One bad value per sweep (a negative load, a negative gap): point 2 fails.
file(WRITE ${WORK}/contact.toml "[base]\ncommand = \"contact\"\nconfig = \"contact-file.toml\"\n"
  "[[axis]]\nkey = \"load.normal_load_N\"\nvalues = [1.0, 5.0, -1.0]\n[sweep]\njobs = 2\n"
  "[outputs]\ncolumns = [\"contact.json:area_fraction\", \"contact.json:iterations\", \"contact.json:provenance.config_hash\"]\n")
file(WRITE ${WORK}/reynolds.toml "[base]\ncommand = \"reynolds\"\nconfig = \"discs.toml\"\n"
  "[base.set]\n\"geometry.kind\" = \"parallel_discs\"\n"
  "[[axis]]\nkey = \"geometry.gap_m\"\nvalues = [1e-6, 2e-6, -1e-6]\n[sweep]\njobs = 2\n"
  "[outputs]\ncolumns = [\"reynolds.json:load_N\", \"reynolds.json:provenance.config_hash\"]\n")

foreach(command contact reynolds)
  file(READ ${WORK}/${command}.toml spec)
  string(REPLACE "[sweep]\n" "[sweep]\nartefacts = true\n" spec "${spec}")
  file(WRITE ${WORK}/${command}-files.toml "${spec}")
  foreach(run ${command} ${command}-files)
    execute_process(COMMAND ${TRIBO} sweep ${WORK}/${run}.toml --out ${WORK}/${run} RESULT_VARIABLE status
                    ERROR_VARIABLE err TIMEOUT 300)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${run} sweep failed (${status}): ${err}")
    endif()
  endforeach()
  rows_without_wall(${WORK}/${command}/results.csv memory 1)
  rows_without_wall(${WORK}/${command}-files/results.csv files 1)
  list(LENGTH memory n)
  if(n EQUAL 4)
    list(GET memory 1 row0)
    list(GET memory 2 row1)
    list(GET memory 3 row2)
  endif()
  if(NOT n EQUAL 4 OR NOT row0 MATCHES "^0,[^,]*,ok,,,[0-9]" OR NOT row1 MATCHES "^1,[^,]*,ok,,,[0-9]"
     OR NOT row2 MATCHES "^2,[^,]*,failed,\"tribo: error: DIR/points/00002/config.toml: key 'geometry.gap_m|^2,[^,]*,failed,\"tribo: error: DIR/points/00002/config.toml: key 'load.normal_load_N")
    message(FATAL_ERROR "${command}: expected points 0 and 1 ok and point 2 failed naming its config and key: ${memory}")
  endif()
  if(NOT memory STREQUAL files)
    message(FATAL_ERROR "${command}: rows in memory differ from rows of file steps:\n${memory}\n---\n${files}")
  endif()
  file(GLOB folders LIST_DIRECTORIES true RELATIVE ${WORK}/${command}/points ${WORK}/${command}/points/*)
  if(NOT folders STREQUAL "00002" OR NOT EXISTS ${WORK}/${command}/points/00002/config.toml)
    message(FATAL_ERROR "${command}: in memory only the failed point 2 keeps a folder (its config.toml), found: ${folders}")
  endif()
endforeach()

# A [base.set] string reaches the points (they ran) and the sweep's record.
file(READ ${WORK}/reynolds/sweep.json sweep_json)
string(JSON kind ERROR_VARIABLE no_kind GET "${sweep_json}" set geometry.kind)
if(NOT kind STREQUAL "parallel_discs")
  message(FATAL_ERROR "reynolds: sweep.json should record [base.set] geometry.kind = parallel_discs: ${no_kind}")
endif()

# By hand: `tribo contact` on point 1's config (written by the file-step sweep) gives the area the
# in-memory point gave.
execute_process(COMMAND ${TRIBO} contact ${WORK}/contact-files/points/00001/config.toml --out ${WORK}/by-hand
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
file(READ ${WORK}/by-hand/contact.json json)
string(JSON area GET "${json}" area_fraction)
file(STRINGS ${WORK}/contact/results.csv row REGEX "^1,")
if(NOT status EQUAL 0 OR NOT row MATCHES ",ok,,[^,]*,${area},")
  message(FATAL_ERROR "tribo contact by hand (${status}: ${err}) gives area fraction ${area}; the sweep's row: ${row}")
endif()
