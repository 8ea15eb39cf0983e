// Hand-made baseline JPEG files for attacks on the image decoder: one grey
// component, 8-bit, every quantiser step 1, and Huffman tables of a single
// one-bit code each (DC: difference 0; AC: end of block), so each 8 × 8 block
// is the two bits "00" and the picture is a uniform grey of 128.
#pragma once

#include <string>

namespace impossible::hostile {

// A marker segment: FF, the marker, the length (2 bytes, itself included), the data.
inline std::string jpeg_segment(unsigned char marker, const std::string& data) {
    const std::size_t n = data.size() + 2;
    return std::string{char(0xFF), char(marker), char(n >> 8), char(n & 0xFF)} + data;
}

// SOI, DQT, SOF0, DHT (DC), DHT (AC), [DRI], SOS, the scan, EOI. With a
// `restart_interval` the file has a DRI segment but no RST markers in its
// scan, as if they had been cut out; with more `components` (ids 1, 2, ...)
// its one scan still covers only the first.
inline std::string jpeg_file(int width, int height, int restart_interval = 0, int components = 1) {
    const auto be16 = [](int v) { return std::string{char((v >> 8) & 0xFF), char(v & 0xFF)}; };
    std::string out = "\xFF\xD8";
    out += jpeg_segment(0xDB, std::string(1, '\0') + std::string(64, '\x01'));
    std::string frame = std::string(1, '\x08') + be16(height) + be16(width) + char(components);
    for (int c = 1; c <= components; ++c) frame += std::string{char(c), 0x11, 0};
    out += jpeg_segment(0xC0, frame);
    const std::string one_code = std::string(1, '\x01') + std::string(15, '\0') + std::string(1, '\0');
    out += jpeg_segment(0xC4, std::string(1, '\x00') + one_code);
    out += jpeg_segment(0xC4, std::string(1, '\x10') + one_code);
    if (restart_interval > 0) out += jpeg_segment(0xDD, be16(restart_interval));
    out += jpeg_segment(0xDA, std::string("\x01\x01\x00\x00\x3F\x00", 6));
    const int blocks = ((width + 7) / 8) * ((height + 7) / 8);
    const int bits = 2 * blocks;  // all zero, padded with one bits to a whole byte
    std::string scan(static_cast<std::size_t>((bits + 7) / 8), '\0');
    if (bits % 8 != 0) scan.back() = char((1 << (8 - bits % 8)) - 1);
    return out + scan + "\xFF\xD9";
}

}  // namespace impossible::hostile
