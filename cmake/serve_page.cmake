# swingsim serve's HTTP library, and its page (src/serve/page/: HTML, CSS, JavaScript) embedded in the program at
# build time, so an installed swingsim serves it without the source tree: the script
# cmake/embed_page.cmake writes each file as a byte array into serve_page_assets.cpp
# (serve/page_assets.h finds them by name). Rebuilt when a page file changes.
# Debian's cpp-httplib is a compiled library built with OpenSSL, zlib and Brotli support:
# code that includes httplib.h takes the same definitions (pkg-config's cflags), or its
# classes would not match the library's.
find_package(PkgConfig REQUIRED)
pkg_check_modules(SWINGSIM_HTTPLIB REQUIRED cpp-httplib)
target_compile_options(swingsim_serve PRIVATE ${SWINGSIM_HTTPLIB_CFLAGS})
target_link_libraries(swingsim_serve PRIVATE ${SWINGSIM_HTTPLIB_LINK_LIBRARIES})
file(GLOB SWINGSIM_PAGE_FILES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/serve/page/*)
set(SWINGSIM_PAGE_CPP ${CMAKE_CURRENT_BINARY_DIR}/generated/serve_page_assets.cpp)
add_custom_command(OUTPUT ${SWINGSIM_PAGE_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUT=${SWINGSIM_PAGE_CPP} -DPAGE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/src/serve/page
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/embed_page.cmake
  DEPENDS ${SWINGSIM_PAGE_FILES} ${CMAKE_CURRENT_SOURCE_DIR}/cmake/embed_page.cmake
  COMMENT "Embedding swingsim serve's page")
target_sources(swingsim_serve PRIVATE ${SWINGSIM_PAGE_CPP})
