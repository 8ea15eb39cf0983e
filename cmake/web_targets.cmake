# The web build's targets (included by CMakeLists.txt under emscripten): the
# page's WebAssembly module, impossible.js + impossible.wasm, with the
# commands that need no window (src/web, and the native commands' files).
file(GLOB web_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/web/*.cpp)
add_executable(impossible_web ${web_sources}
  ${CMAKE_SOURCE_DIR}/src/app/run_command.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_render.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_trace.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_walk.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_walk_command.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_validate.cpp
  ${CMAKE_SOURCE_DIR}/src/app/cmd_compare.cpp)
target_link_libraries(impossible_web PRIVATE impossible_cli impossible_design)
target_compile_options(impossible_web PRIVATE ${warnings})
set_target_properties(impossible_web PROPERTIES OUTPUT_NAME impossible SUFFIX .js)
target_link_options(impossible_web PRIVATE
  -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
  -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=67108864 -sTOTAL_STACK=1048576
  -sMODULARIZE=1 -sEXPORT_NAME=createImpossible -sENVIRONMENT=web,worker,node
  -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,FS,UTF8ToString,GL
  -sEXIT_RUNTIME=0 -sINVOKE_RUN=0
  -sFILESYSTEM=1 -sFORCE_FILESYSTEM=1)

# The page as a folder of static files (web/README.md): build-web/site/.
file(GLOB web_page_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/web/*.html ${CMAKE_SOURCE_DIR}/web/*.js
     ${CMAKE_SOURCE_DIR}/web/*.css)
set(site ${CMAKE_BINARY_DIR}/site)
add_custom_command(TARGET impossible_web POST_BUILD
  COMMAND ${CMAKE_COMMAND} -E make_directory ${site}
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${web_page_files} ${site}
  COMMAND ${CMAKE_COMMAND} -E copy_if_different $<TARGET_FILE_DIR:impossible_web>/impossible.js
          $<TARGET_FILE_DIR:impossible_web>/impossible.wasm ${site}
  VERBATIM)
add_custom_target(web_site ALL DEPENDS impossible_web SOURCES ${web_page_files})
add_custom_command(TARGET web_site POST_BUILD
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${web_page_files} ${site} VERBATIM)
# Emscripten's optimiser (run at link time) finds its node modules (acorn)
# in Debian's folder.
set_property(TARGET impossible_web PROPERTY RULE_LAUNCH_LINK "${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs")
