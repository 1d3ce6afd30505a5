# A test: the image fits its chip. Flash (.text + .data) at most FLASH bytes and RAM
# (.data + .bss) at most RAM bytes (the stack takes what is left: at least STACK bytes must be).
# -DAVR_SIZE=... -DELF=... -DFLASH=... -DRAM=... -DSTACK=...
execute_process(COMMAND ${AVR_SIZE} -A ${ELF} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "avr-size ${ELF}: ${err}")
endif()
foreach(section text data bss)
  set(${section} 0)
  if(out MATCHES "\\.${section}[ \t]+([0-9]+)")
    set(${section} ${CMAKE_MATCH_1})
  endif()
endforeach()
math(EXPR flash "${text} + ${data}")
math(EXPR ram "${data} + ${bss}")
math(EXPR left "${RAM} - ${ram}")
message(STATUS "${ELF}: flash ${flash} of ${FLASH} bytes, RAM ${ram} of ${RAM} (${left} left for the stack)")
if(flash GREATER FLASH OR left LESS STACK)
  message(FATAL_ERROR "does not fit: flash ${flash} > ${FLASH} or stack ${left} < ${STACK}")
endif()
