// JPEG markers from ITU-T T.81 (B.1.1.2 to B.1.1.5): SOI, then marker
// segments (FF, the marker, a 2-byte length that counts itself), each scan's
// entropy-coded data after its SOS segment, in which FF is followed by 00 or
// a restart marker RSTn, and EOI. Bytes between segments are skipped as
// stb_image does.
#include "image/jpeg_check.hpp"

#include <bitset>
#include <cstring>
#include <string>
#include <vector>

namespace impossible::image {
namespace {

const char kTruncated[] = "is truncated (it ends before its EOI marker)";
const char kNoFrame[] = "has no frame header (SOF marker) before its image data";

unsigned be16(const unsigned char* p) { return (unsigned(p[0]) << 8) | p[1]; }

// SOF0 to SOF15, but DHT (C4), JPG (C8) and DAC (CC).
bool is_frame_marker(unsigned char m) { return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC; }
bool is_standalone_marker(unsigned char m) { return (m >= 0xD0 && m <= 0xD8) || m == 0x01 || m == 0x00; }

// The tables of a DHT segment's `length` bytes of `data` (T.81, B.2.4.2):
// class 0 or 1, destination 0 to 3, at most 256 codes, each table inside the
// segment. stb_image copies a table's codes into 256 places unchecked.
bool huffman_tables_fit(const unsigned char* data, std::size_t length) {
    for (std::size_t at = 0; at < length;) {
        if (length - at < 17 || (data[at] >> 4) > 1 || (data[at] & 15) > 3) return false;
        std::size_t codes = 0;
        for (int i = 1; i <= 16; ++i) codes += data[at + static_cast<std::size_t>(i)];
        if (codes > 256 || codes > length - at - 17) return false;
        at += 17 + codes;
    }
    return true;
}

// The offset of the FF of the marker that ends the entropy-coded data from
// `at`, or `size` when the data runs to the end.
std::size_t end_of_scan(const unsigned char* bytes, std::size_t size, std::size_t at) {
    while (at < size) {
        const void* ff = std::memchr(bytes + at, 0xFF, size - at);
        if (ff == nullptr) return size;
        const auto p = static_cast<std::size_t>(static_cast<const unsigned char*>(ff) - bytes);
        std::size_t q = p + 1;
        while (q < size && bytes[q] == 0xFF) ++q;  // fill bytes
        if (q < size && bytes[q] != 0x00 && !(bytes[q] >= 0xD0 && bytes[q] <= 0xD7)) return q - 1;
        at = q + 1;
    }
    return size;
}

// What the walk has read so far: the first frame header's size and
// components, the components the scans cover.
struct JpegWalk {
    JpegFrame frame;
    bool have_frame = false;
    int scans = 0;
    std::vector<unsigned char> components;  // the frame's component ids
    std::bitset<256> scanned;               // ids some scan covers
};

// The fault of the whole segment of `marker` whose `length` bytes (its length
// field included) start at `data`, or none; the walk takes its frame header
// and its scan's components.
std::string segment_fault(unsigned char marker, const unsigned char* data, std::size_t length, JpegWalk& walk) {
    if (marker == 0xC4 && !huffman_tables_fit(data + 2, length - 2))
        return "is damaged (a Huffman table, DHT, has more than 256 codes or does not fit its segment)";
    if (is_frame_marker(marker) && !walk.have_frame) {
        if (length < 8 || length < 8 + 3 * std::size_t{data[7]})
            return "is damaged (its frame header, SOF, is too short)";
        walk.frame.height = static_cast<int>(be16(data + 3));
        walk.frame.width = static_cast<int>(be16(data + 5));
        for (std::size_t c = 0; c < data[7]; ++c) walk.components.push_back(data[8 + 3 * c]);
        walk.have_frame = true;
    }
    if (marker == 0xDA) {  // SOS
        if (!walk.have_frame) return kNoFrame;
        if (length < 3 || length < 3 + 2 * std::size_t{data[2]}) return "is damaged (a scan header, SOS, is too short)";
        for (std::size_t c = 0; c < data[2]; ++c) walk.scanned.set(data[3 + 2 * c]);
        ++walk.scans;
    }
    return {};
}

// At EOI: a frame, at least one scan, and every component in some scan
// (stb_image leaves a component no scan covers unwritten).
Result<JpegFrame> walk_result(const JpegWalk& walk) {
    if (!walk.have_frame) return Error{kNoFrame};
    if (walk.scans == 0) return Error{"has no image data (no SOS marker before its EOI marker)"};
    for (const unsigned char id : walk.components) {
        if (!walk.scanned.test(id)) {
            return Error{"has no image data for its component " + std::to_string(id) + " (no scan covers it)"};
        }
    }
    return walk.frame;
}

}  // namespace

Result<JpegFrame> read_jpeg_markers(const unsigned char* bytes, std::size_t size, bool whole) {
    JpegWalk walk;
    std::size_t at = 2;  // past SOI
    for (;;) {
        while (at < size && bytes[at] != 0xFF) ++at;
        while (at < size && bytes[at] == 0xFF) ++at;
        if (at >= size) return Error{kTruncated};
        const unsigned char marker = bytes[at++];
        if (marker == 0xD9) return walk_result(walk);  // EOI
        if (is_standalone_marker(marker)) continue;
        if (size - at < 2) return Error{kTruncated};
        const std::size_t length = be16(bytes + at);
        if (length < 2) return Error{"is damaged (the segment at byte " + std::to_string(at - 2) + " is too short)"};
        if (length > size - at) return Error{kTruncated};
        if (std::string fault = segment_fault(marker, bytes + at, length, walk); !fault.empty()) return Error{fault};
        if (walk.have_frame && !whole) return walk.frame;
        // After SOS, the scan's entropy-coded data up to the next marker.
        at = marker == 0xDA ? end_of_scan(bytes, size, at + length) : at + length;
    }
}

}  // namespace impossible::image
