# mhd_set_warnings(<target>): MHD's warning policy on one target, per language, so a C
# source never gets a C++-only flag (-Wnon-virtual-dtor). Errors when MHD_WERROR is ON.
# Installed with the CMake package (MhdPlugin.cmake uses it for out-of-tree plugins).
include_guard(GLOBAL)

function(mhd_set_warnings target)
  set(cxx -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wnon-virtual-dtor -Wcast-align -Wnull-dereference
          -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  set(c ${cxx})
  list(REMOVE_ITEM c -Wnon-virtual-dtor)
  target_compile_options(${target} PRIVATE "$<$<COMPILE_LANGUAGE:CXX>:${cxx}>" "$<$<COMPILE_LANGUAGE:C>:${c}>")
  if(MHD_WERROR)
    target_compile_options(${target} PRIVATE "$<$<COMPILE_LANGUAGE:C,CXX>:-Werror>")
  endif()
endfunction()
