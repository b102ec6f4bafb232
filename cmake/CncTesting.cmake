# cnc_add_gtest(NAME SOURCES ... LIBS ... LABEL unit|golden|model|scenario|compare [SYSTEMC])
# Each TEST becomes its own ctest (gtest_discover_tests), so every SystemC test gets a fresh
# elaboration in its own process (SystemC allows one elaboration per process).
set(CNC_TEST_ENV "SC_COPYRIGHT_MESSAGE=DISABLE;SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")

function(cnc_add_gtest NAME)
  cmake_parse_arguments(T "SYSTEMC" "LABEL" "SOURCES;LIBS" ${ARGN})
  add_executable(${NAME} ${T_SOURCES})
  target_link_libraries(${NAME} PRIVATE ${T_LIBS} cnc_warnings GTest::gtest GTest::gmock)
  if(T_SYSTEMC)
    target_link_libraries(${NAME} PRIVATE cnc_sc_gtest_main PkgConfig::SystemC)
  else()
    target_link_libraries(${NAME} PRIVATE GTest::gtest_main)
  endif()
  target_include_directories(${NAME} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${NAME} PRIVATE CNC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             CNC_TEST_OUT_DIR="${PROJECT_BINARY_DIR}/test_out")  # support/test_path.hpp
  gtest_discover_tests(${NAME}
    TEST_PREFIX "${T_LABEL}/"
    DISCOVERY_TIMEOUT 30
    PROPERTIES LABELS ${T_LABEL} TIMEOUT 120 ENVIRONMENT "${CNC_TEST_ENV}")
endfunction()
