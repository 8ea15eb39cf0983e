# The web build's browser tests (web/tests, node's test runner driving
# Debian's chromium through playwright-core; docs/web.md): against the native
# build's trace and walk. scripts/test.sh builds the web build first
# (scripts/web-build.sh); the sanitizer build has none of them. Each smoke
# runs in the README's test command, each full set in the long stage; one
# browser at a time.
find_program(NODE_EXECUTABLE node)
if(NODE_EXECUTABLE AND NOT IMPOSSIBLE_SANITIZE)
  set(web_tests ${CMAKE_SOURCE_DIR}/web/tests)
  function(impossible_web_test name file labels)
    add_test(NAME ${name} COMMAND ${NODE_EXECUTABLE} --test --test-reporter=spec ${web_tests}/${file})
    set_tests_properties(${name} PROPERTIES LABELS "${labels}" TIMEOUT 900 RESOURCE_LOCK web_browser
                         ENVIRONMENT "IMPOSSIBLE_BIN=$<TARGET_FILE:impossible>;${ARGN}")
  endfunction()
  # Six layouts (mirrors, lights and shadows, a volume, windows, textures)
  # and three hard poses; the full set is every layout and eleven poses.
  impossible_web_test(web_render_smoke render.test.mjs web
    "IMPOSSIBLE_WEB_CASES=^(default.json|mirror_hall.json|lamp_hall.json|scanner_lab.json|window_pair.json|gallery.json|default: one eye|default: canted|sliding_box)")
  impossible_web_test(web_render render.test.mjs "web;long")
  impossible_web_test(web_xr_smoke xr.test.mjs web "IMPOSSIBLE_WEB_SMOKE=1")
  impossible_web_test(web_xr xr.test.mjs "web;long")
  impossible_web_test(web_page page.test.mjs web)
  # The core's unit tests compiled by emscripten, run under node: the same
  # files as unit_base, unit_math, unit_layout and unit_walk. Node cannot make
  # FIFOs or devices, so the test of a glTF buffer that is one stays native.
  # In the long stage, which builds them first (.ci/run: web_unit_tests).
  foreach(module base math layout walk)
    add_test(NAME web_unit_${module}
             COMMAND ${NODE_EXECUTABLE} --no-experimental-fetch ${CMAKE_SOURCE_DIR}/build-web/web_unit_${module}.js
                     --gtest_filter=-GltfHardening.ABufferFileThatIsNotARegularFileSaysWhatItIs)
    set_tests_properties(web_unit_${module} PROPERTIES LABELS "web;long" TIMEOUT 300)
  endforeach()
  impossible_web_test(web_cli cli.test.mjs web)
endif()
