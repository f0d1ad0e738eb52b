# cmake -DROOT=<source tree> -P no_climbing_includes.cmake
# Fails, naming file:line, for every #include "...../..." that resolves into an engine
# layer (ROOT/engine/<layer>/) from a file outside that layer. Such an include walks up the
# source folders past the per-layer include roots (cmake/MhdTargets.cmake), so the
# compiler cannot refuse it; an engine header must come in as "<layer>/<file>.h" through a
# linked library. Relative includes that stay out of the engine (a test's helper in a
# sibling test folder) are not this check's business.
cmake_minimum_required(VERSION 3.25)  # policies: GLOB_RECURSE does not follow links
if(NOT DEFINED ROOT)
  message(FATAL_ERROR "no_climbing_includes.cmake: -DROOT=... is required")
endif()
file(REAL_PATH "${ROOT}" root)
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" root_re "${root}")
file(GLOB_RECURSE sources LIST_DIRECTORIES false
  "${root}/*.h" "${root}/*.hpp" "${root}/*.c" "${root}/*.cpp" "${root}/*.cc")
list(FILTER sources EXCLUDE REGEX "^${root_re}/(build[^/]*|\\.git)/")
set(found "")
foreach(source IN LISTS sources)
  file(STRINGS "${source}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]*\\.\\./")
  if(NOT lines)
    continue()
  endif()
  cmake_path(GET source PARENT_PATH dir)
  # The layer folder the including file lives in, if any.
  set(own_layer "")
  if(source MATCHES "^${root_re}/engine/([^/]+)/")
    set(own_layer "${CMAKE_MATCH_1}")
  endif()
  file(STRINGS "${source}" all_lines)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*$" "\\1" spelled "${line}")
    cmake_path(ABSOLUTE_PATH spelled BASE_DIRECTORY "${dir}" NORMALIZE OUTPUT_VARIABLE reached)
    if(reached MATCHES "^${root_re}/engine/([^/]+)/" AND NOT CMAKE_MATCH_1 STREQUAL own_layer)
      list(FIND all_lines "${line}" index)
      math(EXPR line_number "${index} + 1")
      file(RELATIVE_PATH shown "${root}" "${source}")
      string(APPEND found "\n  ${shown}:${line_number}: #include \"${spelled}\"")
    endif()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "includes that climb into another engine layer's folder:${found}")
endif()
