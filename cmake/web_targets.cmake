# The web build's targets (included by CMakeLists.txt under emscripten): the
# page's WebAssembly module, impossible.js + impossible.wasm, with the
# commands that need no window (src/web, and the native commands' files).
# The public API and its Python module are native only.
set_target_properties(impossible_api PROPERTIES EXCLUDE_FROM_ALL ON)
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

# The core's unit tests under node (docs/web.md, "Tests"): the same test
# files as the native programs (tests/), compiled by emscripten against
# Debian's GoogleTest sources, reading the repository's files through node
# (NODERAWFS). Not in the default build (the test command's budget): CI's
# long stage builds them (target web_unit_tests) and tests/web.cmake runs
# them there.
set(gtest_source /usr/src/googletest/googletest)
add_library(web_gtest STATIC EXCLUDE_FROM_ALL ${gtest_source}/src/gtest-all.cc ${gtest_source}/src/gtest_main.cc)
target_include_directories(web_gtest SYSTEM PUBLIC ${gtest_source}/include PRIVATE ${gtest_source})
set_target_properties(web_gtest PROPERTIES UNITY_BUILD OFF)
function(web_unit_tests name dir)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/${dir}/*.cpp)
  # Not the tests that run other programs (node cannot start processes).
  list(FILTER srcs EXCLUDE REGEX ".*/(chair_glb|gallery_assets)_test\\.cpp$")
  add_executable(${name} EXCLUDE_FROM_ALL ${srcs})
  set_target_properties(${name} PROPERTIES UNITY_BUILD_BATCH_SIZE 12 SUFFIX .js)
  target_link_libraries(${name} PRIVATE ${ARGN} web_gtest)
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests)
  target_compile_options(${name} PRIVATE -O1)  # build time: nothing timed runs here
  target_compile_definitions(${name} PRIVATE IMPOSSIBLE_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    IMPOSSIBLE_TEST_DATA="${CMAKE_SOURCE_DIR}/tests/data" IMPOSSIBLE_BINARY="" IMPOSSIBLE_SANITIZED=0)
  # -O0 at link: no wasm-opt pass (build time; the tests take a second).
  target_link_options(${name} PRIVATE -O0 -sNODERAWFS=1 -sENVIRONMENT=node -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1)
  set_property(TARGET ${name} PROPERTY RULE_LAUNCH_LINK "${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs")
endfunction()
web_unit_tests(web_unit_base base impossible_base nlohmann_json::nlohmann_json)
web_unit_tests(web_unit_math math impossible_math)
web_unit_tests(web_unit_layout layout impossible_layout)
web_unit_tests(web_unit_walk walk impossible_walk)
add_custom_target(web_unit_tests DEPENDS web_unit_base web_unit_math web_unit_layout web_unit_walk)
