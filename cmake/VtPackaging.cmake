# The Debian package (CPack's DEB generator): scripts/package builds build/valvetune_<version>_<arch>.deb.
# The version is project(VERSION), the one the programs print with --version; the library
# dependencies are computed by dpkg-shlibdeps from the installed executables, not listed here.
# The dictionaries and the translations are compiled into the executables (EmbedDictionaries.cmake,
# :/i18n), so the package installs programs, desktop files, icons, man pages and the completion.

# Debian policy: the package's copyright and changelog under /usr/share/doc/<package>.
set(vt_docdir ${CMAKE_INSTALL_DATADIR}/doc/valvetune)
install(FILES ${PROJECT_SOURCE_DIR}/resources/debian/copyright
        DESTINATION ${vt_docdir})
set(vt_changelog ${PROJECT_BINARY_DIR}/packaging/changelog.gz)
add_custom_command(OUTPUT ${vt_changelog}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/packaging
    COMMAND sh -c "gzip -9n < '${PROJECT_SOURCE_DIR}/resources/debian/changelog' > '${vt_changelog}'"
    DEPENDS ${PROJECT_SOURCE_DIR}/resources/debian/changelog VERBATIM)
add_custom_target(vt_debian_changelog ALL DEPENDS ${vt_changelog})
install(FILES ${vt_changelog} DESTINATION ${vt_docdir})
# The deliberate lintian findings, each with its reason (resources/debian/lintian-overrides).
install(FILES ${PROJECT_SOURCE_DIR}/resources/debian/lintian-overrides
        DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME valvetune)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME valvetune)
set(CPACK_PACKAGE_VENDOR "ValveTune developers")
set(CPACK_PACKAGE_CONTACT "ValveTune Dev <dev@valvetune.invalid>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "tune hydraulic proportional-valve electronics")
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # valvetune_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's own German texts (dialog buttons, standard menus) come from qtbase_de.qm.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS qt6-translations-l10n)
# CPack puts the summary above this and indents it as a control file wants.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "ValveTune parameterises, tunes and commissions the electronics of hydraulic
proportional valves: the HCS OPAT and DMA-2 modules and the Wandfluh ED1/SD1
and SD7 electronics, over a serial line (Modbus RTU, HART), Modbus TCP, the
node image of a fieldbus node, or CANopen (SocketCAN).

The package holds the desktop application valvetune, the command line tool
valvetune-cli and the device simulator valvetune-sim. Serial ports need the
user in the dialout group.")
include(CPack)
