# RodynPFUnit.cmake - unit tests written in pFUnit's .pf format.
#
#   rodyn_add_pf_test(NAME <name>
#                     TEST_SOURCES <test_a.pf> [<test_b.pf> ...]
#                     [LINK_LIBRARIES <lib> ...]
#                     [LABELS <label> ...])
#
# Builds executable <name> from the .pf files and registers it as CTest test <name>.
# With pFUnit found (the caller ran `find_package(PFUNIT QUIET)` first) this forwards to
# pFUnit's add_pfunit_ctest().  Otherwise pfunit-lite is used: tools/pfunit_lite/pf2f90.py
# translates each .pf into a Fortran module in the build tree, a generated driver program
# runs every @test, and the module `funit` comes from the static library funit_lite.
#
# Each test executable writes its .mod files to its own folder (<name>_modules in the
# current binary directory) so that test modules of different executables cannot clash;
# project modules are seen through the usage requirements of the linked libraries.

include_guard(GLOBAL)

get_filename_component(RODYN_PFUNIT_LITE_DIR "${CMAKE_CURRENT_LIST_DIR}/../tools/pfunit_lite"
                       ABSOLUTE)

if(NOT PFUNIT_FOUND)
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
endif()

# The funit_lite library, created once for the whole build.
function(_rodyn_pfunit_lite_library)
  if(TARGET funit_lite)
    return()
  endif()
  set(moddir "${CMAKE_BINARY_DIR}/pfunit_lite/modules")
  add_library(funit_lite STATIC "${RODYN_PFUNIT_LITE_DIR}/funit.f90")
  set_target_properties(funit_lite PROPERTIES
    Fortran_MODULE_DIRECTORY "${moddir}"
    ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/pfunit_lite")
  target_include_directories(funit_lite PUBLIC "${moddir}")
  if(DEFINED RODYN_WARN)
    target_compile_options(funit_lite PRIVATE ${RODYN_WARN})
  endif()
endfunction()

function(rodyn_add_pf_test)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME" "TEST_SOURCES;LINK_LIBRARIES;LABELS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "rodyn_add_pf_test: unexpected arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_NAME OR NOT ARG_TEST_SOURCES)
    message(FATAL_ERROR "rodyn_add_pf_test: NAME and TEST_SOURCES are required")
  endif()

  if(PFUNIT_FOUND)
    add_pfunit_ctest(${ARG_NAME}
      TEST_SOURCES ${ARG_TEST_SOURCES}
      LINK_LIBRARIES ${ARG_LINK_LIBRARIES})
  else()
    if(NOT Python3_Interpreter_FOUND)
      find_package(Python3 COMPONENTS Interpreter REQUIRED)
    endif()
    _rodyn_pfunit_lite_library()

    set(translator "${RODYN_PFUNIT_LITE_DIR}/pf2f90.py")
    set(gendir "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_pf")
    set(generated)
    set(pf_files)
    foreach(src IN LISTS ARG_TEST_SOURCES)
      get_filename_component(src "${src}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
      get_filename_component(stem "${src}" NAME_WE)
      set(out "${gendir}/${stem}.F90")
      add_custom_command(
        OUTPUT "${out}"
        COMMAND "${Python3_EXECUTABLE}" "${translator}" "${src}" "${out}"
        DEPENDS "${src}" "${translator}"
        COMMENT "pfunit-lite: translating ${stem}.pf"
        VERBATIM)
      list(APPEND generated "${out}")
      list(APPEND pf_files "${src}")
    endforeach()

    set(driver "${gendir}/${ARG_NAME}_driver.F90")
    add_custom_command(
      OUTPUT "${driver}"
      COMMAND "${Python3_EXECUTABLE}" "${translator}" --driver "${driver}" --driver-only
              ${pf_files}
      DEPENDS "${translator}" "${CMAKE_CURRENT_LIST_FILE}"
      COMMENT "pfunit-lite: writing the driver of ${ARG_NAME}"
      VERBATIM)

    add_executable(${ARG_NAME} ${generated} "${driver}")
    target_link_libraries(${ARG_NAME} PRIVATE funit_lite ${ARG_LINK_LIBRARIES})
    add_test(NAME ${ARG_NAME} COMMAND ${ARG_NAME})
  endif()

  set_target_properties(${ARG_NAME} PROPERTIES
    Fortran_MODULE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_modules")
  if(ARG_LABELS)
    set_tests_properties(${ARG_NAME} PROPERTIES LABELS "${ARG_LABELS}")
  endif()
endfunction()
