# Applying a fold plan to a node and the PLC test bench.
target_sources(vt_model PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/fold_apply_moves.h ${CMAKE_CURRENT_LIST_DIR}/fold_apply_moves.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fold_apply.h ${CMAKE_CURRENT_LIST_DIR}/fold_apply.cpp
    ${CMAKE_CURRENT_LIST_DIR}/plc_test_bench.h ${CMAKE_CURRENT_LIST_DIR}/plc_test_bench.cpp
)
target_sources(vt_model PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/module_guide.h ${CMAKE_CURRENT_LIST_DIR}/module_guide.cpp)
