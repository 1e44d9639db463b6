# The runtime's prefetches must reach the machine code. GCC deleted every
# call to the small helpers that held only `__builtin_prefetch` (its
# pure-const analysis found them "pure"), and nothing but the object code
# showed it: the pick lookahead still guessed right, and Koch level 10 ran a
# fifth slower. So:
#  1. every prefetch goes through g2d/prefetch.hpp (a volatile asm
#     statement, which the compiler keeps): no `__builtin_prefetch`
#     elsewhere in the runtime, the compiler or the generated code's emitter;
#  2. the optimised lookahead holds prefetch instructions (at -O2 the old
#     code had none left in PickLookahead::ahead).
# -DSOURCE=<project root> -DOBJDUMP=… -DOBJECTS=<the runtime's object files, ;-separated>
file(GLOB_RECURSE sources "${SOURCE}/runtime/*.hpp" "${SOURCE}/runtime/*.cpp" "${SOURCE}/compiler/*.hpp"
     "${SOURCE}/compiler/*.cpp")
foreach(path IN LISTS sources)
  if(path MATCHES "/prefetch\\.hpp$")
    continue()
  endif()
  file(STRINGS "${path}" hits REGEX "__builtin_prefetch")
  if(hits)
    message(FATAL_ERROR "${path} calls __builtin_prefetch directly; use prefetchLine (g2d/prefetch.hpp): ${hits}")
  endif()
endforeach()

foreach(obj IN LISTS OBJECTS)
  if(obj MATCHES "pick_lookahead\\.cpp\\.o$")
    set(lookahead "${obj}")
  endif()
endforeach()
if(NOT lookahead)
  message(FATAL_ERROR "no pick_lookahead object among: ${OBJECTS}")
endif()
execute_process(COMMAND "${OBJDUMP}" -d -C --no-show-raw-insn "${lookahead}"
                OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} failed on ${lookahead}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(function "")
set(random_picks 0)
set(oldest_picks 0)
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-f]+ <(.*)>:$")
    set(function "${CMAKE_MATCH_1}")
  elseif(line MATCHES "\tprefetch")
    if(function MATCHES "PickLookahead::ahead\\(")
      math(EXPR random_picks "${random_picks}+1")
    elseif(function MATCHES "PickLookahead::aheadOldest\\(")
      math(EXPR oldest_picks "${oldest_picks}+1")
    endif()
  endif()
endforeach()
# Each holds at least the slot or group-header prefetch and a record's
# (whose lines are asked for in a loop, so the count is of places in the
# code, not of prefetches a step makes).
if(random_picks LESS 2 OR oldest_picks LESS 2)
  message(FATAL_ERROR "prefetch instructions in PickLookahead::ahead: ${random_picks}, in aheadOldest: "
                      "${oldest_picks} (want 2 or more each): the compiler dropped the lookahead's prefetches")
endif()
message(STATUS "prefetches kept: ahead ${random_picks}, aheadOldest ${oldest_picks}")
