# Turns a text file into a C++ source that defines `const std::string& NAME()`
# in g2d::rt, returning the file's bytes (for the --view page's script, see
# runtime/CMakeLists.txt). The text goes in raw string literals of under
# 60,000 bytes each, joined at run time: no compiler limit on one literal
# applies, and -Wpedantic stays quiet.
# Usage: cmake -DINPUT=FILE -DOUTPUT=FILE.cpp -DNAME=function -DHEADER=g2d/x.hpp [-DWHOLE_PAGE=ON] -P embed_text.cmake
# WHOLE_PAGE: the text is a page served as it is (the studio's), not a script inlined in one.
cmake_minimum_required(VERSION 3.25)
file(READ "${INPUT}" text)
set(delimiter "g2d_embed")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains )${delimiter}\": pick another delimiter in ${CMAKE_CURRENT_LIST_FILE}")
endif()
# A script is inlined in a <script> element: these would end it early.
string(TOLOWER "${text}" lower)
set(inline_breakers "</script" "<!--")
if(WHOLE_PAGE)
  set(inline_breakers)
endif()
foreach(bad ${inline_breakers})
  string(FIND "${lower}" "${bad}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${INPUT} contains ${bad} at byte ${at}: it cannot be inlined in a <script> element")
  endif()
endforeach()

string(LENGTH "${text}" length)
set(out "// Generated from ${INPUT} by cmake/embed_text.cmake: do not edit.\n")
string(APPEND out "#include <string>\n\n#include \"${HEADER}\"\n\nnamespace g2d::rt {\n\nnamespace {\nconst char* const kChunks[] = {\n\"\",\n")
set(chunk 60000)
set(at 0)
while(at LESS length)
  string(SUBSTRING "${text}" ${at} ${chunk} piece)
  string(APPEND out "R\"${delimiter}(${piece})${delimiter}\",\n")
  math(EXPR at "${at} + ${chunk}")
endwhile()
string(APPEND out "};\n}  // namespace\n\nconst std::string& ${NAME}() {\n")
string(APPEND out "    static const std::string text = [] {\n        std::string s;\n        s.reserve(${length});\n")
string(APPEND out "        for (const char* c : kChunks) s += c;\n        return s;\n    }();\n    return text;\n}\n\n}  // namespace g2d::rt\n")
# Replaced only when it changes, so an unchanged bundle compiles nothing.
file(WRITE "${OUTPUT}.tmp" "${out}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
