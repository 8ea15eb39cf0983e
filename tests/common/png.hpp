// A PNG that a test expects to read: a failure names the file, and the image
// is empty so later checks fail too rather than crash.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "image/png.hpp"

namespace impossible::testing {

inline image::Pixels read_png_ok(const std::string& path) {
    Result<image::Pixels> read = image::read_png(path);
    if (!read) {
        ADD_FAILURE() << read.error();
        return {};
    }
    return std::move(*read);
}

}  // namespace impossible::testing
