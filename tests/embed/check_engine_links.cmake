# g2d_engine is what embedding programs link: it must not bring the run
# library's dependencies (librsvg and cairo for PNG, CLI11 for options).
# -DLINKS=<g2d_engine's LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES, one line>
# -DPROGRAM=<a program linking only g2d_engine> -DREADELF=<readelf, or empty>
set(forbidden "rsvg|cairo|CLI11|gio-2|glib-2|gobject-2")
file(READ "${LINKS}" links)
string(STRIP "${links}" links)
if(links MATCHES "${forbidden}")
  message(FATAL_ERROR "g2d_engine links ${CMAKE_MATCH_0}: ${links}")
endif()
message(STATUS "g2d_engine links: ${links}")
if(READELF)
  execute_process(COMMAND "${READELF}" -d "${PROGRAM}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${READELF} -d ${PROGRAM} failed")
  endif()
  string(REGEX MATCHALL "NEEDED[^\n]*" needed "${dynamic}")
  if(needed MATCHES "${forbidden}")
    message(FATAL_ERROR "${PROGRAM} needs ${CMAKE_MATCH_0}: ${needed}")
  endif()
  message(STATUS "the engine-only program needs: ${needed}")
endif()
