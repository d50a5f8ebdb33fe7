// Writes the frame just drawn to a PNG file: the back buffer, read before it is swapped.
#ifndef EDYN_TESTBED_SCREENSHOT_HPP
#define EDYN_TESTBED_SCREENSHOT_HPP

#include <string>

namespace testbed {

// Returns false (and says why on stderr) when the file cannot be written.
bool write_screenshot(const std::string &path, int width, int height);

} // namespace testbed

#endif // EDYN_TESTBED_SCREENSHOT_HPP
