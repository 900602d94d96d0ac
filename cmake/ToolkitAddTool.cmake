# toolkit_add_tool(NAME): the one place a tool is wired in.
#   - builds tools/NAME/*.cpp against libshared (main.cpp wires the options,
#     a tool with several modes keeps one file per mode beside it),
#   - installs the executable and man/NAME.1, gzipped (PREFIX honoured),
#   - registers test/bats/NAME.bats under ctest when tests are on.
# toolkit_compile_as_wiring(TARGET): for the targets that only wire the
# library up, the tools' mains (CLI11) and the unit tests (GoogleTest), whose
# header-heavy code dominates their compile time while the work runs in the
# library (built as shipped, -O3). Release: -O1, half the time of -O3 with
# the tools' runtimes measured unchanged. Sanitizer pass: -O0 (a main.cpp
# took ~100 s at -O2, ~15 s at -O0) under ASan alone (see toolkit_flags);
# the library keeps -O1 and both sanitizers. Set on the target, not per
# source, so the unity build still batches their sources.
function(toolkit_compile_as_wiring target)
  if(TOOLKIT_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
    set_target_properties(${target} PROPERTIES TOOLKIT_ADDRESS_SANITIZER_ONLY ON)
  else()
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()

include(ToolkitTestCosts)

# `make demo` and the sanitizer pass build the tools alone: `--target toolkit_tools`.
add_custom_target(toolkit_tools)

function(toolkit_add_tool name)
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/${name}/*.cpp)
  add_executable(${name} ${sources})
  add_dependencies(toolkit_tools ${name})
  target_link_libraries(${name} PRIVATE toolkit_shared toolkit_flags fmt::fmt)  # the mains format with fmt
  toolkit_compile_as_wiring(${name})
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # The committed page, gzipped without a timestamp as Debian installs man pages.
  set(page ${PROJECT_BINARY_DIR}/man/${name}.1.gz)
  add_custom_command(OUTPUT ${page}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
    COMMAND gzip -9n -c ${PROJECT_SOURCE_DIR}/man/${name}.1 > ${page}
    DEPENDS ${PROJECT_SOURCE_DIR}/man/${name}.1)
  add_custom_target(${name}_man ALL DEPENDS ${page})
  add_dependencies(toolkit_tools ${name}_man)
  install(FILES ${page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  set_property(GLOBAL APPEND PROPERTY TOOLKIT_TOOLS ${name})
  # test/bats/NAME.bats and NAME_*.bats (e.g. NAME_oracle.bats), each one ctest test.
  file(GLOB bats_files ${PROJECT_SOURCE_DIR}/test/bats/${name}.bats ${PROJECT_SOURCE_DIR}/test/bats/${name}_*.bats)
  if(TOOLKIT_TESTS)
    foreach(bats_file IN LISTS bats_files)
      toolkit_add_bats_suite(${bats_file} $<TARGET_FILE_DIR:${name}>)
    endforeach()
  endif()
endfunction()

# toolkit_add_bats_suite(FILE BIN_DIR): one bats file as one ctest test,
# with the tools found in BIN_DIR.
function(toolkit_add_bats_suite bats_file bin_dir)
  get_filename_component(suite ${bats_file} NAME_WE)
  add_test(NAME bats_${suite} COMMAND bats --tap ${bats_file})
  set(cost 30)
  if(DEFINED TOOLKIT_COST_bats_${suite})
    set(cost ${TOOLKIT_COST_bats_${suite}})
  endif()
  set_tests_properties(bats_${suite} PROPERTIES
    ENVIRONMENT "TOOLKIT_BIN=${bin_dir};TOOLKIT_ROOT=${PROJECT_SOURCE_DIR};TOOLKIT_BUILD=${PROJECT_BINARY_DIR}"
    TIMEOUT 1800 COST ${cost})
endfunction()
