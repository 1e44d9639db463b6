# Runs `g2d check tests/bad/NAME.g2d` and compares its first line of output
# with tests/bad/NAME.expected. Fails on a crash, a wrong exit code or text.
execute_process(
  COMMAND "${G2D}" check "tests/bad/${NAME}.g2d"
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 30)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit code 1, got '${rc}'\n${err}")
endif()
string(REGEX REPLACE "\n.*" "" first "${err}")
file(READ "tests/bad/${NAME}.expected" expected)
string(REGEX REPLACE "\n.*" "" expected "${expected}")
if(NOT first STREQUAL expected)
  message(FATAL_ERROR "first diagnostic differs\n  expected: ${expected}\n  actual:   ${first}\n\nfull output:\n${err}")
endif()
