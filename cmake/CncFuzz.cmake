# CNC_FUZZ=ON (fuzz/README in the top README): every library is compiled for libFuzzer with AddressSanitizer and
# UndefinedBehaviorSanitizer, undefined behaviour fatal, so the harnesses in fuzz/ stop at the first finding.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "CNC_FUZZ needs clang (libFuzzer): configure a separate build directory with "
                      "CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCNC_FUZZ=ON (apt-get install clang)")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
