# add_avr_firmware(NAME MCU <mcu> F_CPU <hz> SOURCES <c files> [DEFINES <NAME=value>...] [DEPENDS <headers>...] [HEX])
# Cross-compiles an AVR firmware with avr-gcc into ${CMAKE_CURRENT_BINARY_DIR}/NAME.elf, built
# by the target NAME. The ELF path is the target property AVR_ELF: use $<TARGET_PROPERTY:NAME,AVR_ELF> (tests do
# so in a compile definition). The firmware gets F_CPU and CNC_MCU_NAME (the MCU name as a string) defined, for
# simavr's .mmcu section: AVR_MCU(F_CPU, CNC_MCU_NAME); the simavr-avr link flags place that section outside
# the flash image. HEX also writes NAME.hex, the flash as Intel HEX (avr-objcopy -O ihex, what grbl's Makefile and
# the Arduino IDE produce): its path is the target property AVR_HEX.
find_program(AVR_GCC avr-gcc)
find_program(AVR_OBJCOPY avr-objcopy)
if(NOT AVR_GCC)
  message(FATAL_ERROR "avr-gcc not found: apt-get install gcc-avr avr-libc binutils-avr")
endif()
pkg_check_modules(SIMAVR_AVR QUIET simavr-avr)
if(SIMAVR_AVR_FOUND)
  set(CNC_AVR_FW_CFLAGS ${SIMAVR_AVR_CFLAGS})
  set(CNC_AVR_FW_LDFLAGS ${SIMAVR_AVR_LDFLAGS})
else()  # the same flags as /usr/share/pkgconfig/simavr-avr.pc (simavr 1.6)
  set(CNC_AVR_FW_CFLAGS -I/usr/include/simavr/avr -ffunction-sections -fdata-sections)
  set(CNC_AVR_FW_LDFLAGS -Wl,--relax,--gc-sections -Wl,--undefined=_mmcu,--section-start=.mmcu=0x910000)
endif()

function(add_avr_firmware NAME)
  cmake_parse_arguments(FW "HEX" "MCU;F_CPU" "SOURCES;DEFINES;DEPENDS" ${ARGN})
  if(NOT FW_MCU OR NOT FW_F_CPU OR NOT FW_SOURCES)
    message(FATAL_ERROR "add_avr_firmware(${NAME}): MCU, F_CPU and SOURCES are required")
  endif()
  set(elf ${CMAKE_CURRENT_BINARY_DIR}/${NAME}.elf)
  set(srcs)
  foreach(s ${FW_SOURCES})
    get_filename_component(a ${s} ABSOLUTE)
    list(APPEND srcs ${a})
  endforeach()
  set(deps)
  foreach(d ${FW_DEPENDS})
    get_filename_component(a ${d} ABSOLUTE)
    list(APPEND deps ${a})
  endforeach()
  list(TRANSFORM FW_DEFINES PREPEND -D)
  add_custom_command(OUTPUT ${elf}
    COMMAND ${AVR_GCC} -mmcu=${FW_MCU} -DF_CPU=${FW_F_CPU}UL "-DCNC_MCU_NAME=\"${FW_MCU}\""
            -Os -g -Wall -Wextra -std=gnu11 ${CNC_AVR_FW_CFLAGS} ${FW_DEFINES} ${srcs} -o ${elf} ${CNC_AVR_FW_LDFLAGS}
    DEPENDS ${srcs} ${deps} VERBATIM COMMENT "avr-gcc ${NAME}.elf (${FW_MCU})")
  set(outputs ${elf})
  if(FW_HEX)
    set(hex ${CMAKE_CURRENT_BINARY_DIR}/${NAME}.hex)
    add_custom_command(OUTPUT ${hex}
      COMMAND ${AVR_OBJCOPY} -O ihex -j .text -j .data ${elf} ${hex}
      DEPENDS ${elf} VERBATIM COMMENT "avr-objcopy ${NAME}.hex")
    list(APPEND outputs ${hex})
  endif()
  add_custom_target(${NAME} ALL DEPENDS ${outputs})
  set_target_properties(${NAME} PROPERTIES AVR_ELF ${elf})
  if(FW_HEX)
    set_target_properties(${NAME} PROPERTIES AVR_HEX ${hex})
  endif()
endfunction()
