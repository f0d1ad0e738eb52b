# cmake -DBUILD_DIR=<build tree> -DTARGET=<probe> -DCONFIG=<config> -DEXPECT=pass|fail
#       [-DMESSAGE_REGEX=<what the failed build must say>] -P build_probe.cmake
# Builds one probe target of tests/layering and checks the outcome: EXPECT=fail needs a
# failed build whose output matches MESSAGE_REGEX (a build failing for another reason is
# a test failure, not a pass).
foreach(var BUILD_DIR TARGET CONFIG EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "build_probe.cmake: -D${var}=... is required")
  endif()
endforeach()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target "${TARGET}" --config "${CONFIG}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(EXPECT STREQUAL "pass")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "probe ${TARGET} was expected to compile and did not (exit ${rc})")
  endif()
elseif(EXPECT STREQUAL "fail")
  if(rc EQUAL 0)
    message(FATAL_ERROR "probe ${TARGET} compiled: a layer could include a header it must not see")
  endif()
  if(NOT out MATCHES "${MESSAGE_REGEX}")
    message(FATAL_ERROR "probe ${TARGET} failed, but not with the expected message /${MESSAGE_REGEX}/")
  endif()
else()
  message(FATAL_ERROR "build_probe.cmake: EXPECT must be pass or fail, not '${EXPECT}'")
endif()
