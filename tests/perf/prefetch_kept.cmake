# The pick lookahead's prefetches must survive optimisation. GCC once deleted
# every call to the small helpers that held only `__builtin_prefetch` (it
# found them "pure"), and nothing but the machine code showed it: the
# lookahead still guessed right, and the run was a quarter slower at a
# million matches. This reads the optimised object code and counts the
# prefetch instructions in each lookahead function.
# -DOBJDUMP=… -DOBJECTS=<the runtime's object files, ;-separated>
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
# The thresholds are below what the code holds now (14 and 6 at -O3) and
# above what it kept when the calls were deleted (3 and 5 at -O3, 0 and 1
# at -O2).
if(NOT random_picks GREATER_EQUAL 8 OR NOT oldest_picks GREATER_EQUAL 3)
  message(FATAL_ERROR "prefetch instructions in PickLookahead::ahead: ${random_picks} (want 8), "
                      "in aheadOldest: ${oldest_picks} (want 3): the compiler dropped the lookahead's prefetches")
endif()
message(STATUS "prefetches kept: ahead ${random_picks}, aheadOldest ${oldest_picks}")
