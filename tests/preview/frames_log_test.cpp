// frames.jsonl without a window: the line's bytes, and numbers written by
// nlohmann's JSON exactly as `walk` writes them (impossible::format_number).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>
#include "base/format.hpp"
#include "common/temp_dir.hpp"

#include "preview/frames_log.hpp"

namespace impossible::preview {
namespace {

// The line as the preview wrote it by hand before it used nlohmann's JSON:
// the bytes frame_line must keep.
std::string numbers_by_hand(std::initializer_list<double> values) {
    std::string s = "[";
    for (double v : values) s += (s.size() > 1 ? "," : "") + impossible::format_number(v);
    return s + "]";
}

std::string line_by_hand(const FrameRecord& r) {
    auto pose = [](const math::HeadPose& p) {
        return numbers_by_hand({p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg});
    };
    std::string line = "{\"frame\":" + std::to_string(r.frame) + ",\"room\":\"" + r.room + "\",\"teleports\":[";
    for (std::size_t k = 0; k < r.teleports.size(); ++k) line += (k ? ",\"" : "\"") + r.teleports[k] + "\"";
    const math::dvec3 p = r.position, f = r.forward;
    return line + "],\"pose\":" + pose(r.pose) + ",\"physical\":" + pose(r.physical) +
           ",\"position\":" + numbers_by_hand({p.x, p.y, p.z}) + ",\"forward\":" + numbers_by_hand({f.x, f.y, f.z}) +
           ",\"eye_size\":[" + std::to_string(r.eye_width) + "," + std::to_string(r.eye_height) + "]}\n";
}

TEST(PreviewFramesLog, NumbersAsWalkWritesThem) {
    for (double v : {0.0, -0.0, 1.0, -3.0, 1.6, 0.1 + 0.2, 1e-7, 1e21, 1e5, 5e-4, 551.665212202747})
        EXPECT_EQ(dump_json(v), impossible::format_number(v)) << v;
    // Every digit of random metres and degrees, round numbers as typed in
    // path files, -0, and portal ids.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto any = [&](int k) {
        switch (k % 4) {
            case 0: return u(rng) * std::pow(10.0, (k % 24) - 18);
            case 1: return std::round(u(rng) * 2000.0) / 10.0;
            case 2: return std::round(u(rng) * 2e6);
            default: return k % 8 == 3 ? -0.0 : u(rng) * 360.0;
        }
    };
    for (int k = 0; k < 3000; ++k) {
        FrameRecord r;
        r.frame = k;
        r.room = "room_" + std::to_string(k % 5);
        for (int t = 0; t < k % 3; ++t) r.teleports.push_back("door-" + std::to_string(t));
        r.pose = {{any(k), any(k + 1), any(k + 2)}, any(k + 3), any(k + 5), any(k + 7)};
        r.physical = {{any(k + 1), any(k + 2), any(k + 3)}, any(k), any(k + 2), any(k + 6)};
        r.position = {any(k + 2), any(k + 3), any(k + 4)};
        r.forward = {any(k + 3), any(k + 4), any(k + 5)};
        r.eye_width = 1 + k % 4096;
        r.eye_height = 1 + k % 777;
        const std::string line = frame_line(r);
        ASSERT_EQ(line, line_by_hand(r));
        ASSERT_EQ(nlohmann::json::parse(line)["position"][1].get<double>(), r.position.y);
    }
}

TEST(PreviewFramesLog, LineHasTheFieldsInOrder) {
    FrameRecord r;
    r.frame = 3;
    r.room = "hall";
    r.teleports = {"a", "b"};
    r.pose = {{0.5, 1.6, -0.0}, 90.0, -5.0, 0.0};
    r.physical = {{1.0, 1.6, 2.0}, 0.0, 0.0, 0.0};
    r.position = {0.1 + 0.2, 1.6, 2.0};
    r.forward = {0.0, 0.0, -1.0};
    r.eye_width = 160;
    r.eye_height = 120;
    EXPECT_EQ(frame_line(r),
              "{\"frame\":3,\"room\":\"hall\",\"teleports\":[\"a\",\"b\"],\"pose\":[0.5,1.6,0,90,-5,0],"
              "\"physical\":[1,1.6,2,0,0,0],\"position\":[0.30000000000000004,1.6,2],\"forward\":[0,0,-1],"
              "\"eye_size\":[160,120]}\n");
    r.teleports.clear();
    EXPECT_NE(frame_line(r).find("\"teleports\":[],"), std::string::npos);
    // A frame that made changes ends with them, as `walk`'s line does.
    r.changes = {"swap"};
    const std::string line = frame_line(r);
    EXPECT_EQ(line.substr(line.size() - 41), "\"eye_size\":[160,120],\"changes\":[\"swap\"]}\n");
}

TEST(PreviewFramesLog, SavesNumberedFilesAndTheLog) {
    const test::TempDir dir("preview-frames");
    EXPECT_EQ(open_frame_files(std::nullopt).dir, std::filesystem::path("."));
    FrameFiles files = open_frame_files((dir / "shots").string());
    EXPECT_TRUE(files.every_frame);
    EXPECT_EQ(numbered(files.dir, "frame", 7, "-ids.png"), (dir / "shots" / "frame-0007-ids.png").string());
    image::Image image;
    image.width = 2;
    image.height = 1;
    image.rgb.assign(6, 128);
    image.ids.assign(2, 1);
    FrameRecord r;
    r.frame = 7;
    r.room = "r";
    save_frame(files, image, r);
    EXPECT_TRUE(std::filesystem::exists(dir / "shots" / "frame-0007.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "shots" / "frame-0007-ids.png"));
    const std::vector<std::uint8_t> rgb(6, 9);
    EXPECT_EQ(save_screenshot(files, 2, 1, rgb), (dir / "shots" / "screenshot-0000.png").string());
    EXPECT_EQ(save_screenshot(files, 2, 1, rgb), (dir / "shots" / "screenshot-0001.png").string());
    std::ifstream log(dir / "shots" / "frames.jsonl", std::ios::binary);
    std::stringstream text;
    text << log.rdbuf();
    EXPECT_EQ(text.str(), frame_line(r));
}

}  // namespace
}  // namespace impossible::preview
