# Bad input once found accepted or misreported (exit 2 naming the file, line or key, nothing simulated or
# written), inputs within the machine, output paths checked before a run, and write errors that fail it (exit 1).
# Included from tests/sim/CMakeLists.txt, which defines cnc_bad_input_test, BAD and SQUARE.
set(ROBUST ${CMAKE_CURRENT_BINARY_DIR}/robust)
set(SCENARIOS ${PROJECT_SOURCE_DIR}/scenarios)

function(cnc_cli_test NAME LABEL EXIT)
  cmake_parse_arguments(T "" "NO_FILE;FILE;FILE_MATCH;STDOUT" "CMD;MATCH" ${ARGN})
  list(JOIN T_CMD "|" cmd)
  list(JOIN T_MATCH "|" match)
  set(extra)
  if(T_NO_FILE)
    list(APPEND extra -DNO_FILE=${T_NO_FILE})
  endif()
  if(T_FILE)
    list(APPEND extra -DFILE=${T_FILE} "-DFILE_MATCH=${T_FILE_MATCH}")
  endif()
  if(T_STDOUT)
    list(APPEND extra -DSTDOUT=${T_STDOUT})
  endif()
  add_test(NAME ${LABEL}/${NAME}
    COMMAND ${CMAKE_COMMAND} "-DCMD=$<TARGET_FILE:cncsim>|${cmd}" -DEXIT=${EXIT} "-DMATCH=${match}" ${extra}
            -P ${PROJECT_SOURCE_DIR}/cmake/expect_run.cmake)
  set_tests_properties(${LABEL}/${NAME} PROPERTIES LABELS golden ENVIRONMENT "${CNC_TEST_ENV}")
endfunction()

# --- Bad input, one test each ---
cnc_bad_input_test(steps_file_without_header ${BAD}/no_header_steps.toml "no_header.steps:1: a data row where the header belongs")
cnc_cli_test(bad_input.analyze_steps_per_mm_nan golden 2
  CMD analyze ${PROJECT_SOURCE_DIR}/tests/data/vcd/capture_with_bus.vcd --step step_x --dir dir_x --steps-per-mm nan
  MATCH "--steps-per-mm: must be a finite number > 0")
cnc_bad_input_test(empty_job_strict "${BAD}/empty_job.toml|--set|scenario.gcode_policy=strict"
                   "empty[.]nc: the job has no XY move" "gcode_policy = .strict. refuses it")
cnc_bad_input_test(comment_only_job_strict "${BAD}/comments_only.toml|--set|scenario.gcode_policy=strict"
                   "comments_only[.]nc: the job has no XY move [(]3 lines")
cnc_cli_test(comment_only_job_warns golden 0 CMD run ${BAD}/comments_only.toml --progress off
  MATCH "warning: .*comments_only[.]nc: the job has no XY move")
cnc_bad_input_test(fpga_uart_baud_300 "${SQUARE}|--set|link.baud=300" "link.baud, fpga.uart_baud: baud mismatch")
cnc_bad_input_test(number_out_of_range ${BAD}/exponent_out_of_range.toml
                   "exponent_out_of_range[.]nc:2: number '1e400' is out of range")
cnc_bad_input_test(missing_job_names_the_key ${BAD}/missing_job.toml "missing_job[.]toml:2: scenario[.]job: the job file .*no_such_job[.]nc does not exist")
cnc_bad_input_test(job_is_a_folder "${SQUARE}|--set|scenario.job=${BAD}" "--set scenario[.]job: .*bad is a folder, not a job file")
cnc_bad_input_test(scenario_is_a_folder ${BAD} "tests/data/bad: is a folder, not a scenario file")
cnc_bad_input_test(set_of_unknown_key "${SQUARE}|--set|link.bauds=3" "--set link[.]bauds: unknown key [(]allowed in [[]link[]]: baud")
cnc_bad_input_test(set_of_bad_value "${SQUARE}|--set|link.baud=12" "--set link[.]baud: 12 is out of range")
cnc_bad_input_test(numerator_overflow ${BAD}/numerator_overflow.toml
                   "numerator_overflow[.]toml: machine[.]x[.]steps_per_mm .*fpga[.]clock_hz: 0[.]01 steps/mm: NUMERATOR")
cnc_bad_input_test(control_bytes_escaped ${BAD}/control_bytes.toml "control_bytes[.]nc:2: unexpected character '.x1B'")

# --- Inputs within the machine, on every architecture (the same check before any host runs) ---
set(archs fpga-uart spi-fpga)
if(CNC_WITH_AVR)
  list(APPEND archs atmega)
endif()
foreach(arch IN LISTS archs)
  cnc_bad_input_test(huge_rapid.${arch} "${BAD}/huge_rapid.toml|--set|scenario.architecture=${arch}"
                     "huge_rapid[.]nc:3: X 2[.]888888889e[+]13 mm is out of range" "2.30 - 1 steps")
  cnc_bad_input_test(huge_arc.${arch} "${BAD}/huge_arc.toml|--set|scenario.architecture=${arch}"
                     "huge_arc[.]nc:4: .*out of range")
  cnc_bad_input_test(endless_job.${arch} "${BAD}/endless_job.toml|--set|scenario.architecture=${arch}"
                     "endless_job[.]nc:3: the job reaches .* more than the longest job simulated, 1e[+]06 s")
endforeach()
cnc_bad_input_test(spi_feed_below_rate_word ${BAD}/slow_feed_spi.toml
                   "slow_feed[.]nc:3: feed 0[.]01 mm/min .* slower than the spi-fpga rate word's slowest step")

# --- Output paths ---
file(MAKE_DIRECTORY ${ROBUST}/folder.vcd)
cnc_cli_test(output.vcd_is_a_folder golden 2 CMD run ${SQUARE} --vcd ${ROBUST}/folder.vcd --progress off
  MATCH "^cncsim: --vcd .*folder[.]vcd: is a folder, not a file\n$")
cnc_cli_test(output.report_in_missing_folder golden 2
  CMD run ${SQUARE} --report ${ROBUST}/no_such_folder/r.json --progress off
  MATCH "^cncsim: --report .*no_such_folder/r[.]json: its folder .*no_such_folder does not exist\n$")
file(WRITE ${ROBUST}/plain_file "")
cnc_cli_test(output.plots_under_a_file golden 2 CMD run ${SQUARE} --plots ${ROBUST}/plain_file/plots --progress off
  MATCH "^cncsim: --plots .*plain_file/plots: .*plain_file is not a folder\n$")
cnc_cli_test(output.compare_out_under_a_file golden 2 CMD compare ${SQUARE} --arch fpga-uart --out ${ROBUST}/plain_file/o
  MATCH "^cncsim: --out .*plain_file/o: .*plain_file is not a folder\n$")
cnc_cli_test(output.compare_report_in_missing_folder golden 2
  CMD compare ${SQUARE} --arch fpga-uart --report ${ROBUST}/no_such_folder/c.json
  MATCH "^cncsim: --report .*: its folder .*no_such_folder does not exist\n$")
cnc_cli_test(output.report_to_dev_full golden 1 CMD run ${SQUARE} --report /dev/full --progress off
  MATCH "cncsim: run failed: cannot write /dev/full [(]--report[)]: No space left on device")
cnc_cli_test(output.vcd_to_dev_full golden 1
  CMD run ${SQUARE} --vcd /dev/full --report ${ROBUST}/vcd_to_dev_full.json --progress off
  MATCH "cncsim: run failed: cannot write /dev/full [(]the VCD[)]: No space left on device"
  NO_FILE ${ROBUST}/vcd_to_dev_full.json)
# --vcd writes the path given (SystemC's tracer appended .vcd), complete, with no .partial left.
file(REMOVE ${ROBUST}/trace ${ROBUST}/trace.partial ${ROBUST}/trace.vcd)
cnc_cli_test(output.vcd_path_as_given golden 0 CMD run ${SQUARE} --vcd ${ROBUST}/trace --progress off
  MATCH "square" NO_FILE ${ROBUST}/trace.partial FILE ${ROBUST}/trace FILE_MATCH "[$]enddefinitions")

# --- Traces of long jobs: trace.signals, trace.from_s/to_s, SPI wires on request ---
# A window from 1 s to 2 s of simulated time at 100 ps: $dumpvars at tick 1e10, the file ends at tick 2e10.
cnc_cli_test(trace.window_and_signals golden 0
  CMD run ${SQUARE} --vcd ${ROBUST}/window.vcd --progress off --set "trace.signals=[\"step_x\", \"dir_x\"]"
      --set trace.from_s=1 --set trace.to_s=2
  MATCH "square"
  FILE ${ROBUST}/window.vcd
  FILE_MATCH "[$]scope module cncsim [$]end\n[$]scope module driver_x [$]end\n[$]var wire 1 ! step_x [$]end\n"
             "[$]var wire 1 \" dir_x [$]end\n[$]upscope [$]end\n[$]upscope"
             "[$]enddefinitions [$]end\n#10000000000\n[$]dumpvars\n" "\n#20000000000\n$")
cnc_bad_input_test(trace_signal_unknown "${SQUARE}|--set|trace.signals=[\"step_x\", \"stepx\"]|--vcd|${ROBUST}/unknown.vcd"
                   "square_20mm[.]toml: trace[.]signals: 'stepx' is not a signal of fpga-uart [(]allowed: step_x, dir_x, n_enbl_x, step_y")
cnc_bad_input_test(trace_window_reversed "${SQUARE}|--set|trace.from_s=2|--set|trace.to_s=1"
                   "--set trace[.]to_s: 1 s must be after trace[.]from_s = 2 s")
# spi-fpga: the SPI wires are not driven bit by bit, nor traced, unless asked for: laser is the file's last pin,
# the carriage's positions follow it in their own scope.
cnc_cli_test(trace.spi_wires_on_request golden 0
  CMD run ${SCENARIOS}/spi-fpga/square_20mm.toml --vcd ${ROBUST}/spi_default.vcd --progress off
  MATCH "square" FILE ${ROBUST}/spi_default.vcd
  FILE_MATCH " laser [$]end\n[$]upscope [$]end\n[$]scope module carriage [$]end\n"
             "[$]var real 64 [^ ]+ carriage_x_mm [$]end\n[$]var real 64 [^ ]+ carriage_y_mm [$]end\n[$]upscope")

# --- --samples FILE: the tool samples as CSV, checked and written like every output ---
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME golden/samples_file_loads
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/samples_file.py $<TARGET_FILE:cncsim> ${PROJECT_SOURCE_DIR}
          ${ROBUST}/samples_file_loads)
set_tests_properties(golden/samples_file_loads PROPERTIES LABELS golden ENVIRONMENT "${CNC_TEST_ENV}")
cnc_cli_test(output.samples_in_missing_folder golden 2
  CMD run ${SQUARE} --samples ${ROBUST}/no_such_folder/s.csv --progress off
  MATCH "^cncsim: --samples .*no_such_folder/s[.]csv: its folder .*no_such_folder does not exist\n$")
cnc_cli_test(output.samples_to_dev_full golden 1 CMD run ${SQUARE} --samples /dev/full --progress off
  MATCH "cncsim: run failed: cannot write /dev/full [(]--samples[)]: No space left on device")

# --- Standard output: the summary, a compare table or the key list that cannot be written is a failed command ---
cnc_cli_test(output.summary_to_dev_full golden 1 CMD run ${SQUARE} --progress off STDOUT /dev/full
  MATCH "^cncsim: run failed: writing standard output: No space left on device\n$")
cnc_cli_test(output.keys_to_dev_full golden 1 CMD keys STDOUT /dev/full
  MATCH "^cncsim: run failed: writing standard output: No space left on device\n$")

# A clock no oscillator part is: a jitter whose edges could pass each other, an offset outside the part's tolerance.
cnc_bad_input_test(clock_jitter_past_period "${SQUARE}|--set|fpga.clock_jitter_rms_ps=1250"
                   "--set fpga[.]clock_jitter_rms_ps: 1250 ps: must be below a sixteenth of the clock's period")
cnc_bad_input_test(clock_offset_outside_tolerance "${SQUARE}|--set|clock.offset_ppm=80"
                   "--set clock[.]offset_ppm: 80 ppm is outside the part's tolerance of [+]-50 ppm")
