# ctest (issue 18 item 4): with no display at all (no DISPLAY, WAYLAND_DISPLAY or
# QT_QPA_PLATFORM), PROGRAM --help and --version print and exit 0, and the screens themselves
# say in one line that there is no display and exit 2 (Qt alone aborts with a core dump).
set(env ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM)
execute_process(COMMAND ${env} "${PROGRAM}" --version OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out STREQUAL "${NAME} ${VERSION}\n")
  message(FATAL_ERROR "no display: --version exited ${rc}, printed '${out}' '${err}'")
endif()
foreach(flag --help -h)
  execute_process(COMMAND ${env} "${PROGRAM}" ${flag} OUTPUT_VARIABLE out ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "no display: ${flag} exited ${rc}: ${err}")
  endif()
  foreach(option --machine --program --no-start-screen --lang --version)
    string(FIND "${out}" "${option}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "no display: ${flag} does not list ${option}: '${out}'")
    endif()
  endforeach()
endforeach()
execute_process(COMMAND ${env} "${PROGRAM}" --no-start-screen OUTPUT_VARIABLE out
                ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 30)
if(NOT rc EQUAL 2 OR NOT err MATCHES "^trilho: no display")
  message(FATAL_ERROR "no display: the screens exited ${rc} saying '${err}'")
endif()
message(STATUS "no display: --help, -h, --version exit 0; the screens say: ${err}")
