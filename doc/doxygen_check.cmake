# Documentation build and check, in two roles.
#
# 1. Included from the top-level CMakeLists.txt (`include(doc/doxygen_check.cmake)`): when doxygen
#    is found, registers
#      - the test `doxygen_no_warnings`, which builds the documentation and fails if doxygen
#        fails or writes anything to its warnings file;
#      - the target `sfe_doc` (`cmake --build . --target sfe_doc`), which builds it without the check.
#    The HTML goes to <build dir>/doc/html, the warnings to <build dir>/doc/doxygen_warnings.log.
#
# 2. Run as a script by that test and that target (`cmake -P`), with -DDOXYGEN=<doxygen>
#    -DSOURCE_DIR=<repository root> -DOUTPUT_DIR=<output directory> [-DCHECK=ON]. doc/Doxyfile
#    holds paths relative to the repository root, so doxygen runs there, on a small build-side
#    configuration that includes doc/Doxyfile and only redirects its outputs.

if(CMAKE_SCRIPT_MODE_FILE)
  foreach(variable DOXYGEN SOURCE_DIR OUTPUT_DIR)
    if(NOT ${variable})
      message(FATAL_ERROR "doxygen_check.cmake: -D${variable}=... is required")
    endif()
  endforeach()
  set(warnings_file "${OUTPUT_DIR}/doxygen_warnings.log")
  set(build_config "${OUTPUT_DIR}/Doxyfile")
  # A fresh output directory: pages of removed symbols must not survive, and doxygen does not
  # create missing parent directories.
  file(REMOVE_RECURSE "${OUTPUT_DIR}")
  file(MAKE_DIRECTORY "${OUTPUT_DIR}")
  file(WRITE "${build_config}"
       "@INCLUDE = \"${SOURCE_DIR}/doc/Doxyfile\"\n"
       "OUTPUT_DIRECTORY = \"${OUTPUT_DIR}\"\n"
       "WARN_LOGFILE = \"${warnings_file}\"\n")
  execute_process(COMMAND "${DOXYGEN}" "${build_config}"
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "doxygen failed (exit status ${status})")
  endif()
  if(CHECK)
    file(READ "${warnings_file}" warnings)
    if(NOT warnings STREQUAL "")
      message(FATAL_ERROR "doxygen reported warnings (${warnings_file}):\n${warnings}")
    endif()
  endif()
  message(STATUS "Documentation: ${OUTPUT_DIR}/html/index.html")
  return()
endif()

find_package(Doxygen QUIET)
if(DOXYGEN_FOUND)
  get_filename_component(_sfe_source_dir "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
  set(_sfe_doc_command
      "${CMAKE_COMMAND}" "-DDOXYGEN=${DOXYGEN_EXECUTABLE}" "-DSOURCE_DIR=${_sfe_source_dir}"
      "-DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/doc")
  enable_testing()
  add_test(NAME doxygen_no_warnings
           COMMAND ${_sfe_doc_command} -DCHECK=ON -P "${CMAKE_CURRENT_LIST_FILE}")
  set_tests_properties(doxygen_no_warnings PROPERTIES LABELS documentation TIMEOUT 600)
  add_custom_target(sfe_doc
                    COMMAND ${_sfe_doc_command} -P "${CMAKE_CURRENT_LIST_FILE}"
                    COMMENT "Building the documentation with doxygen"
                    VERBATIM)
  message(STATUS "Sharp_feature_extraction: doxygen found, test doxygen_no_warnings and target sfe_doc added")
else()
  message(STATUS "Sharp_feature_extraction: doxygen not found, documentation test skipped")
endif()
