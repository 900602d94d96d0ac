# `make deb`: a Debian package of the ten tools (CPack's DEB generator).
#   /usr/bin/TOOL, /usr/share/man/man1/TOOL.1.gz (installed by toolkit_add_tool),
#   /usr/share/doc/toolkit/{examples/,copyright,changelog.gz},
#   bash and zsh completions.
# Runtime dependencies come from dpkg-shlibdeps on the binaries as linked.

install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
foreach(tool IN LISTS TOOLKIT_TOOLS)
  install(FILES ${PROJECT_SOURCE_DIR}/completions/toolkit.bash
          DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME ${tool})
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/completions/_toolkit DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)

# A native package's changelog is changelog.gz, gzipped without a timestamp (gzip -n), dated
# by SOURCE_DATE_EPOCH when set so two builds of one commit match.
set(TOOLKIT_DEB_MAINTAINER "Toolkit maintainers <toolkit@example.org>" CACHE STRING "The package's Maintainer field")
string(TIMESTAMP TOOLKIT_DEB_DATE "%a, %d %b %Y %H:%M:%S +0000" UTC)
configure_file(${PROJECT_SOURCE_DIR}/packaging/changelog.in ${PROJECT_BINARY_DIR}/packaging/changelog @ONLY)
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/packaging/changelog.gz
  COMMAND gzip -9nf -k ${PROJECT_BINARY_DIR}/packaging/changelog
  DEPENDS ${PROJECT_BINARY_DIR}/packaging/changelog VERBATIM)
add_custom_target(toolkit_changelog ALL DEPENDS ${PROJECT_BINARY_DIR}/packaging/changelog.gz)
add_dependencies(toolkit_tools toolkit_changelog)
install(FILES ${PROJECT_BINARY_DIR}/packaging/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME toolkit)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGE_CONTACT "${TOOLKIT_DEB_MAINTAINER}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Unix filters for prime hunters and machining engineers")
# CPack puts the summary first and indents these lines itself.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Ten command-line tools that read records on standard input and write JSON
Lines or CSV, each implementing a published method: sieve, mrtest and riesel
for prime searches (generalized sieve, BPSW, Lucas-Lehmer-Riesel and Proth
proofs); gcode-pulse, dxf2region and threadcalc for CNC preparation;
fuzzyfeed, smcsim, tnorm-bench and subtune for control studies.")
include(CPack)
