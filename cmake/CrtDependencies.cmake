# Finds the packages every part of crt builds against (Debian 12 versions).
find_package(BISON 3.8 REQUIRED)
find_program(RE2C_EXECUTABLE re2c REQUIRED)
find_package(fmt REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(Catch2 2 REQUIRED)
find_package(CLI11 2.1 REQUIRED) # crtc's command line
# crtc --preview's HTTP server (cpp-httplib: declarations in httplib.h, the code in the shared
# library; its pkg-config flags must be used as given, they change the classes' layout).
find_package(PkgConfig REQUIRED)
pkg_check_modules(CPP_HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
find_package(PNG REQUIRED)
find_package(Freetype REQUIRED) # Text's glyph outlines
find_package(assimp REQUIRED)   # PLY, STL and glTF meshes
find_package(ZLIB REQUIRED) # a test deflates the strips of a TIFF it writes by hand
# MPI (optional): with it, crtc under mpirun shares a render out over the processes
# (apps/crtc/distributed); without it, crtc says so when started by mpirun.
find_package(MPI COMPONENTS CXX QUIET)
