# Shared by the sweep tests: a results.csv as comparable rows.

# The column header and rows of a results.csv, one list entry per line: the "# key: value"
# provenance lines dropped (they carry dates), the wall_s column (6th field in a sweep of two axes)
# emptied and the output folder's name replaced by DIR in error messages.
function(rows_without_wall file out)
  file(STRINGS ${file} lines)
  list(FILTER lines EXCLUDE REGEX "^#")
  get_filename_component(dir ${file} DIRECTORY)
  set(result "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^([^,]*,[^,]*,[^,]*,[^,]*,[^,]*,)[^,]*" "\\1" line "${line}")
    string(REPLACE "${dir}" "DIR" line "${line}")
    list(APPEND result "${line}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()
