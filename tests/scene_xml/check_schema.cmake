# Runs xmllint against scenes/scene.xsd (ctest: SceneXmlSchema.*).
#   cmake -DXMLLINT=... -DSOURCE_DIR=... -DMODE=valid|malformed -P check_schema.cmake
# valid:     every scenes/**/*.xml present now, plus tests/data/scenes/{valid,bad_mesh},
#            must validate (files are globbed at run time, so new scenes are covered).
# malformed: the test files whose fault a schema can see must fail to validate.

set(schema "${SOURCE_DIR}/scenes/scene.xsd")
if(NOT EXISTS "${schema}")
  message(FATAL_ERROR "missing ${schema}")
endif()

if(MODE STREQUAL "valid")
  file(GLOB_RECURSE files LIST_DIRECTORIES false
    "${SOURCE_DIR}/scenes/*.xml"
    "${SOURCE_DIR}/tests/data/scenes/valid/*.xml"
    "${SOURCE_DIR}/tests/data/scenes/bad_mesh/*.xml")
elseif(MODE STREQUAL "malformed")
  set(files)
  foreach(name IN ITEMS malformed_xml unknown_element unknown_attribute non_finite
                        negative_stiffness zero_scale duplicate_names trailing_junk wrong_arity
                        two_shapes missing_version unknown_plugin_kind
                        slow_haptic_rate tiny_haptic_rate absurd_stiffness absurd_material
                        bad_texture absurd_crease_angle)
    list(APPEND files "${SOURCE_DIR}/tests/data/scenes/malformed/${name}.xml")
  endforeach()
else()
  message(FATAL_ERROR "MODE must be valid or malformed, not '${MODE}'")
endif()

list(SORT files)
set(failures)
foreach(file IN LISTS files)
  execute_process(COMMAND "${XMLLINT}" --noout --schema "${schema}" "${file}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(RELATIVE_PATH shown "${SOURCE_DIR}" "${file}")
  if(MODE STREQUAL "valid" AND NOT rc EQUAL 0)
    list(APPEND failures "${shown}")
    message("${shown}: rejected by the schema:\n${err}")
  elseif(MODE STREQUAL "malformed" AND rc EQUAL 0)
    list(APPEND failures "${shown}")
    message("${shown}: accepted by the schema but it is malformed")
  else()
    message("${shown}: ok")
  endif()
endforeach()

list(LENGTH files count)
if(failures)
  list(JOIN failures ", " failed)
  message(FATAL_ERROR "schema check (${MODE}) failed for: ${failed}")
endif()
message("schema check (${MODE}): ${count} files as expected")
