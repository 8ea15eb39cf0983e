// Reads a JPEG file's markers before decoding it: stb_image names most faults
// of a JPEG by another format's reason ("bad png sig"), leaves the pixels of
// a JPEG without a scan (or of a component no scan covers) unwritten, and
// overflows a Huffman table of more than 256 codes.
#pragma once

#include <cstddef>

#include "base/result.hpp"

namespace impossible::image {

struct JpegFrame {
    int width = 0;  // from the first frame header (SOF)
    int height = 0;
};

// Walks the marker segments of JPEG data (which starts with SOI) up to its
// first frame header (SOF) or, with `whole`, on to its EOI marker, skipping
// each scan's entropy-coded data. The error says what is wrong, after "it":
// "is truncated (it ends before its EOI marker)", "has no frame header (SOF
// marker) before its image data", "has no image data (no SOS marker before
// its EOI marker)", "has no image data for its component 2 (no scan covers
// it)", "is damaged (a Huffman table, DHT, has more than 256 codes ...)".
Result<JpegFrame> read_jpeg_markers(const unsigned char* bytes, std::size_t size, bool whole);

}  // namespace impossible::image
