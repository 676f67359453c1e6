# Every output says how it was made: `tribo rig` writes a "provenance" block into summary.json
# (version from project(), the build's commit, the config's absolute path and hash, date, threads,
# seed, command line) and the same block beside trace.csv and events.csv (NAME.csv.provenance.json);
# the CSVs themselves are plain, so numpy.genfromtxt(names=True), pandas.read_csv and
# csv.DictReader read them without options, and the plotting script draws from them.
# Arguments: TRIBO (the binary), VERSION (PROJECT_VERSION), CONFIG (a rig config), WORK, PYTHON.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
configure_file(${CONFIG} ${WORK}/rig.toml COPYONLY)
execute_process(COMMAND ${TRIBO} rig ${WORK}/rig.toml --out ${WORK}/out --plot
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo rig failed (${status}): ${err}")
endif()

function(expect what actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: expected '${expected}', got '${actual}'")
  endif()
endfunction()

file(READ ${WORK}/out/summary.json summary)
string(JSON p GET "${summary}" provenance)
string(JSON version GET "${p}" tribo_version)
expect("summary.json provenance.tribo_version" "${version}" "${VERSION}")
string(JSON config GET "${p}" config)
expect("summary.json provenance.config" "${config}" "${WORK}/rig.toml")
string(JSON hash GET "${p}" config_hash)
if(NOT hash MATCHES "^[0-9a-f]+$")
  message(FATAL_ERROR "config_hash '${hash}' is not hex")
endif()
string(LENGTH "${hash}" n)
expect("config_hash length" "${n}" 16)
string(JSON commit GET "${p}" git_commit)
if(commit STREQUAL "")
  message(FATAL_ERROR "empty git_commit")
endif()
string(JSON seed GET "${p}" seed)
expect("provenance.seed (the [run] default)" "${seed}" 1)
string(JSON threads GET "${p}" threads)
if(NOT threads GREATER 0)
  message(FATAL_ERROR "threads = ${threads}")
endif()
string(JSON date GET "${p}" date_utc)
if(NOT date MATCHES "^[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]T[0-9][0-9]:[0-9][0-9]:[0-9][0-9]Z$")
  message(FATAL_ERROR "date_utc '${date}' is not ISO 8601 UTC")
endif()
string(JSON argv1 GET "${p}" command_line 1)
expect("provenance.command_line[1]" "${argv1}" rig)

# The CSVs: plain, the column header first; the same block beside each.
foreach(csv trace events)
  file(STRINGS ${WORK}/out/${csv}.csv first LIMIT_COUNT 1)
  if(NOT first MATCHES "^t_s,")
    message(FATAL_ERROR "${csv}.csv: the column header should be the first line, got '${first}'")
  endif()
  file(READ ${WORK}/out/${csv}.csv.provenance.json beside)
  string(JSON beside_p GET "${beside}" provenance)
  string(JSON equal EQUAL "${beside_p}" "${p}")
  if(NOT equal)
    message(FATAL_ERROR "${csv}.csv.provenance.json: provenance differs from summary.json's: ${beside_p}")
  endif()
  string(JSON named GET "${beside}" csv)
  expect("${csv}.csv.provenance.json csv" "${named}" "${csv}.csv")
  # The three readers people reach for, without options: every column named, as many rows as lines.
  execute_process(COMMAND ${PYTHON} -c "
import csv, sys, numpy, pandas
path = sys.argv[1]
lines = open(path).read().splitlines()
columns, rows = lines[0].split(','), len(lines) - 1
a = numpy.genfromtxt(path, delimiter=',', names=True, dtype=None, encoding='utf-8')
assert list(a.dtype.names) == columns and a.size == rows, ('numpy', a.dtype.names, a.size)
d = pandas.read_csv(path)
assert list(d.columns) == columns and len(d) == rows, ('pandas', list(d.columns), len(d))
r = list(csv.DictReader(open(path)))
assert list(r[0].keys()) == columns and len(r) == rows, ('csv', list(r[0].keys()), len(r))
" ${WORK}/out/${csv}.csv RESULT_VARIABLE read_status ERROR_VARIABLE read_err)
  if(NOT read_status EQUAL 0)
    message(FATAL_ERROR "${csv}.csv does not read plainly with numpy, pandas and csv: ${read_err}")
  endif()
endforeach()

# Read back: the plotting script (when matplotlib is there) drew from trace.csv.
execute_process(COMMAND ${PYTHON} -c "import matplotlib" RESULT_VARIABLE no_matplotlib OUTPUT_QUIET ERROR_QUIET)
if(NOT no_matplotlib)
  foreach(png phase_plane trace)
    if(NOT EXISTS ${WORK}/out/${png}.png)
      message(FATAL_ERROR "${png}.png not drawn from the CSV: ${err}")
    endif()
  endforeach()
endif()
