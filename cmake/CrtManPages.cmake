# Manual pages: written in Markdown (docs/man/*.md), turned into roff by go-md2man at build
# time and gzipped as Debian installs them. Target crt_man_pages; CRT_MAN_PAGE_FILES lists
# the .gz files for CrtInstall.cmake.
option(CRT_MAN_PAGES "Build and install the manual pages (needs go-md2man)" ON)
set(CRT_MAN_PAGE_FILES)
if(NOT CRT_MAN_PAGES)
  return()
endif()
find_program(CRT_GO_MD2MAN go-md2man)
if(NOT CRT_GO_MD2MAN)
  message(FATAL_ERROR "go-md2man, which builds the manual pages, was not found: run "
                      "scripts/setup.sh, or configure with -DCRT_MAN_PAGES=OFF")
endif()

set(crt_man_dir ${CMAKE_BINARY_DIR}/man)
foreach(page crtc.1 crt-lsp.1)
  # The version comes from project(): the page's title line carries @PROJECT_VERSION@.
  configure_file(${PROJECT_SOURCE_DIR}/docs/man/${page}.md ${crt_man_dir}/${page}.md @ONLY)
  # gzip -n: no name or time stamp inside, so the same page gives the same bytes.
  add_custom_command(
    OUTPUT ${crt_man_dir}/${page} ${crt_man_dir}/${page}.gz
    COMMAND ${CRT_GO_MD2MAN} -in ${crt_man_dir}/${page}.md -out ${crt_man_dir}/${page}
    COMMAND gzip -9 -n -k -f ${crt_man_dir}/${page}
    DEPENDS ${crt_man_dir}/${page}.md
    COMMENT "go-md2man ${page}")
  list(APPEND CRT_MAN_PAGE_FILES ${crt_man_dir}/${page}.gz)
endforeach()
add_custom_target(crt_man_pages ALL DEPENDS ${CRT_MAN_PAGE_FILES})
