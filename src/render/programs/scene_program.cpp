#include "render/programs/scene_program.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "base/embedded.hpp"
#include "gl/shader.hpp"
#include "layout/layout.hpp"
#include "render/objects/instance_stream.hpp"
#include "render/programs/gpu_scene.hpp"
#include "shading/shading.hpp"

namespace impossible::render {
namespace {

std::string shading_defines() {
    const glm::dvec3 l = shading::kLightDir;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "#define LIGHT_DIR vec3(%.9g, %.9g, %.9g)\n#define AMBIENT %.9g\n"
                  "#define DIFFUSE %.9g\n#define CHECKER_DARK %.9g\n#define CHECKER_TIE %.9g\n",
                  l.x, l.y, l.z, shading::kAmbient, shading::kDiffuse, shading::kCheckerDark, shading::kCheckerAxisTie);
    return buf;
}

}  // namespace

gl::ShaderSource embedded_shader(GLenum stage, const char* name) {
    return {stage, name, std::string(embedded::find(name))};
}

namespace {

// Which uniforms a variant of the scene's vertex shader and a fragment shader
// uses, so that the GLSL compiler keeps them.
struct SceneVariant {
    const char* fragment = "shaders/scene.frag.glsl";
    bool single_eye = false;             // STEREO_SINGLE_EYE: u_single_eye
    bool materials = false;              // MATERIALS: textures and cut-outs
    bool object_cuts = false;            // OBJECT_CUTS
    bool volumes = false;                // VOLUMES
    bool lights = false;                 // LIGHTS
    bool light_ubo = false;              // LIGHT_UBO
    bool light_naive = false;            // LIGHTS_NAIVE
    bool light_ambient = false;          // LIGHTS_AMBIENT
    bool light_no_direct = false;        // LIGHTS_NO_DIRECT
    bool light_no_paths = false;         // LIGHTS_NO_PATHS
    bool light_direct_blockers = false;  // LIGHTS_DIRECT_BLOCKERS
    bool light_no_shadows = false;       // LIGHTS_NO_SHADOWS
    bool light_plain_points = false;     // LIGHTS_PLAIN_POINTS
    bool light_single_aperture = false;  // LIGHTS_SINGLE_APERTURE
    bool light_cached = false;           // LIGHTS_CACHED
};

std::string variant_defines(const SceneVariant& variant) {
    std::string defines;
    if (variant.object_cuts) defines += "#define OBJECT_CUTS\n";
    // The inside test's tolerance: far below a pixel, above float rounding
    // of positions a few metres from the cell's origin.
    if (variant.volumes) defines += "#define VOLUMES\n#define VOLUME_TOLERANCE 1e-6\n";
    if (variant.lights)
        defines += "#define LIGHTS\n#define LIGHT_MAX_APERTURES " + std::to_string(layout::kMaxLightDepth) + "\n";
    if (variant.lights && variant.light_naive) defines += "#define LIGHTS_NAIVE\n";
    if (variant.lights && variant.light_ambient) defines += "#define LIGHTS_AMBIENT\n";
    if (variant.lights && variant.light_no_direct) defines += "#define LIGHTS_NO_DIRECT\n";
    if (variant.lights && variant.light_no_paths) defines += "#define LIGHTS_NO_PATHS\n";
    if (variant.lights && variant.light_direct_blockers) defines += "#define LIGHTS_DIRECT_BLOCKERS\n";
    if (variant.lights && variant.light_no_shadows) defines += "#define LIGHTS_NO_SHADOWS\n";
    if (variant.lights && variant.light_plain_points) defines += "#define LIGHTS_PLAIN_POINTS\n";
    if (variant.lights && variant.light_single_aperture) defines += "#define LIGHTS_SINGLE_APERTURE\n";
    if (variant.lights && variant.light_cached) defines += "#define LIGHTS_CACHED\n";
    if (variant.lights && variant.light_ubo)
        defines += "#define LIGHT_UBO\n#define LIGHT_UBO_VEC4S " + std::to_string(kLightUboVec4s) + "\n";
    return defines;
}

void find_variant_uniforms(const SceneVariant& variant, gl::UniformLocations& u, SceneProgram& p) {
    if (variant.object_cuts) {
        p.record_base = u.required("u_record_base");
        glProgramUniform1i(p.program.get(), u.required("u_records"), static_cast<GLint>(kInstanceRecordUnit));
    }
    if (variant.volumes) {
        p.to_volume_space = u.required("u_to_volume_space");
        p.volume_first = u.required("u_volume_first");
        p.volume_count = u.required("u_volume_count");
        p.volume_inside = u.required("u_volume_inside");
        // The portal texture's fragment shader shows no tint.
        p.volume_tint = std::string(variant.fragment) == "shaders/scene.frag.glsl" ? u.required("u_volume_tint")
                                                                                   : u.optional("u_volume_tint");
    }
    if (variant.lights) {
        // The ambient-only variant reads only the ambient; the naive one
        // no origin (only the portal tests read it, for their tolerance), nor
        // the variant without paths.
        auto per_image = [&](const char* name) { return variant.light_ambient ? u.optional(name) : u.required(name); };
        p.to_light_space = per_image("u_to_light_space");
        p.light_first = per_image("u_light_first");
        p.light_count =
            variant.light_no_paths || variant.light_cached ? u.optional("u_light_count") : per_image("u_light_count");
        p.light_direct = variant.light_no_direct ? u.optional("u_light_direct") : per_image("u_light_direct");
        p.light_ambient = u.required("u_light_ambient");
        // The one-aperture test has no blocker, so no tolerance either.
        const bool tests_paths =
            (!variant.light_no_paths && !variant.light_single_aperture) || variant.light_direct_blockers;
        p.light_origin = variant.light_naive || !tests_paths || variant.light_cached ? u.optional("u_light_origin")
                                                                                     : per_image("u_light_origin");
        if (variant.light_cached) {
            glProgramUniform1i(p.program.get(), u.required("u_light_cache"), static_cast<GLint>(kLightCacheUnit));
            glProgramUniform1i(p.program.get(), u.required("u_light_edges"), static_cast<GLint>(kLightEdgesUnit));
        }
    }
}

Result<SceneProgram> link_scene_program(const SceneVariant& variant, const std::string& defines) {
    std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/scene.vert.glsl"),
                                            embedded_shader(GL_FRAGMENT_SHADER, variant.fragment)};
    // The volume test, shared by both fragment shaders, goes before the
    // fragment shader's own text (whose lines keep their numbers).
    // So do the props' shadows and the lit colour (the LIGHTS variants only).
    stages[1].text = std::string(embedded::find("shaders/volume_clip.frag.glsl")) + "\n" +
                     std::string(embedded::find("shaders/shadow_lookup.frag.glsl")) + "\n" +
                     std::string(embedded::find("shaders/lighting.frag.glsl")) + "\n#line 1\n" + stages[1].text;
    Result<gl::Program> built = gl::build_program(stages, defines + variant_defines(variant));
    if (!built) return built;
    SceneProgram p;
    p.program = std::move(*built);
    const GLuint name = p.program.get();
    const bool scene_fragment = std::string(variant.fragment) == "shaders/scene.frag.glsl";
    gl::UniformLocations u(name, gl::program_name(stages));
    p.view_proj = u.required("u_view_proj");
    p.eye_rect = u.required("u_eye_rect");
    p.clip_plane = u.required("u_clip_plane");
    // Only the checker pattern reads it: a fragment shader without one (the
    // portal texture's) leaves it to be optimised out.
    p.checker_offset = scene_fragment ? u.required("u_checker_offset") : u.optional("u_checker_offset");
    if (variant.single_eye) p.single_eye = u.required("u_single_eye");
    if (scene_fragment) {
        p.cell_id = u.required("u_cell_id");
        p.unshaded = u.required("u_unshaded");
        p.exposure = u.required("u_exposure");
        glProgramUniform1f(name, p.exposure, 1.0f);
    } else {
        p.target_size = u.required("u_target_size");
        glProgramUniform1i(name, u.required("u_color_texture"), 0);
        glProgramUniform1i(name, u.required("u_id_texture"), 1);
    }
    if (variant.materials) {
        p.textured = u.required("u_textured");
        p.alpha_cutoff = u.required("u_alpha_cutoff");
        p.mip_level0 = u.required("u_mip_level0");
        glProgramUniform1i(name, u.required("u_texture"), static_cast<GLint>(kSceneTextureUnit));
        glProgramUniform1f(name, p.alpha_cutoff, -1.0f);
    }
    find_variant_uniforms(variant, u, p);
    if (Result<void> all = u.check(); !all) return all;
    return p;
}

}  // namespace

Result<SceneProgram> build_scene_program(StereoMode mode, bool materials) {
    return build_scene_variant(mode, materials ? kMaterials : 0u);
}

Result<SceneProgram> build_scene_variant(StereoMode mode, unsigned flags) {
    std::string defines = shading_defines();
    if (flags & kMaterials) defines += "#define MATERIALS\n";
    if (mode == StereoMode::ViewportIndex) defines += "#define STEREO_VIEWPORT_INDEX\n";
    if (mode == StereoMode::TwoPass) defines += "#define STEREO_SINGLE_EYE\n";
    SceneVariant variant;
    variant.single_eye = mode == StereoMode::TwoPass;
    variant.materials = (flags & kMaterials) != 0;
    variant.object_cuts = (flags & kObjectCuts) != 0;
    variant.volumes = (flags & kVolumes) != 0;
    variant.lights = (flags & kLights) != 0;
    variant.light_ubo = (flags & kLightsUbo) != 0;
    variant.light_naive = (flags & kLightsNaive) != 0;
    variant.light_ambient = (flags & kLightsAmbient) != 0;
    variant.light_no_direct = (flags & kLightsNoDirect) != 0;
    variant.light_no_paths = (flags & kLightsNoPaths) != 0;
    variant.light_direct_blockers = (flags & kLightsDirectBlockers) != 0;
    variant.light_no_shadows = (flags & kLightsNoShadows) != 0;
    variant.light_plain_points = (flags & kLightsPlainPoints) != 0;
    variant.light_single_aperture = (flags & kLightsSingleAperture) != 0;
    variant.light_cached = (flags & kLightsCached) != 0;
    return link_scene_program(variant, defines);
}

Result<SceneProgram> build_portal_texture_program(bool volumes) {
    SceneVariant variant;
    variant.fragment = "shaders/portal_texture.frag.glsl";
    variant.volumes = volumes;
    return link_scene_program(variant, "");
}

Result<ClearDepthProgram> build_clear_depth_program() {
    const std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
                                                  embedded_shader(GL_FRAGMENT_SHADER, "shaders/clear_depth.frag.glsl")};
    Result<gl::Program> built = gl::build_program(stages, "");
    if (!built) return built;
    ClearDepthProgram out;
    out.program = std::move(*built);
    gl::UniformLocations u(out.program.get(), gl::program_name(stages));
    out.far_depth = u.required("u_far_depth");
    out.color = u.required("u_color");
    out.eye_quads = u.required("u_eye_quads");
    out.rects = u.required("u_rects");
    if (Result<void> all = u.check(); !all) return all;
    return out;
}

Result<WindowBlendProgram> build_window_blend_program(bool multisample) {
    const std::vector<gl::ShaderSource> stages = {
        embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
        embedded_shader(GL_FRAGMENT_SHADER, "shaders/window_blend.frag.glsl")};
    Result<gl::Program> built = gl::build_program(stages, multisample ? "#define SAVED_MULTISAMPLE\n" : "");
    if (!built) return built;
    WindowBlendProgram out;
    out.program = std::move(*built);
    const GLuint name = out.program.get();
    gl::UniformLocations u(name, gl::program_name(stages));
    out.use_saved = u.required("u_use_saved");
    out.scale = u.required("u_scale");
    out.constant = u.required("u_constant");
    glProgramUniform1i(name, u.required("u_saved"), 0);
    if (Result<void> all = u.check(); !all) return all;
    return out;
}

Result<gl::Program> build_id_resolve_program(int samples) {
    const std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
                                                  embedded_shader(GL_FRAGMENT_SHADER, "shaders/id_resolve.frag.glsl")};
    Result<gl::Program> built = gl::build_program(stages, "#define SAMPLES " + std::to_string(samples) + "\n");
    if (!built) return built;
    gl::UniformLocations u(built->get(), gl::program_name(stages));
    glProgramUniform1i(built->get(), u.required("u_ids"), 0);
    if (Result<void> all = u.check(); !all) return all;
    return built;
}

}  // namespace impossible::render
