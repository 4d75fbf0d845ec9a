# The installed layout, `cmake --install build --prefix P`, also what the Debian package holds
# (CrtPackage.cmake):
#   bin/crtc, bin/crt-lsp
#   lib/crt/crt_image_io_oiio.so        the image module (tracer/image_io/module_loader.cpp)
#   lib/crt/crt_mpi.so                  the MPI module, when built with MPI
#                                       (apps/crtc/distributed/mpi_module_loader.cpp)
#   lib/crt/crtc-preview                the program behind crtc --preview
#                                       (apps/crtc/preview_launch.cpp)
#   share/crt/stdlib/                   the standard library (lang/include_search.cpp)
#   share/crt/editors/                  editor integrations, as editors/ holds them
#   share/man/man1/crtc.1.gz, crt-lsp.1.gz
#   share/bash-completion/completions/crtc
#   share/doc/crt/                      README, docs, the licence (as Debian's copyright),
#                                       the demos as examples
# The programs find the modules and the standard library relative to their own folder, so
# those three paths are fixed here rather than taken from GNUInstallDirs (whose LIBDIR is
# lib/x86_64-linux-gnu on Debian).
include(GNUInstallDirs)
include(CrtManPages)

set(CRT_INSTALL_MODULE_DIR lib/crt)
set(CRT_INSTALL_DATA_DIR share/crt)

install(TARGETS crtc crt-lsp RUNTIME DESTINATION bin)
install(TARGETS crt_image_io_oiio LIBRARY DESTINATION ${CRT_INSTALL_MODULE_DIR})
install(TARGETS crtc-preview RUNTIME DESTINATION ${CRT_INSTALL_MODULE_DIR})
if(TARGET crt_mpi)
  install(TARGETS crt_mpi LIBRARY DESTINATION ${CRT_INSTALL_MODULE_DIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/stdlib/ DESTINATION ${CRT_INSTALL_DATA_DIR}/stdlib)
# The editors' folders are installed as they are, less what a local npm install or a VS Code
# packaging run leaves behind.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/editors/ DESTINATION ${CRT_INSTALL_DATA_DIR}/editors
        PATTERN node_modules EXCLUDE
        PATTERN .vscode-test EXCLUDE
        PATTERN "*.vsix" EXCLUDE)

install(FILES ${CRT_MAN_PAGE_FILES} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/apps/crtc/completion/crtc.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME crtc)

install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN man EXCLUDE PATTERN gallery EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/demos/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# What an install needs built, and no more (no tests): scripts/package.sh builds this target
# before CPack, which packages what is built without building it.
add_custom_target(crt_installed_files)
add_dependencies(crt_installed_files crtc crt-lsp crt_image_io_oiio)
if(TARGET crt_man_pages)
  add_dependencies(crt_installed_files crt_man_pages)
endif()
