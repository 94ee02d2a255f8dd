# What a program's --help says, for the man page generator and its checks (GenerateManPage.cmake,
# CheckHelpCoverage.cmake): the text, its commands and its long options.

# How the programs run here: the GUI answers --help without a display on the offscreen platform;
# in the sanitizer build, what Qt keeps until exit is no leak of ours (tests/lsan.supp).
set(VT_HELP_ENV QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0)

# vt_help_text(program args out): stdout of `program args…`, which must exit 0.
function(vt_help_text program args out)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env ${VT_HELP_ENV} ${program} ${args}
                    OUTPUT_VARIABLE text ERROR_VARIABLE err RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${program} ${args} exited ${rc}: ${err}")
    endif()
    string(STRIP "${text}" text)
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

# vt_help_commands(program out): the names under "Commands:" in `program --help`, in order.
function(vt_help_commands program out)
    vt_help_text(${program} --help text)
    string(REGEX MATCH "\nCommands:\n(  [^\n]*\n?)+" block "${text}")
    string(REGEX MATCHALL "\n  [a-z][a-z0-9-]*" lines "${block}")
    set(names)
    foreach(line IN LISTS lines)
        string(STRIP "${line}" line)
        list(APPEND names ${line})
    endforeach()
    set(${out} ${names} PARENT_SCOPE)
endfunction()

# vt_help_options(text out): every long option (--name) the text mentions, once each.
function(vt_help_options text out)
    string(REGEX MATCHALL "--[a-z][a-z0-9-]*" options "${text}")
    list(REMOVE_DUPLICATES options)
    set(${out} ${options} PARENT_SCOPE)
endfunction()
