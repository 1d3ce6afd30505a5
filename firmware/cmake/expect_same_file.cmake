# A test: ACTUAL must equal EXPECTED line for line (the firmware's recorded warnings against the
# list its README documents). -DACTUAL=... -DEXPECTED=...
file(READ ${ACTUAL} actual)
file(READ ${EXPECTED} expected)
if(NOT actual STREQUAL expected)
  message(FATAL_ERROR "${ACTUAL} differs from ${EXPECTED}\n--- got:\n${actual}--- expected:\n${expected}")
endif()
message(STATUS "same as ${EXPECTED}")
