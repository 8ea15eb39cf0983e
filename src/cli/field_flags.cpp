#include "cli/field_flags.hpp"

#include <string_view>
#include <utility>

namespace impossible::cli {

namespace {

// Fields whose flag is not "--" and the field with '-' for '_'.
constexpr std::pair<std::string_view, std::string_view> kFlagsByField[] = {
    {"fov_y_deg", "--fov"},
    {"fov", "--fov"},
    {"eye_optics", "--fov-angles"},
    {"cull_portals", "--no-cull"},
    {"no_cull", "--no-cull"},
    {"portal_texture_scale", "--portal-texture"},
    {"portal_texture_level", "--texture-from-level"},
    {"shadow_map_size", "--shadow-size"},
};

}  // namespace

std::string flag_of(const std::string& field) {
    for (const auto& [f, flag] : kFlagsByField)
        if (field == f) return std::string(flag);
    std::string flag = "--" + field;
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

std::string with_flags(const std::string& message) { return session::spell_fields(message, flag_of); }

std::string flag_message(const session::FieldError& error) { return session::command_message(error, flag_of); }

}  // namespace impossible::cli
