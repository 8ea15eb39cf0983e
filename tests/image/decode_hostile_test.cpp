// Hostile PNGs and JPEGs through the decoder (image/decode.hpp): palette
// indices past the PLTE chunk, JPEG scans cut short, truncated and damaged
// files. Every decoded pixel is written to /dev/null with write(2), so that
// under valgrind (the ctest image_decode_valgrind runs this suite so) a
// pixel that comes from uninitialised memory is an error; without valgrind
// each image is decoded twice and must give the same pixels.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hostile/jpeg_bytes.hpp"
#include "hostile/png_bytes.hpp"
#include "image/decode.hpp"

namespace impossible::image {
namespace {

using hostile::jpeg_file;
using hostile::png_chunk;
using hostile::png_file;

const unsigned char* bytes_of(const std::string& s) { return reinterpret_cast<const unsigned char*>(s.data()); }

// Hands every byte to the kernel, which valgrind checks for definedness.
void write_to_null(const Pixels& pixels) {
    const int fd = ::open("/dev/null", O_WRONLY);
    ASSERT_GE(fd, 0);
    EXPECT_EQ(::write(fd, pixels.data.data(), pixels.data.size()), static_cast<ssize_t>(pixels.data.size()));
    ::close(fd);
}

// Decodes `data` twice as a texture: the same pixels or the same error.
Result<Pixels> decode_twice(const std::string& data) {
    Result<Pixels> first = decode_image(bytes_of(data), data.size(), 8192);
    const Result<Pixels> second = decode_image(bytes_of(data), data.size(), 8192);
    EXPECT_EQ(first.has_value(), second.has_value());
    if (first && second) {
        write_to_null(*first);
        EXPECT_EQ(first->data, second->data);
    } else if (!first && !second) {
        EXPECT_EQ(first.error(), second.error());
    }
    return first;
}

// `png` with `chunk` inserted before its IDAT chunk.
std::string with_chunk(std::string png, const std::string& chunk) {
    png.insert(png.find("IDAT") - 4, chunk);
    return png;
}

// 4 × 1 pixels of 8-bit palette indices.
std::string palette_png(const std::string& indices, const std::string& plte, const std::string& trns = "") {
    std::string png = with_chunk(png_file(4, 1, 8, 3, std::string(1, '\0') + indices), png_chunk("PLTE", plte));
    return trns.empty() ? png : with_chunk(png, png_chunk("tRNS", trns));
}

const std::string kTwoColours = "\x10\x20\x30\x40\x50\x60";

TEST(DecodeHostile, AShortPaletteDecodesToItsColoursWithTheirAlpha) {
    const std::string indices = {0, 1, 1, 0};
    const Result<Pixels> pixels = decode_twice(palette_png(indices, kTwoColours, "\x80"));
    ASSERT_TRUE(pixels) << pixels.error();
    EXPECT_EQ(pixels->channels, 4);
    const std::vector<std::uint8_t> want = {0x10, 0x20, 0x30, 0x80, 0x40, 0x50, 0x60, 0xFF,
                                            0x40, 0x50, 0x60, 0xFF, 0x10, 0x20, 0x30, 0x80};
    EXPECT_EQ(pixels->data, want);
    // The same picture with a full palette, which stb_image decodes alone.
    const Result<Pixels> full = decode_twice(palette_png(indices, kTwoColours + std::string(254 * 3, '\x7F'), "\x80"));
    ASSERT_TRUE(full) << full.error();
    EXPECT_EQ(full->data, want);
}

TEST(DecodeHostile, APaletteIndexPastThePlteIsAnErrorNamingThePixel) {
    const Result<Pixels> past = decode_twice(palette_png(std::string{0, 1, 1, char(255)}, kTwoColours));
    ASSERT_FALSE(past);
    EXPECT_EQ(past.error(),
              "could not be decoded as PNG: pixel (3, 0) has the palette index 255, past the 2 entries of its PLTE "
              "chunk");
    // 2-bit indices 0, 1, 2, 3 in one byte; a PLTE of one entry.
    const std::string packed = with_chunk(png_file(4, 1, 2, 3, std::string("\0\x1B", 2)), png_chunk("PLTE", "abc"));
    const Result<Pixels> two_bits = decode_twice(packed);
    ASSERT_FALSE(two_bits);
    EXPECT_EQ(two_bits.error(),
              "could not be decoded as PNG: pixel (1, 0) has the palette index 1, past the 1 entry of its PLTE chunk");
    // Read back as a PNG file (compare): the same.
    const std::string png = palette_png(std::string{0, 1, 2, 0}, kTwoColours);
    const Result<Pixels> rgb = decode_grey_or_rgb(bytes_of(png), png.size());
    ASSERT_FALSE(rgb);
    EXPECT_EQ(rgb.error(), "pixel (2, 0) has the palette index 2, past the 2 entries of its PLTE chunk");
    const std::string fine = palette_png(std::string{1, 0, 1, 1}, kTwoColours, "\x00");
    const Result<Pixels> rgb_fine = decode_grey_or_rgb(bytes_of(fine), fine.size());
    ASSERT_TRUE(rgb_fine) << rgb_fine.error();
    EXPECT_EQ(rgb_fine->channels, 3);
    EXPECT_EQ(rgb_fine->data,
              std::vector<std::uint8_t>({0x40, 0x50, 0x60, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x40, 0x50, 0x60}));
}

TEST(DecodeHostile, TwoPltesOrATrnsLongerThanThePlteAreErrors) {
    const std::string indices = {0, 1, 1, 0};
    const Result<Pixels> two = decode_twice(with_chunk(palette_png(indices, kTwoColours), png_chunk("PLTE", "abc")));
    ASSERT_FALSE(two);
    EXPECT_EQ(two.error(), "could not be decoded as PNG: it has more than one PLTE chunk");
    const Result<Pixels> trns = decode_twice(palette_png(indices, kTwoColours, "\x01\x02\x03"));
    ASSERT_FALSE(trns);
    EXPECT_EQ(trns.error(),
              "could not be decoded as PNG: its tRNS chunk has 3 entries, more than the 2 of its PLTE chunk");
}

// stb_image stops decoding a scan at a restart interval whose RST marker is
// missing; the blocks after it are its zeroed memory: black.
TEST(DecodeHostile, AJpegScanCutShortLeavesBlackBlocks) {
    const Result<Pixels> whole = decode_twice(jpeg_file(16, 8));
    ASSERT_TRUE(whole) << whole.error();
    EXPECT_EQ(whole->data[0], 128);
    EXPECT_EQ(whole->data[4 * 15], 128);
    const Result<Pixels> cut = decode_twice(jpeg_file(16, 8, 1));
    ASSERT_TRUE(cut) << cut.error();
    EXPECT_EQ(cut->data[0], 128);     // the first block, before the first restart
    EXPECT_EQ(cut->data[4 * 15], 0);  // the second block
    EXPECT_EQ(cut->data[4 * 15 + 3], 255);
}

// stb_image copies a Huffman table's codes into 256 places without checking
// their count (found by UBSan in the damaged-byte test below).
TEST(DecodeHostile, AJpegHuffmanTableOfMoreThan256CodesIsAnError) {
    std::string jpeg = jpeg_file(16, 16);
    const std::size_t dht = jpeg.find("\xFF\xC4");
    std::string counts(16, '\0');
    counts[1] = '\xFF';
    counts[2] = 2;  // 257 codes
    jpeg.replace(dht, 22, hostile::jpeg_segment(0xC4, std::string(1, '\0') + counts + std::string(257, '\0')));
    const Result<Pixels> pixels = decode_twice(jpeg);
    ASSERT_FALSE(pixels);
    EXPECT_EQ(pixels.error(),
              "could not be decoded as JPEG: it is damaged (a Huffman table, DHT, has more than 256 codes or does "
              "not fit its segment)");
}

// stb_image leaves a component that no scan covers unwritten.
TEST(DecodeHostile, AJpegComponentThatNoScanCoversIsAnError) {
    const Result<Pixels> pixels = decode_twice(jpeg_file(16, 16, 0, 3));
    ASSERT_FALSE(pixels);
    EXPECT_EQ(pixels.error(),
              "could not be decoded as JPEG: it has no image data for its component 2 (no scan covers it)");
}

TEST(DecodeHostile, EveryTruncationOfAPngAndAJpegDecodesTheSameTwice) {
    const std::string png = palette_png(std::string{0, 1, 1, 0}, kTwoColours, "\x80");
    const std::string jpeg = jpeg_file(24, 16, 2);
    for (const std::string* data : {&png, &jpeg}) {
        for (std::size_t keep = 3; keep < data->size(); ++keep) {
            const Result<Pixels> cut = decode_twice(data->substr(0, keep));
            EXPECT_FALSE(cut) << keep;  // every file needs its last byte (IEND's CRC, EOI)
        }
    }
}

// A palette PNG of 4 × 2 pixels from its IDAT data, every CRC right, so that
// damage in that data reaches stb_image's decoder (interlaced: Adam7).
std::string palette_png_of(const std::string& idat, bool interlaced) {
    const std::string ihdr = hostile::be32(4) + hostile::be32(2) + std::string{8, 3, 0, 0, char(interlaced)};
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("PLTE", kTwoColours) +
           png_chunk("IDAT", idat) + png_chunk("IEND", "");
}

// The data of a PNG's IDAT chunk.
std::string idat_of(const std::string& png) {
    const std::size_t at = png.find("IDAT");
    const auto length = static_cast<std::size_t>(static_cast<unsigned char>(png[at - 2]) << 8 |
                                                 static_cast<unsigned char>(png[at - 1]));
    return png.substr(at + 4, length);
}

TEST(DecodeHostile, EveryByteOfAPngsImageDataOrAJpegDamagedDecodesTheSameTwice) {
    // Filter byte and indices a row; interlaced, the rows of passes 1, 4, 6 and 7.
    const std::string rows = std::string("\0\0\1\1\0\0\1\0\0\1", 10);
    const std::string adam7 = std::string("\0\0\0\1\0\1\0\0\1\0\0\1", 12);
    const Result<Pixels> plain = decode_twice(palette_png_of(idat_of(png_file(4, 2, 8, 3, rows)), false));
    const Result<Pixels> interlaced = decode_twice(palette_png_of(idat_of(png_file(4, 2, 8, 3, adam7)), true));
    ASSERT_TRUE(plain) << plain.error();
    ASSERT_TRUE(interlaced) << interlaced.error();
    EXPECT_EQ(plain->data, interlaced->data);
    for (const bool interlace : {false, true}) {
        const std::string idat = idat_of(png_file(4, 2, 8, 3, interlace ? adam7 : rows));
        for (std::size_t at = 0; at < idat.size(); ++at) {
            for (const char value : {'\x00', '\x01', '\x3F', '\x80', '\xFF'}) {
                std::string damaged = idat;
                damaged[at] = value;
                (void)decode_twice(palette_png_of(damaged, interlace));
            }
        }
    }
    const std::string jpeg = jpeg_file(24, 16, 2);
    for (std::size_t at = 2; at < jpeg.size(); ++at) {
        for (const char value : {'\x00', '\x01', '\x3F', '\x80', '\xFF'}) {
            std::string damaged = jpeg;
            damaged[at] = value;
            (void)decode_twice(damaged);
        }
    }
}

}  // namespace
}  // namespace impossible::image
