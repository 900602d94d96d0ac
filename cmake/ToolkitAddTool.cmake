# toolkit_add_tool(NAME): the one place a tool is wired in.
#   - builds tools/NAME/main.cpp against libshared,
#   - installs the executable and man/NAME.1 (PREFIX honoured),
#   - registers test/bats/NAME.bats under ctest when tests are on.
function(toolkit_add_tool name)
  add_executable(${name} ${PROJECT_SOURCE_DIR}/tools/${name}/main.cpp)
  target_link_libraries(${name} PRIVATE toolkit_shared toolkit_flags)
  target_compile_definitions(${name} PRIVATE TOOLKIT_TOOL_NAME="${name}")
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${PROJECT_SOURCE_DIR}/man/${name}.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  set(bats_file ${PROJECT_SOURCE_DIR}/test/bats/${name}.bats)
  if(TOOLKIT_TESTS AND EXISTS ${bats_file})
    add_test(NAME bats_${name}
             COMMAND bats --tap ${bats_file})
    set_tests_properties(bats_${name} PROPERTIES
      ENVIRONMENT "TOOLKIT_BIN=$<TARGET_FILE_DIR:${name}>;TOOLKIT_ROOT=${PROJECT_SOURCE_DIR}"
      TIMEOUT 1800)
  endif()
endfunction()
