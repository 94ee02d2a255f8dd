# Writes a program's man page from its own --help and --version with help2man, so the page says
# what the program says. With COMMANDS=ON (valvetune-cli) each command's own --help follows in a
# COMMANDS section, in the order --help lists them. EXTRA is a help2man include file with the
# sections --help does not hold (serial port permissions, files, see also).
#   cmake -DHELP2MAN=… -DPROGRAM=<executable> -DSUMMARY=… -DEXTRA=<file.h2m> [-DCOMMANDS=ON]
#         -DWORK=<folder> -DOUT=<name.1.gz> -P GenerateManPage.cmake
include(${CMAKE_CURRENT_LIST_DIR}/HelpText.cmake)

get_filename_component(name ${PROGRAM} NAME)
file(MAKE_DIRECTORY ${WORK})
set(includes --include=${EXTRA})
if(COMMANDS)
    set(generated ${WORK}/${name}.commands.h2m)
    set(body "")
    vt_help_commands(${PROGRAM} commands)
    if(NOT commands)
        message(FATAL_ERROR "${name} --help lists no commands")
    endif()
    string(APPEND body "[COMMANDS]\n")
    foreach(command IN LISTS commands)
        vt_help_text(${PROGRAM} "${command};--help" text)
        # Preformatted roff: a backslash is \e, a hyphen \- (so options stay typeable), a line
        # starting with . or ' is no request.
        string(REPLACE "\\" "\\e" text "${text}")
        string(REPLACE "-" "\\-" text "${text}")
        string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
        string(APPEND body ".SS \"${name} ${command}\"\n.nf\n${text}\n.fi\n")
    endforeach()
    file(WRITE ${generated} "${body}")
    list(PREPEND includes --include=${generated})
endif()

# help2man runs the program, as vt_help_text() does.
execute_process(
    COMMAND ${CMAKE_COMMAND} -E env ${VT_HELP_ENV}
            ${HELP2MAN} --no-info --section=1 --name=${SUMMARY} ${includes}
            --output=${WORK}/${name}.1 ${PROGRAM}
    RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "help2man ${name} failed (${rc}): ${err}")
endif()
# Debian policy §12.1: man pages compressed with gzip -9, without a time stamp (-n).
execute_process(COMMAND gzip -9nf ${WORK}/${name}.1 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gzip ${name}.1 failed (${rc})")
endif()
file(COPY_FILE ${WORK}/${name}.1.gz ${OUT} ONLY_IF_DIFFERENT)
