# For the CTest scripts (cmake -P): run("what" COMMAND ARGS...) stops the test with the command's
# output when it fails, else leaves its stdout in `last_output`. execute_process keywords
# (WORKING_DIRECTORY, ...) may follow the command.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
