# ctest: runs PROGRAM --version (offscreen) and checks it exits 0 printing "NAME VERSION".
execute_process(COMMAND "${PROGRAM}" --version OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --version exited ${rc}: ${err}")
endif()
if(NOT out STREQUAL "${NAME} ${VERSION}\n")
  message(FATAL_ERROR "${PROGRAM} --version printed '${out}', expected '${NAME} ${VERSION}'")
endif()
message(STATUS "${out}")
