# Applying a fold plan to a simulated node and the PLC test bench over the node image (issue #9
# part B).
add_executable(vt_fold_apply_tests
    ${CMAKE_CURRENT_LIST_DIR}/fold_apply_moves_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_apply_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/plc_test_bench_test.cpp
)
target_link_libraries(vt_fold_apply_tests PRIVATE vt_model vt_gui_test_main Qt6::Test)
vt_warnings(vt_fold_apply_tests)
vt_discover(vt_fold_apply_tests)
