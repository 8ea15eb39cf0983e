#include "image/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace impossible::image {

namespace {

size_t pixel_count(const Image& p) { return static_cast<size_t>(p.width) * static_cast<size_t>(p.height); }

// Whether some pixel of `ids` within one pixel of (x, y) holds `id`.
bool near_id(const std::vector<std::uint8_t>& ids, int width, int height, int x, int y, std::uint8_t id) {
    for (int yy = std::max(0, y - 1); yy <= std::min(height - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(width - 1, x + 1); ++xx)
            if (ids[static_cast<size_t>(yy) * width + xx] == id) return true;
    return false;
}

// Whether every pixel of `ids` within one pixel of (x, y) holds `id`.
bool all_id(const std::vector<std::uint8_t>& ids, int width, int height, int x, int y, std::uint8_t id) {
    for (int yy = std::max(0, y - 1); yy <= std::min(height - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(width - 1, x + 1); ++xx)
            if (ids[static_cast<size_t>(yy) * width + xx] != id) return false;
    return true;
}

// Whether no pixel within one pixel of (x, y) differs from it by more than
// 8 levels in any channel: (x, y) is on no colour edge (a checker's or a
// texture's), where a sub-pixel shift flips the pixel to the other colour.
bool flat(const Image& p, int x, int y) {
    const std::uint8_t* centre = &p.rgb[3 * (static_cast<size_t>(y) * p.width + x)];
    for (int yy = std::max(0, y - 1); yy <= std::min(p.height - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(p.width - 1, x + 1); ++xx)
            for (size_t c = 0; c < 3; ++c)
                if (std::abs(int(p.rgb[3 * (static_cast<size_t>(yy) * p.width + xx) + c]) - int(centre[c])) > 8)
                    return false;
    return true;
}

int channel_error(const Image& a, const Image& b, size_t pixel, int& worst) {
    int sum_sq = 0;
    for (size_t c = 0; c < 3; ++c) {
        const int e = std::abs(int(a.rgb[3 * pixel + c]) - int(b.rgb[3 * pixel + c]));
        worst = std::max(worst, e);
        sum_sq += e * e;
    }
    return sum_sq;
}

double psnr(double sum_sq, double samples) {
    if (sum_sq == 0.0 || samples == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(255.0 * 255.0 * samples / sum_sq);
}

}  // namespace

std::optional<std::string> incomparable(const Image& a, const Image& b) {
    if (a.width <= 0 || a.height <= 0) return std::string("the first image is empty");
    if (a.width != b.width || a.height != b.height)
        return "the images differ in size (" + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
               std::to_string(b.width) + "x" + std::to_string(b.height) + ")";
    const size_t n = pixel_count(a);
    if (a.rgb.size() != 3 * n || b.rgb.size() != 3 * n) return std::string("internal error: bad colour buffer size");
    if (a.ids.empty() != b.ids.empty()) return std::string("an id map is given for one image only");
    if (!a.ids.empty() && (a.ids.size() != n || b.ids.size() != n))
        return std::string("the id maps differ in size from the colour images");
    return std::nullopt;
}

std::vector<std::uint8_t> id_mismatch_mask(int width, int height, const std::vector<std::uint8_t>& ids_a,
                                           const std::vector<std::uint8_t>& ids_b) {
    std::vector<std::uint8_t> mask(static_cast<size_t>(width) * height, 0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            const bool a_found = near_id(ids_b, width, height, x, y, ids_a[i]);
            const bool b_found = near_id(ids_a, width, height, x, y, ids_b[i]);
            mask[i] = (a_found && b_found) ? 0 : 1;
        }
    }
    return mask;
}

Comparison compare_pictures(const Image& a, const Image& b) {
    Comparison c;
    const size_t n = pixel_count(a);
    c.pixels = static_cast<long>(n);
    double sum_sq = 0.0, interior_sq = 0.0, flat_sq = 0.0;
    for (size_t i = 0; i < n; ++i) sum_sq += channel_error(a, b, i, c.max_error);
    c.psnr_db = psnr(sum_sq, 3.0 * static_cast<double>(n));
    c.has_ids = !a.ids.empty();
    if (!c.has_ids) return c;

    const std::vector<std::uint8_t> mask = id_mismatch_mask(a.width, a.height, a.ids, b.ids);
    for (std::uint8_t m : mask) c.id_mismatches += m;
    c.id_mismatch_percent = n ? 100.0 * static_cast<double>(c.id_mismatches) / static_cast<double>(n) : 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const size_t i = static_cast<size_t>(y) * a.width + x;
            const std::uint8_t id = a.ids[i];
            if (b.ids[i] != id || !all_id(a.ids, a.width, a.height, x, y, id) ||
                !all_id(b.ids, a.width, a.height, x, y, id))
                continue;
            ++c.interior_pixels;
            interior_sq += channel_error(a, b, i, c.interior_max_error);
            if (!flat(a, x, y) || !flat(b, x, y)) continue;
            ++c.flat_pixels;
            flat_sq += channel_error(a, b, i, c.flat_max_error);
        }
    }
    c.interior_psnr_db = psnr(interior_sq, 3.0 * static_cast<double>(c.interior_pixels));
    c.flat_psnr_db = psnr(flat_sq, 3.0 * static_cast<double>(c.flat_pixels));
    return c;
}

std::vector<std::uint8_t> diff_picture(const Image& a, const Image& b) {
    const size_t n = pixel_count(a);
    std::vector<std::uint8_t> mask;
    if (!a.ids.empty()) mask = id_mismatch_mask(a.width, a.height, a.ids, b.ids);
    std::vector<std::uint8_t> out(3 * n);
    for (size_t i = 0; i < n; ++i) {
        std::uint8_t* px = &out[3 * i];
        if (!mask.empty() && mask[i]) {
            px[0] = 255, px[1] = 0, px[2] = 0;
            continue;
        }
        const double luminance = 0.2126 * a.rgb[3 * i] + 0.7152 * a.rgb[3 * i + 1] + 0.0722 * a.rgb[3 * i + 2];
        const int grey = static_cast<int>(std::lround(luminance / 3.0));
        int worst = 0;
        channel_error(a, b, i, worst);
        px[0] = static_cast<std::uint8_t>(grey);
        px[1] = static_cast<std::uint8_t>(std::min(255, grey + 8 * worst));
        px[2] = static_cast<std::uint8_t>(grey);
    }
    return out;
}

std::string summary_line(const Comparison& c) {
    std::ostringstream s;
    auto db = [&](double v) {
        if (std::isinf(v))
            s << "inf";
        else
            s << v;
    };
    s.setf(std::ios::fixed);
    s.precision(2);
    s << "pixels=" << c.pixels << " psnr_db=";
    db(c.psnr_db);
    s << " max_error=" << c.max_error;
    if (c.has_ids) {
        s << " id_mismatches=" << c.id_mismatches;
        s.precision(4);
        s << " id_mismatch_pct=" << c.id_mismatch_percent;
        s.precision(2);
        s << " interior_pixels=" << c.interior_pixels << " interior_psnr_db=";
        db(c.interior_psnr_db);
        s << " interior_max_error=" << c.interior_max_error << " flat_pixels=" << c.flat_pixels << " flat_psnr_db=";
        db(c.flat_psnr_db);
        s << " flat_max_error=" << c.flat_max_error;
    }
    return s.str();
}

}  // namespace impossible::image
