// The GLSL each profile compiles: the native build's "#version 450 core", or
// the web build's "#version 300 es" (WebGL 2) with its precision and
// extension lines. ES 3.0 has no layout(binding = N): the web profile strips
// those and binds the samplers and uniform blocks by name after linking.
#pragma once

#include <string>
#include <vector>

namespace impossible::gl {

// A sampler or uniform block and the unit or binding point its source named.
struct NamedBinding {
    std::string name;
    int binding = 0;
    bool block = false;  // a uniform block (else a sampler)
};

// The text a stage compiles: the profile's first lines, `defines`, then
// `text`; on the web profile with its layout bindings moved to `bindings`.
std::string profile_source(const std::string& defines, const std::string& text, std::vector<NamedBinding>& bindings);

// Moves each "binding = N" out of `text`'s layout qualifiers into `bindings`
// (a layout left empty goes too). Pure text: unit-tested natively.
std::string strip_layout_bindings(const std::string& text, std::vector<NamedBinding>& bindings);

}  // namespace impossible::gl
