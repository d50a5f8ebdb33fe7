// A screenshot read back for checking, and the colour tests the checks share.
#ifndef EDYN_TESTBED_CHECK_IMAGE_HPP
#define EDYN_TESTBED_CHECK_IMAGE_HPP

#include "body_colour.hpp"
#include <algorithm>
#include <cmath>
#include <memory>
#include <stb_image.h>
#include <string>

namespace testbed {

struct image {
    int width{0}, height{0};
    std::unique_ptr<unsigned char, void (*)(void *)> pixels{nullptr, stbi_image_free};

    // Reads an RGB PNG; false when it cannot.
    bool load(const std::string &path) {
        int channels = 0;
        pixels.reset(stbi_load(path.c_str(), &width, &height, &channels, 3));
        return pixels != nullptr;
    }
    colour at(int x, int y) const {
        auto *p = pixels.get() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
    }
};

// Lit colours are the body's colour times a light factor (the shader's 0.4 to 1.0): the pixel
// must be close to some such multiple.
inline bool lit_match(colour pixel, colour base) {
    float dot_pc = pixel.r * base.r + pixel.g * base.g + pixel.b * base.b;
    float dot_cc = base.r * base.r + base.g * base.g + base.b * base.b;
    float k = dot_pc / dot_cc;
    if (k < 0.3f || k > 1.1f) return false;
    float worst = std::max(
        {std::abs(pixel.r - k * base.r), std::abs(pixel.g - k * base.g), std::abs(pixel.b - k * base.b)});
    return worst < 0.06f;
}

inline bool is_background(colour pixel) {
    auto bg = background_colour;
    return std::abs(pixel.r - bg.r) < 0.015f && std::abs(pixel.g - bg.g) < 0.015f &&
           std::abs(pixel.b - bg.b) < 0.015f;
}

// How many of the 3 x 3 pixels around (x, y) are a lit shade of `base`.
inline int lit_matches_around(const image &img, int x, int y, colour base) {
    int good = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            good += lit_match(img.at(x + dx, y + dy), base);
    return good;
}

} // namespace testbed

#endif // EDYN_TESTBED_CHECK_IMAGE_HPP
