# The Debian package, built by CPack from the install rules (CrtInstall.cmake):
# scripts/package.sh writes dist/crt_<version>_amd64.deb.
set(CRT_PACKAGE_MAINTAINER "The crt authors" CACHE STRING
    "The Debian package's Maintainer field (a name and <address>)")
set(CRT_PACKAGE_HOMEPAGE "" CACHE STRING "The Debian package's Homepage field (none when empty)")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME crt)
set(CPACK_PACKAGE_VENDOR "the crt authors")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "renderer and language server for the CRT scene language")
set(CPACK_PACKAGE_CONTACT ${CRT_PACKAGE_MAINTAINER})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_SOURCE_DIR}/dist)
# Debian installs stripped programs.
set(CPACK_STRIP_FILES ON)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # crt_<version>_<architecture>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER ${CRT_PACKAGE_MAINTAINER})
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
if(CRT_PACKAGE_HOMEPAGE)
  set(CPACK_DEBIAN_PACKAGE_HOMEPAGE ${CRT_PACKAGE_HOMEPAGE})
endif()
# Debian's extended description, under the summary above.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "CRT is a POV-Ray-style language for describing 3D scenes: objects, CSG, materials,
textures, lights and cameras, with macros and loops. crtc checks, evaluates and
renders scripts to PNG, JPEG, TIFF, OpenEXR, HDR or animated GIF, reporting
errors as compilers do. crt-lsp is a language server that gives editors
diagnostics, completion, hover, navigation, rename and formatting; Neovim and
VS Code files are in /usr/share/crt/editors.")
# Depends: from the shared libraries the programs and the modules (image, MPI) link
# (dpkg-shlibdeps, from dpkg-dev).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Not a library, so shlibdeps cannot see it: the font a Text uses when it names none.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
# Man pages are installed gzipped already (CrtManPages.cmake); control files 0644/0755.
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
