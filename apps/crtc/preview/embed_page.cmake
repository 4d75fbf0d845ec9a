# Writes the preview page (INPUT) into a C++ header (OUTPUT) as one raw string literal.
file(READ ${INPUT} page)
if(page MATCHES "\\)CRT_PAGE\"")
  message(FATAL_ERROR "${INPUT} contains the raw string's closing delimiter")
endif()
file(WRITE ${OUTPUT} "// Generated from ${INPUT} by embed_page.cmake: do not edit.\n#pragma once\n\n#include <string_view>\n\nnamespace crt::crtc::preview {\n\ninline constexpr std::string_view kPreviewPage = R\"CRT_PAGE(${page})CRT_PAGE\";\n\n} // namespace crt::crtc::preview\n")
