# The web build's dependencies (included by CMakeLists.txt under emscripten):
# Debian's header-only libraries, seen through a folder of links so that
# /usr/include's C library never meets emscripten's, as the targets the
# native build's find_package calls define.
set(web_include ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${web_include})
foreach(entry glm nlohmann stb boost tiny_gltf.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "/usr/include/${entry} is missing: run scripts/setup.sh")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${web_include}/${entry} SYMBOLIC)
endforeach()

function(web_header_target name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  target_include_directories(${name} SYSTEM INTERFACE ${web_include})
endfunction()
web_header_target(glm::glm)
web_header_target(nlohmann_json::nlohmann_json)
web_header_target(TinyGLTF::TinyGLTF)
web_header_target(PkgConfig::STB)
web_header_target(Boost::headers)
# No GLU (the web build has its own tessellator) and no threads (the page
# runs on one).
add_library(PkgConfig::GLU INTERFACE IMPORTED GLOBAL)
add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)


# stb's headers are included by their names alone, as Debian's stb.pc says.
target_include_directories(PkgConfig::STB SYSTEM INTERFACE ${web_include}/stb)
target_include_directories(TinyGLTF::TinyGLTF SYSTEM INTERFACE ${web_include}/stb)
# Errors travel as C++ exceptions (docs/architecture.md): WebAssembly's own.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
