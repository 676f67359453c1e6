# Shared by the sweep tests: a results.csv as comparable rows.

# The column header and rows of a results.csv, one list entry per line: any "# key: value"
# lines dropped (older tables began with their provenance, which carries dates), the wall_s column emptied (the field after point_id,
# the axes, status and error; a third argument gives the number of axes, default 2) and the output
# folder's name replaced by DIR in error messages.
function(rows_without_wall file out)
  set(axes 2)
  if(ARGC GREATER 2)
    set(axes ${ARGV2})
  endif()
  math(EXPR before "${axes} + 3")
  string(REPEAT "[^,]*," ${before} fields)  # CMake's regex has no {n}
  file(STRINGS ${file} lines)
  list(FILTER lines EXCLUDE REGEX "^#")
  get_filename_component(dir ${file} DIRECTORY)
  set(result "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^(${fields})[^,]*" "\\1" line "${line}")
    string(REPLACE "${dir}" "DIR" line "${line}")
    list(APPEND result "${line}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()
