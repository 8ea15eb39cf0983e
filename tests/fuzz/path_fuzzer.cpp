// libFuzzer entry point for the path-file parser of `walk`, `preview --path`,
// `bench --path` and `plan --path` (built with -DIMPOSSIBLE_FUZZER=ON and
// clang). Each input is read four times, as a stream (read_path_stream,
// read_path_frames_stream) and as a file of its own folder (read_path_file,
// read_path_frames_file, through the size-limited reader), and must give
// poses or one error line, never a crash, hang or leak. The checks:
//   - an error is one line without control characters and valid UTF-8
//     (fuzz_check.hpp) starting "fuzz.txt:LINE: " (stream) or with the file's
//     path (file), LINE between 1 and the input's lines + 1, or, for an
//     error about the whole file (no poses, UTF-16/32 text), no line;
//   - every pose (head or hand) is six finite numbers within +-1e6;
//   - the four readers agree: the same heads (the frames readers' heads are
//     the heads readers' poses), the same hands, the same message after the
//     name, and a file of no poses is the error "holds no poses" for all;
//   - frames printed with 17 digits (6 numbers a line, or 18 with hands)
//     read back bit for bit.
// Seeds: tests/fuzz/path_corpus.
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_check.hpp"
#include "layout/path_file.hpp"

namespace {

using impossible::layout::PathFile;
using impossible::layout::PathFrame;
using impossible::layout::PathFrames;
using impossible::math::HeadPose;

using impossible::fuzz::require;
using impossible::fuzz::require_clean_line;

// The file the input is written to, kept open in a folder of its own. It is
// rewritten in place (pwrite, then ftruncate to the new length): opening it
// with O_TRUNC each time frees its block, which costs a millisecond and more
// on ext4 mounted with `discard`, ten times the rest of a run.
struct InputFile {
    std::string path;
    int fd = -1;
};

const InputFile& input_file() {
    static const InputFile file = [] {
        char name[] = "/tmp/path_fuzzer_XXXXXX";
        if (::mkdtemp(name) == nullptr) std::abort();
        InputFile f{std::string(name) + "/path.txt"};
        f.fd = ::open(f.path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
        if (f.fd < 0) std::abort();
        return f;
    }();
    return file;
}

void write_input(const std::string& text) {
    const InputFile& f = input_file();
    require(::pwrite(f.fd, text.data(), text.size(), 0) == static_cast<::ssize_t>(text.size()), "write the input");
    require(::ftruncate(f.fd, static_cast<::off_t>(text.size())) == 0, "write the input");
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_pose(const HeadPose& a, const HeadPose& b) {
    return same_bits(a.position.x, b.position.x) && same_bits(a.position.y, b.position.y) &&
           same_bits(a.position.z, b.position.z) && same_bits(a.yaw_deg, b.yaw_deg) &&
           same_bits(a.pitch_deg, b.pitch_deg) && same_bits(a.roll_deg, b.roll_deg);
}

bool same_poses(const std::vector<HeadPose>& a, const std::vector<HeadPose>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same_pose(a[i], b[i])) return false;
    return true;
}

bool same_frames(const std::vector<PathFrame>& a, const std::vector<PathFrame>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!same_pose(a[i].head, b[i].head) || a[i].hands.has_value() != b[i].hands.has_value()) return false;
        if (a[i].hands &&
            (!same_pose((*a[i].hands)[0], (*b[i].hands)[0]) || !same_pose((*a[i].hands)[1], (*b[i].hands)[1])))
            return false;
    }
    return true;
}

// The heads of frames, to compare with the heads readers.
std::vector<HeadPose> heads_of(const std::vector<PathFrame>& frames) {
    std::vector<HeadPose> heads;
    for (const PathFrame& f : frames) heads.push_back(f.head);
    return heads;
}

void require_finite(const HeadPose& p) {
    for (double v : {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg})
        require(std::isfinite(v) && std::abs(v) <= 1e6, "every pose finite, within 1e6");
}

// A pose as six numbers with 17 digits, after `separator`.
void print_pose(std::string& out, const HeadPose& p, const char* separator) {
    char line[256];
    std::snprintf(line, sizeof line, "%s%.17g %.17g %.17g\t%.17g %.17g %.17g", separator, p.position.x, p.position.y,
                  p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg);
    out += line;
}

// Errors about the whole file rather than one line: no poses at all, or text
// in a wide encoding (caught on the first line's byte order mark).
bool whole_file_error(const std::string& message) {
    return message == "the path file holds no poses" ||
           (message.rfind("is UTF-", 0) == 0 && message.find(" text; save it as UTF-8 or ASCII") != std::string::npos);
}

// "NAME:LINE: message" with LINE in [1, max_line], or "NAME: message" for an
// error about the whole file; returns the message.
std::string message_after(const std::string& error, const std::string& name, std::size_t max_line) {
    require_clean_line(error);
    require(error.compare(0, name.size() + 1, name + ":") == 0, "an error starts with the name");
    if (error.compare(name.size() + 1, 1, " ") == 0) {
        const std::string message = error.substr(name.size() + 2);
        require(whole_file_error(message), "an error without a line is about the whole file");
        return message;
    }
    std::size_t i = name.size() + 1;
    std::size_t line = 0;
    const std::size_t digits = i;
    while (i < error.size() && error[i] >= '0' && error[i] <= '9' && i - digits < 12)
        line = line * 10 + static_cast<std::size_t>(error[i++] - '0');
    require(i > digits && line >= 1 && line <= max_line, "an error names a line of the input");
    require(error.compare(i, 2, ": ") == 0 && error.size() > i + 2, "an error is NAME:LINE: message");
    return error.substr(i + 2);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::size_t lines = 1;
    for (char c : text) lines += c == '\n';

    std::istringstream in(text);
    const PathFile stream = impossible::layout::read_path_stream(in, "fuzz.txt");
    std::istringstream frames_in(text);
    const PathFrames frames = impossible::layout::read_path_frames_stream(frames_in, "fuzz.txt");

    write_input(text);
    const std::string& path = input_file().path;
    const PathFile file = impossible::layout::read_path_file(path);
    const PathFrames frames_file = impossible::layout::read_path_frames_file(path);

    if (!stream) {
        const std::string message = message_after(stream.error(), "fuzz.txt", lines);
        require(!file && !frames && !frames_file, "every reader fails where the stream reader does");
        require(message_after(file.error(), path, lines) == message, "both readers give the same message");
        require(frames.error() == stream.error(), "the frames reader gives the same message");
        require(frames_file.error() == file.error(), "the frames file reader gives the same message");
        return 0;
    }
    require(frames && frames_file, "every reader reads what the stream reader reads");
    for (const PathFrame& f : *frames) {
        require_finite(f.head);
        if (f.hands) {
            require_finite((*f.hands)[0]);
            require_finite((*f.hands)[1]);
        }
    }
    require(!stream->empty() && stream->size() <= lines, "at least one pose, at most a pose a line");
    require(file && same_poses(*file, *stream), "both readers give the same poses");
    require(same_poses(heads_of(*frames), *stream), "the frames reader's heads are the poses");
    require(same_frames(*frames_file, *frames), "both frames readers give the same frames");

    std::string printed = "# printed again\n";
    for (const PathFrame& f : *frames) {
        print_pose(printed, f.head, "");
        if (f.hands) {
            print_pose(printed, (*f.hands)[0], " ");
            print_pose(printed, (*f.hands)[1], "\t ");
        }
        printed += "\r\n";
    }
    std::istringstream again(printed);
    const PathFrames reread = impossible::layout::read_path_frames_stream(again, "again.txt");
    require(reread && same_frames(*reread, *frames), "frames printed with 17 digits read back bit for bit");
    return 0;
}
