# Warnings are errors for ValveTune's own targets (not for third-party headers: those come in
# as SYSTEM includes through their imported targets).
function(vt_warnings target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
        -Woverloaded-virtual -Wconversion -Wsign-conversion -Wformat=2
        -Werror)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        # -Wrestrict: GCC 12 at -O3 reports false positives inside std::string's operator+
        # (GCC bug 105329, fixed in GCC 13).
        target_compile_options(${target} PRIVATE -Wduplicated-cond -Wlogical-op -Wno-restrict)
    endif()
endfunction()
