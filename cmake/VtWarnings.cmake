# Warnings are errors for ValveTune's own targets (not for third-party headers: those come in
# as SYSTEM includes through their imported targets).
function(vt_warnings target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
        -Woverloaded-virtual -Wconversion -Wsign-conversion -Wformat=2
        -Werror)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        # -Wrestrict and -Wstringop-overflow: GCC 12 at -O3 reports false positives inside
        # libstdc++'s std::string and std::vector code (GCC bugs 105329 and 106199, fixed in 13).
        target_compile_options(${target} PRIVATE -Wduplicated-cond -Wlogical-op -Wno-restrict
                                                 -Wno-stringop-overflow)
        if(VT_SANITIZE)
            # ASan's instrumentation defeats GCC's flow analysis: std::variant members are then
            # reported "maybe uninitialized" and std::fill "pointer overflow" (GCC documents such
            # false positives with sanitizers). The Release build keeps both warnings as errors.
            target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized -Wno-array-bounds)
        endif()
    endif()
endfunction()
