# cmake -DTARGET=<target> -DFORBIDDEN=<target> "-DCHAIN=<a -> b -> c, or empty>" -P check_link_chain.cmake
# Fails when TARGET links FORBIDDEN, naming the chain (found at configure time by
# link_chain.cmake, mhd_link_chain).
foreach(var TARGET FORBIDDEN)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_link_chain.cmake: -D${var}=... is required")
  endif()
endforeach()
if(CHAIN)
  message(FATAL_ERROR "${TARGET} links ${FORBIDDEN}: ${CHAIN}")
endif()
message("${TARGET} does not link ${FORBIDDEN}")
