# The browser viewer (viewer/, docs/viewer.md): its page template is bundled
# by node from viewer/src and linked into the bestiary binary, so `bestiary
# show` needs nothing at run time; `bestiary render` runs viewer/render.mjs
# with node, Chromium and ffmpeg. Needs node and viewer/node_modules
# (./scripts/setup runs `npm ci` in viewer/).

set(BX_VIEWER_DIR ${CMAKE_SOURCE_DIR}/viewer)
find_program(NODE_EXECUTABLE node)
if(NOT NODE_EXECUTABLE OR NOT EXISTS ${BX_VIEWER_DIR}/node_modules/esbuild/package.json)
  message(FATAL_ERROR "The viewer needs node and viewer/node_modules: run ./scripts/setup "
                      "(or `npm ci` in viewer/ with Debian's nodejs and npm)")
endif()

# viewer/src -> the page template as C++ (bx::kViewerPage), rebuilt when a source changes
file(GLOB BX_VIEWER_SRC CONFIGURE_DEPENDS ${BX_VIEWER_DIR}/src/*)
set(BX_VIEWER_OUT ${CMAKE_BINARY_DIR}/viewer)
add_custom_command(
  OUTPUT ${BX_VIEWER_OUT}/viewer.html ${BX_VIEWER_OUT}/viewer_page.cpp
  COMMAND ${NODE_EXECUTABLE} ${BX_VIEWER_DIR}/build.mjs
          --out ${BX_VIEWER_OUT}/viewer.html --cpp ${BX_VIEWER_OUT}/viewer_page.cpp
  DEPENDS ${BX_VIEWER_SRC} ${BX_VIEWER_DIR}/build.mjs ${BX_VIEWER_DIR}/package-lock.json
  WORKING_DIRECTORY ${BX_VIEWER_DIR}
  COMMENT "Bundling the viewer page (three.js + viewer/src)"
  VERBATIM)
add_library(bx_viewer_page STATIC ${BX_VIEWER_OUT}/viewer_page.cpp)
target_link_libraries(bx_io PUBLIC bx_viewer_page)

# render finds render.mjs and node_modules here unless $BESTIARY_VIEWER_DIR says otherwise
target_compile_definitions(bestiary PRIVATE BESTIARY_VIEWER_DIR="${BX_VIEWER_DIR}")

if(BESTIARY_TESTS)
  # the viewer's JavaScript, in node
  file(GLOB BX_VIEWER_TESTS CONFIGURE_DEPENDS ${BX_VIEWER_DIR}/test/*.test.mjs)
  add_test(NAME viewer_js COMMAND ${NODE_EXECUTABLE} --test ${BX_VIEWER_TESTS}
           WORKING_DIRECTORY ${BX_VIEWER_DIR})
  # the end-to-end tests (tests/viewer) keep their screenshots in the build folder
  if(TARGET test_viewer)
    target_compile_definitions(test_viewer PRIVATE BESTIARY_BUILD_DIR="${CMAKE_BINARY_DIR}")
  endif()
endif()
