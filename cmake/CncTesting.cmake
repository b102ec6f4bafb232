# cnc_add_gtest(NAME SOURCES ... LIBS ... LABEL unit|golden|model|scenario|compare [SYSTEMC] [TIMEOUT s] [COST s])
# COST (on every test of the target): about its seconds on the project's machine. ctest starts the costliest tests
# first; in a fresh build folder (CI) it knows no times of its own, and long tests left to the end would run alone.
# Each TEST becomes its own ctest (gtest_discover_tests), so every SystemC test gets a fresh
# elaboration in its own process (SystemC allows one elaboration per process). TIMEOUT (wall time, default 600 s)
# only stops a hung test (every simulation is bounded by scenario.max_sim_s anyway): `ctest -j8 --repeat
# until-fail:20` on a 2-core machine with other work beside it ran a 7 s test for over 100 s, and
# 120 s timed it out.
# The RTL plug-ins the tests build (fpga.model = "rtl") go to the build folder, shared by the tests, never to ~/.cache.
set(CNC_TEST_ENV "SC_COPYRIGHT_MESSAGE=DISABLE;SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1;CNCSIM_RTL_CACHE=${CMAKE_BINARY_DIR}/rtl-cache")

function(cnc_add_gtest NAME)
  cmake_parse_arguments(T "SYSTEMC" "LABEL;TIMEOUT;COST" "SOURCES;LIBS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  add_executable(${NAME} ${T_SOURCES})
  # The tests' own code at -O1: it compiles in about 70 % of Release's -O3 time (a third of the build is tests) and
  # runs little; the code under test is in the libraries, built as the build type says.
  target_compile_options(${NAME} PRIVATE -O1)
  target_link_libraries(${NAME} PRIVATE ${T_LIBS} cnc_warnings GTest::gtest GTest::gmock)
  if(T_SYSTEMC)
    target_link_libraries(${NAME} PRIVATE cnc_sc_gtest_main PkgConfig::SystemC)
  else()
    target_link_libraries(${NAME} PRIVATE GTest::gtest_main)
  endif()
  target_include_directories(${NAME} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${NAME} PRIVATE CNC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             CNC_TEST_OUT_DIR="${PROJECT_BINARY_DIR}/test_out")  # support/test_path.hpp
  if(NOT T_COST)
    set(T_COST 0)
  endif()
  gtest_discover_tests(${NAME}
    TEST_PREFIX "${T_LABEL}/"
    DISCOVERY_TIMEOUT 30
    PROPERTIES LABELS ${T_LABEL} TIMEOUT ${T_TIMEOUT} COST ${T_COST} ENVIRONMENT "${CNC_TEST_ENV}")
endfunction()
