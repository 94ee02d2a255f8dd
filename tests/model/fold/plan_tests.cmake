# Fold plan logic (issue #9 part A): byte maps and lengths against the manuals, checks, plan file,
# exports (HTML/CSV/PDF) and `valvetune-cli fold plan` golden output.
add_executable(vt_fold_plan_tests
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan_layout_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan_check_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan_file_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_export_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_cli_test.cpp
)
target_compile_definitions(vt_fold_plan_tests PRIVATE VT_FOLD_TEST_DIR="${CMAKE_CURRENT_LIST_DIR}")
target_link_libraries(vt_fold_plan_tests PRIVATE vt_cli vt_model vt_gui_test_main Qt6::Test)
vt_warnings(vt_fold_plan_tests)
vt_discover(vt_fold_plan_tests)
