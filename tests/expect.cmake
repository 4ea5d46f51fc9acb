# Runs COMMAND (arguments separated by '|') and checks its exit code (EXPECT_CODE), that its
# standard output and error contain EXPECT_OUTPUT (if given) and, with EXPECT_CHECKS, that the
# test program reported running exactly that many checks ("<name>: N checks, M failures", the
# last such line, from psx/test.h's test_done). Used by CTest for CLI behaviour and test programs.
string(REPLACE "|" ";" cmd "${COMMAND}")
# In a sanitizer build a finding must never pass as an expected exit code (ASan and UBSan exit
# with 1 by default, the CLI's usage-error code): unless the caller chose one, they exit with 99,
# which psxrl never uses.
foreach(var ASAN_OPTIONS UBSAN_OPTIONS)
  if(NOT "$ENV{${var}}" MATCHES "exitcode=")
    set(ENV{${var}} "$ENV{${var}}:exitcode=99")
  endif()
endforeach()
execute_process(COMMAND ${cmd} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
message("${all}")
set(problems "")
if(code STREQUAL "99")
  string(APPEND problems "exit code 99: a sanitizer (ASan, LSan or UBSan) reported an error\n")
elseif(NOT code STREQUAL EXPECT_CODE)
  string(APPEND problems "exit code ${code}, expected ${EXPECT_CODE}\n")
endif()
if(DEFINED EXPECT_OUTPUT)
  string(FIND "${all}" "${EXPECT_OUTPUT}" pos)
  if(pos EQUAL -1)
    string(APPEND problems "output does not contain: ${EXPECT_OUTPUT}\n")
  endif()
endif()
if(DEFINED EXPECT_CHECKS)
  string(REGEX MATCHALL "[0-9]+ checks, [0-9]+ failures" reports "${all}")
  if(NOT reports)
    string(APPEND problems "no \"N checks, M failures\" line: the program did not reach test_done\n")
  else()
    list(GET reports -1 last)
    string(REGEX MATCH "^([0-9]+) checks" _ "${last}")
    if(NOT CMAKE_MATCH_1 EQUAL EXPECT_CHECKS)
      string(APPEND problems "the program ran ${CMAKE_MATCH_1} checks, expected ${EXPECT_CHECKS}"
                             " (checks were skipped, or added without updating the test's CHECKS)\n")
    endif()
  endif()
endif()
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
