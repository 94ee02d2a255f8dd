# Compiles through ccache when it is installed (scripts/deps installs it). The cache lives in the
# user's cache folder, outside the checkout, so a fresh clone of a commit already built on this
# machine compiles warm. Paths are made relative to the source folder and the working folder is
# left out of the hash, so two clones in different folders share their objects.
find_program(VT_CCACHE ccache)
if(VT_CCACHE)
    set(launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${CMAKE_SOURCE_DIR} CCACHE_NOHASHDIR=1 CCACHE_MAXSIZE=20G
                 CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
                 ${VT_CCACHE})
    set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
    message(STATUS "Compiler cache: ${VT_CCACHE}")
endif()
