#include "cli/technique_options.hpp"

#include "cli/args.hpp"
#include "cli/errors.hpp"
#include "math/view_limits.hpp"

namespace impossible::cli {

double parse_portal_texture(const std::string& name, const std::string& text) {
    const double scale = parse_number(name, text);
    const double most = math::limits::kMaxPortalTextureScale;
    if (!(scale > 0.0 && scale <= most))
        throw InputError(name + ": " + text + " is not in (0, " + format_number(most) + "]");
    return scale;
}

Technique parse_technique(const std::string& name, const std::string& text) {
    if (text == "stencil") return Technique::Stencil;
    if (text == "hybrid") return Technique::Hybrid;
    if (text == "z-clear") return Technique::ZClear;
    throw InputError(name + ": '" + text + "' is not stencil, hybrid or z-clear");
}

void resolve_technique(const std::optional<Technique>& technique, const std::optional<int>& texture_from_level,
                       render::FrameDesc& frame) {
    const bool scale = frame.portal_texture_scale > 0.0;
    const Technique t = technique.value_or(scale ? Technique::Hybrid : Technique::Stencil);
    if (t != Technique::Hybrid && scale)
        throw UsageError("--portal-texture needs --technique hybrid (the scale of its textures)");
    if (t != Technique::Hybrid && texture_from_level) throw UsageError("--texture-from-level needs --technique hybrid");
    if (t == Technique::Hybrid) {
        if (!scale) frame.portal_texture_scale = 1.0;
        frame.portal_texture_level = texture_from_level.value_or(0);
    }
    frame.z_clear = t == Technique::ZClear;
}

}  // namespace impossible::cli
