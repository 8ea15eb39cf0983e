// --technique and --texture-from-level (cli.md, "Portal techniques"): how
// portals are drawn, as the options give it, and how that becomes a frame
// description together with --portal-texture.
#pragma once

#include <optional>
#include <string>

#include "render/frame.hpp"

namespace impossible::cli {

enum class Technique {
    Stencil,  // stencil portals all the way (the default)
    Hybrid,   // stencil above --texture-from-level K, textures from it on
    ZClear,   // the PowerVR scheme: depth 1, doors only
};

// --portal-texture's value: a scale in (0, 4]; InputError naming the option.
double parse_portal_texture(const std::string& name, const std::string& text);

// --technique's value; InputError naming the option if it is none of them.
Technique parse_technique(const std::string& name, const std::string& text);

// The technique (none: as --portal-texture says) and --texture-from-level
// into `frame`, whose portal_texture_scale is --portal-texture's (0 if not
// given): --portal-texture alone is hybrid from level 0, as before
// --technique; hybrid without it has scale 1. UsageError for --portal-texture
// or --texture-from-level with another technique.
void resolve_technique(const std::optional<Technique>& technique, const std::optional<int>& texture_from_level,
                       render::FrameDesc& frame);

}  // namespace impossible::cli
