# Fold plan logic: plan value, checks, PLC configuration, plan file, exports.
target_sources(vt_model PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan.h ${CMAKE_CURRENT_LIST_DIR}/fold_plan.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_check.h ${CMAKE_CURRENT_LIST_DIR}/fold_check.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_check_text.cpp
    ${CMAKE_CURRENT_LIST_DIR}/plc_config.h ${CMAKE_CURRENT_LIST_DIR}/plc_config.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan_file.h ${CMAKE_CURRENT_LIST_DIR}/fold_plan_file.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_plan_file_text.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_export.h ${CMAKE_CURRENT_LIST_DIR}/fold_export.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_sheet_text.cpp
)
