// A deterministic fuzz loop: thousands of mutations of valid layouts (byte
// flips, deletions, inserted JSON tokens, odd numbers, repeated keys). Each
// result must be either errors (well-formed, in file order) or a layout that
// keeps every promise of layout.hpp; nothing may crash or take long.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <iterator>
#include <random>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "layout/room_shape.hpp"
#include "layout_test_util.hpp"
#include "math/polygon.hpp"

namespace layout_test {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool in_unit_range(const glm::dvec3& c) { return c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1; }

// The promises of a room's ambient and lights (layout-format.md, "Lights"):
// none but the defaults under "fixed"; under "lights" each light strictly
// inside its room, with the spec's ranges.
void check_lights(const Layout& layout, const Room& room) {
    if (layout.lighting == Lighting::Fixed) {
        EXPECT_EQ(layout.light_depth, kDefaultLightDepth);
        EXPECT_EQ(room.ambient, kDefaultAmbient);
        EXPECT_TRUE(room.lights.empty());
        return;
    }
    EXPECT_TRUE(layout.light_depth >= 0 && layout.light_depth <= kMaxLightDepth);
    EXPECT_TRUE(finite(room.ambient) && room.ambient.x >= 0 && room.ambient.y >= 0 && room.ambient.z >= 0);
    for (const Light& light : room.lights) {
        const double tolerance = 1e-9 * (1.0 + glm::length(light.position));
        for (int a = 0; a < 3; ++a) {
            EXPECT_GT(light.position[a] - room.min[a], tolerance);
            EXPECT_GT(room.max[a] - light.position[a], tolerance);
        }
        if (is_prism(room)) {
            const glm::dvec2 p{light.position.x, light.position.z};
            EXPECT_TRUE(impossible::math::contains(room.floor, p, 0.0));
            EXPECT_GT(impossible::math::distance_to_boundary(room.floor, p), tolerance);
        }
        EXPECT_TRUE(in_unit_range(light.color));
        EXPECT_GT(light.intensity, 0.0);
        EXPECT_GE(light.range, 0.0);
        if (light.spot) {
            EXPECT_NEAR(glm::length(light.spot->direction), 1.0, 1e-12);
            EXPECT_GE(light.spot->inner_deg, 0.0);
            EXPECT_GT(light.spot->outer_deg, light.spot->inner_deg);
            EXPECT_LE(light.spot->outer_deg, 90.0);
        }
        if (light.prop >= 0) {
            ASSERT_LT(std::size_t(light.prop), room.props.size());
            EXPECT_TRUE(std::holds_alternative<GltfProp>(room.props[std::size_t(light.prop)]));
        }
    }
}

// The promises of a prism room (layout-format.md, "Rooms of any shape"): a
// simple floor polygon of at most 1000 corners whose bounding box is the
// room's min/max in x and z.
void check_prism(const Room& room) {
    if (!is_prism(room)) return;
    EXPECT_LE(room.floor.size(), 1000u);
    EXPECT_FALSE(impossible::math::simple_polygon_problem(room.floor).has_value());
    glm::dvec2 lo = room.floor[0], hi = room.floor[0];
    for (const glm::dvec2& c : room.floor) {
        EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y));
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    EXPECT_EQ(lo, glm::dvec2(room.min.x, room.min.z));
    EXPECT_EQ(hi, glm::dvec2(room.max.x, room.max.z));
}

// The promises of a layout's changes (layout.hpp, Change): a condition,
// an earlier `after`, and pairs of doors of one size, each door once.
void check_changes(const Layout& layout) {
    const int portal_count = int(layout.portals.size());
    for (std::size_t i = 0; i < layout.changes.size(); ++i) {
        const Change& change = layout.changes[i];
        EXPECT_FALSE(change.id.empty());
        const ChangeWhen& when = change.when;
        EXPECT_TRUE(when.enter >= 0 || when.after >= 0 || when.time.has_value());
        EXPECT_LT(when.enter, int(layout.rooms.size()));
        EXPECT_LT(when.after, int(i));
        EXPECT_TRUE(!when.time || (std::isfinite(*when.time) && *when.time >= 0.0));
        EXPECT_FALSE(change.pairs.empty());
        std::vector<int> doors;
        for (const auto& pair : change.pairs) {
            for (const int door : pair) {
                ASSERT_GE(door, 0);
                ASSERT_LT(door, portal_count);
                EXPECT_EQ(layout.portals[std::size_t(door)].kind, PortalKind::Door);
                EXPECT_EQ(std::count(doors.begin(), doors.end(), door), 0) << "each door once in a change";
                doors.push_back(door);
            }
            const Portal& a = layout.portals[std::size_t(pair[0])];
            const Portal& b = layout.portals[std::size_t(pair[1])];
            EXPECT_NEAR(a.rect.width, b.rect.width, 1e-6);
            EXPECT_NEAR(a.rect.height, b.rect.height, 1e-6);
        }
    }
}

// The promises of a loaded layout (layout.hpp).
void check_invariants(const Layout& layout) {
    ASSERT_FALSE(layout.rooms.empty());
    const int room_count = int(layout.rooms.size());
    ASSERT_GE(layout.start.room, 0);
    ASSERT_LT(layout.start.room, room_count);
    EXPECT_TRUE(finite(layout.start.position));
    EXPECT_TRUE(std::isfinite(layout.start.yaw_deg));
    if (layout.play_area) {
        EXPECT_LT(layout.play_area->min.x, layout.play_area->max.x);
        EXPECT_LT(layout.play_area->min.y, layout.play_area->max.y);
    }
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const Room& room = layout.rooms[i];
        EXPECT_FALSE(room.id.empty());
        EXPECT_EQ(find_room(layout, room.id), int(i)) << "ids are unique";
        EXPECT_TRUE(finite(room.min) && finite(room.max));
        EXPECT_TRUE(room.max.x > room.min.x && room.max.y > room.min.y && room.max.z > room.min.z);
        check_prism(room);
        EXPECT_EQ(room.face_color.size(), std::size_t(face_count(room)));
        EXPECT_EQ(room.face_texture.size(), std::size_t(face_count(room)));
        for (const glm::dvec3& c : room.face_color) EXPECT_TRUE(in_unit_range(c));
        check_lights(layout, room);
        EXPECT_GE(room.checker, 0.0);
        EXPECT_TRUE(std::isfinite(room.texture_size) && room.texture_size > 0.0);
        for (const auto& image : room.face_texture) {
            if (image == nullptr) continue;
            EXPECT_GE(image->width, 1);
            EXPECT_GE(image->height, 1);
            EXPECT_EQ(image->data.size(), std::size_t(image->width) * std::size_t(image->height) * 4);
        }
        for (const Prop& prop : room.props) {
            if (const auto* box = std::get_if<BoxProp>(&prop)) {
                EXPECT_TRUE(box->max.x > box->min.x && box->max.y > box->min.y && box->max.z > box->min.z);
                EXPECT_TRUE(in_unit_range(box->color));
            } else {
                const auto& model = std::get<GltfProp>(prop);
                EXPECT_FALSE(model.triangles.empty());
                EXPECT_GT(model.scale, 0.0);
                EXPECT_TRUE(finite(model.position));
            }
        }
    }
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const Portal& p = layout.portals[i];
        ASSERT_GE(p.room, 0);
        ASSERT_LT(p.room, room_count);
        EXPECT_NEAR(glm::length(p.rect.normal), 1.0, 1e-12);
        EXPECT_NEAR(glm::length(p.rect.up), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(p.rect.up, p.rect.normal), 0.0, 1e-12);
        EXPECT_TRUE(finite(p.rect.center));
        EXPECT_GT(p.rect.width, 0.0);
        EXPECT_GT(p.rect.height, 0.0);
        EXPECT_GE(p.hole_face, -1);
        EXPECT_LT(p.hole_face, face_count(layout.rooms[std::size_t(p.room)]));
        EXPECT_TRUE(in_unit_range(p.tint));
        EXPECT_TRUE(p.reflectance >= 0.0 && p.reflectance <= 1.0);
        if (p.kind == PortalKind::Door) {
            EXPECT_GT(p.rect.depth, 0.0);
        } else {
            // No box, and a hole in a face of its room (layout-format.md, "Mirrors and windows").
            EXPECT_EQ(p.rect.depth, 0.0);
            EXPECT_GE(p.hole_face, 0);
        }
        if (p.kind == PortalKind::Mirror) {
            EXPECT_EQ(p.target, -1);
            continue;
        }
        ASSERT_GE(p.target, 0);
        ASSERT_LT(p.target, int(layout.portals.size()));
        EXPECT_NE(p.target, int(i));
        const Portal& target = layout.portals[std::size_t(p.target)];
        EXPECT_EQ(target.target, int(i));
        EXPECT_EQ(target.kind, p.kind);
        EXPECT_NEAR(p.rect.width, target.rect.width, 1e-6);
        EXPECT_NEAR(p.rect.height, target.rect.height, 1e-6);
    }
    check_changes(layout);
}

void check_diagnostics(const std::vector<Diagnostic>& list, const std::string& text) {
    int lines = 1;
    for (const char c : text) lines += c == '\n';
    std::pair<int, int> previous{0, 0};
    for (const Diagnostic& d : list) {
        EXPECT_EQ(d.file, "fuzz.json");
        EXPECT_FALSE(d.message.empty());
        for (const char c : d.message) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << d.message;
        if (d.line > 0) {
            EXPECT_LE(d.line, lines);
            EXPECT_GE(d.column, 1);
        }
        const std::pair<int, int> here{d.line, d.column};
        EXPECT_LE(previous, here) << "errors in file order";
        previous = here;
    }
}

class Mutator {
public:
    explicit Mutator(std::uint32_t seed) : random_(seed) {}

    std::string mutate(std::string text) {
        const int count = 1 + pick(3);
        for (int i = 0; i < count && !text.empty(); ++i) {
            switch (pick(6)) {
                case 0: text[pick(text.size())] = static_cast<char>(pick(256)); break;
                case 1: text.erase(pick(text.size()), 1 + pick(16)); break;
                case 2: text.insert(pick(text.size() + 1), kTokens[pick(std::size(kTokens))]); break;
                case 3: replace_number(text); break;
                case 4: repeat_member(text); break;
                default: text = text.substr(0, pick(text.size() + 1)); break;  // truncate
            }
        }
        return text;
    }

private:
    static constexpr const char* kTokens[] = {
        "{",
        "}",
        "[",
        "]",
        ",",
        ":",
        "\"",
        "null",
        "true",
        "false",
        "0",
        "-0",
        "1e308",
        "NaN",
        "\"_c\": 1,",
        "\"id\": \"x\",",
        "\"rooms\": [],",
        "[[[[[[[[",
        "\xFF",
        "\\u0000",
        "\"\\ud800\"",
        "\xEF\xBB\xBF",
        "\"room\": \"annex\",",
        "\"target\": \"hall_east\",",
        "\"up\": [0, 1, 0],",
        "\n",
        "\"kind\": \"mirror\",",
        "\"kind\": \"window\",",
        "\"kind\": \"door\",",
        "\"tint\": [1, 0.5, 0],",
        "\"reflectance\": 0.5,",
        "\"depth\": 0.1,",
        "\"target\": \"hall_mirror\",",
        // Prism rooms (layout-format.md, "Rooms of any shape").
        "\"floor\": [[0, 0], [4, 0], [4, 4], [0, 4]], \"y\": [0, 3],",
        "\"floor\": [[0, 0], [4, 0], [2, 2], [4, 4], [0, 4]],",
        "\"y\": [0, 3],",
        "\"min\": [0, 0, 0],",
        "\"walls\": [0.5, 0.5, 0.5],",
        "\"wall0\": [1, 0, 0],",
        "\"wall23\": [1, 0, 0],",
        "\"-x\": [1, 0, 0],",
        "[2, 2], ",
        "\"lighting\": \"lights\",",
    };
    static constexpr const char* kNumbers[] = {
        "NaN",
        "Infinity",
        "-Infinity",
        "1e308",
        "-1e308",
        "1e400",
        "-0",
        "0",
        "4e-324",
        "1e-9",
        "99999999999999999999999",
        "-1",
        "1.0009",
        "1.002",
        "2",
        "0.5",
        "-2.5",
        "1e5",
        "100001",
    };

    std::mt19937 random_;

    std::size_t pick(std::size_t n) {
        return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
    }

    void replace_number(std::string& text) {
        std::vector<std::size_t> starts;
        for (std::size_t i = 1; i < text.size(); ++i) {
            const char c = text[i];
            const char before = text[i - 1];
            if ((c == '-' || (c >= '0' && c <= '9')) &&
                (before == ' ' || before == '[' || before == ',' || before == ':')) {
                starts.push_back(i);
            }
        }
        if (starts.empty()) return;
        const std::size_t at = starts[pick(starts.size())];
        std::size_t end = at + 1;
        while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                     text[end] == 'e' || text[end] == 'E' || text[end] == '-' || text[end] == '+')) {
            ++end;
        }
        text.replace(at, end - at, kNumbers[pick(std::size(kNumbers))]);
    }

    // Copies `"key": value,` in place, so the key appears twice.
    void repeat_member(std::string& text) {
        const std::size_t quote = text.find('"', pick(text.size()));
        if (quote == std::string::npos) return;
        const std::size_t comma = text.find(',', quote);
        if (comma == std::string::npos) return;
        text.insert(quote, text.substr(quote, comma + 1 - quote));
    }
};

TEST(LayoutFuzzLoop, MutatedLayoutsGiveErrorsOrValidLayouts) {
    const std::vector<std::string> seeds = {
        two_rooms(),
        read_text(kLayoutDir + "/impossible.json"),
        read_text(kLayoutDir + "/props.json"),
        read_text(kLayoutDir + "/mirrors_windows.json"),
        read_text(kLayoutDir + "/lit_rooms.json"),
        read_text(std::string(IMPOSSIBLE_SOURCE_DIR) + "/tests/fuzz/layout_corpus/prism_rooms.json"),
        read_text(std::string(IMPOSSIBLE_SOURCE_DIR) + "/tests/fuzz/layout_corpus/changes.json")};
    for (const std::string& seed : seeds) {
        const LoadResult r = load_layout_text(seed, "fuzz.json", kLayoutDir);
        ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    }
    Mutator mutator(20240611);
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    double slowest = 0.0;
    int valid = 0;
    int invalid = 0;
    const int rounds = 5000;
    for (int round = 0; round < rounds; ++round) {
        for (const std::string& seed : seeds) {
            const std::string text = mutator.mutate(seed);
            const auto before = clock::now();
            const LoadResult r = load_layout_text(text, "fuzz.json", kLayoutDir);
            slowest = std::max(slowest, std::chrono::duration<double>(clock::now() - before).count());
            ASSERT_EQ(r.layout.has_value(), r.errors.empty()) << text;
            check_diagnostics(r.errors, text);
            if (r.layout) {
                ++valid;
                check_invariants(*r.layout);
            } else {
                ++invalid;
            }
            if (::testing::Test::HasFailure()) {
                FAIL() << "round " << round << " input:\n" << text << "\n" << all_messages(r.errors);
            }
        }
    }
    const double total = std::chrono::duration<double>(clock::now() - start).count();
    EXPECT_LT(slowest, 2.0) << "one load took " << slowest << " s";
    EXPECT_LT(total, 60.0);
    // Both outcomes occur: the loop exercises the validator, not only the parser.
    EXPECT_GT(valid, rounds / 20);
    EXPECT_GT(invalid, rounds);
    std::printf("fuzz loop: %d valid, %d invalid, %.2f s, slowest %.3f s\n", valid, invalid, total, slowest);
}

}  // namespace
}  // namespace layout_test
