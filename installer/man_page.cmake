# cmake -DHELP2MAN=... -DPROGRAM=path/to/exe -DOUTPUT=name.1 -DNAME="one-line description"
#       [-DSUBCOMMANDS="compile;run"] [-DSEE_ALSO="trilho-cli(1)"] -P man_page.cmake
# Writes the man page of a program from its --help and --version (help2man), with a COMMAND
# OPTIONS section made of each subcommand's --help, a FILES section and SEE ALSO.
set(include_file "${OUTPUT}.include")
set(text "[FILES]\n.TP\n.I /usr/share/trilho/programs\nExample programs (the Select dialog opens here).\n")
string(APPEND text ".TP\n.I /usr/share/trilho/machines\nMachine profiles: rail.json (the default) and the XY tables.\n")
string(APPEND text ".TP\n.I /usr/share/trilho/translations\nThe pt_BR and es translations.\n")
if(SEE_ALSO)
  string(APPEND text "[SEE ALSO]\n${SEE_ALSO}\n")
endif()
if(SUBCOMMANDS)
  string(APPEND text "[COMMAND OPTIONS]\n")
  foreach(sub IN LISTS SUBCOMMANDS)
    execute_process(COMMAND "${PROGRAM}" ${sub} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${PROGRAM} ${sub} --help failed (${rc})")
    endif()
    # Usage names the command as typed, not the build's path.
    string(REPLACE "Usage: ${PROGRAM}" "Usage: trilho-cli ${sub}" help "${help}")
    # roff: backslashes, and lines starting with a dot or a quote, taken literally.
    string(REPLACE "\\" "\\e" help "${help}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
    string(APPEND text ".SS ${sub}\n.nf\n${help}.fi\n")
  endforeach()
endif()
file(WRITE "${include_file}" "${text}")
execute_process(COMMAND "${HELP2MAN}" --no-info "--name=${NAME}"
                        "--include=${include_file}" "--output=${OUTPUT}" "${PROGRAM}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed for ${PROGRAM} (${rc})")
endif()
