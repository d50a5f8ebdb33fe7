#include "screenshot.hpp"
#include "gl.hpp"
#include <algorithm>
#include <cstdio>
#include <stb_image_write.h>
#include <vector>

namespace testbed {

bool write_screenshot(const std::string &path, int width, int height) {
    std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 3);
    glFinish();
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // OpenGL's rows go bottom up, PNG's top down.
    std::vector<unsigned char> flipped(pixels.size());
    auto row = std::size_t(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy_n(pixels.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                    flipped.begin() + std::ptrdiff_t(std::size_t(y) * row));
    if (!stbi_write_png(path.c_str(), width, height, 3, flipped.data(), int(row))) {
        std::fprintf(stderr, "edyn-testbed: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

} // namespace testbed
