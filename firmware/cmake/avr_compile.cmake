# Compiles and links one AVR firmware image with avr-gcc (run by firmware/CMakeLists.txt as a
# custom command: the host compiler never sees firmware code). avr-gcc's diagnostics are kept in
# WARNINGS (one "file:line: warning: text" a line, the source's directory left out) rather than
# printed, so the host build stays warning-free while every warning the seed's own code triggers
# is recorded and checked against the folder's expected list (the firmware.*.warnings tests).
# On an error the whole diagnostic is printed and the build fails.
# -DAVR_GCC=... -DSOURCE=... -DOUTPUT=... -DWARNINGS=... -DFLAGS="a|b|c" (| between flags: a
# semicolon would not survive the custom command)
string(REPLACE "|" ";" FLAGS "${FLAGS}")
execute_process(COMMAND ${AVR_GCC} ${FLAGS} -o ${OUTPUT} ${SOURCE} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "avr-gcc failed on ${SOURCE}:\n${out}${err}")
endif()
get_filename_component(dir ${SOURCE} DIRECTORY)
string(REPLACE "\n" ";" lines "${err}")
set(kept "")
foreach(line IN LISTS lines)
  if(line MATCHES "^(.*):([0-9]+):[0-9]+: warning: (.*)$")
    set(file ${CMAKE_MATCH_1})
    string(REPLACE "${dir}/" "" file "${file}")
    string(APPEND kept "${file}:${CMAKE_MATCH_2}: warning: ${CMAKE_MATCH_3}\n")
  endif()
endforeach()
file(WRITE ${WARNINGS} "${kept}")
