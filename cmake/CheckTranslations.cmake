# Fails when the sources hold UI text that translations/valvetune_de.ts does not translate yet:
# runs lupdate on a scratch copy of the catalogue and looks for unfinished entries.
#   cmake -DLUPDATE=… -DTS=…/valvetune_de.ts -DSOURCE_DIR=… -DWORK=… -P CheckTranslations.cmake
file(GLOB_RECURSE sources
    ${SOURCE_DIR}/app/*.cpp ${SOURCE_DIR}/app/*.h ${SOURCE_DIR}/widgets/*.cpp ${SOURCE_DIR}/widgets/*.h
    ${SOURCE_DIR}/model/*.cpp ${SOURCE_DIR}/model/*.h ${SOURCE_DIR}/transports/*.cpp ${SOURCE_DIR}/transports/*.h)
file(MAKE_DIRECTORY ${WORK})
configure_file(${TS} ${WORK}/check_de.ts COPYONLY)
# Include paths as the update_translations target has them, so lupdate resolves the same contexts.
execute_process(COMMAND ${LUPDATE} -no-obsolete -locations none -I ${SOURCE_DIR} -I ${SOURCE_DIR}/devices
                        ${sources} -ts ${WORK}/check_de.ts
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lupdate failed (${rc})")
endif()
file(STRINGS ${WORK}/check_de.ts unfinished REGEX "type=\"unfinished\"")
list(LENGTH unfinished count)
if(count GREATER 0)
    message(FATAL_ERROR "${count} UI text(s) lack a German translation: run "
                        "'cmake --build build --target update_translations' and translate them in ${TS}")
endif()
message(STATUS "German catalogue covers every UI text")
