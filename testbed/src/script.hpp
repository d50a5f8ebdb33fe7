// Scripted pointer input for off-screen runs: what a user does with the mouse, frame by frame,
// so that picking, the cursor ray and shooting run through the same code as in a window and a
// test can check what they did.
#ifndef EDYN_TESTBED_SCRIPT_HPP
#define EDYN_TESTBED_SCRIPT_HPP

#include <string>
#include <vector>

namespace testbed {

enum class script_action {
    press,   // left button down at (x, y): grabs the body there
    move,    // cursor to (x, y) over `frames` frames, in a straight line
    release, // left button up
    wait,    // `frames` frames with the pointer as it is
    ray,     // the cursor ray at (x, y), shown from then on, its hit reported
    shoot    // a ball shot through (x, y), as the B key does
};

struct script_command {
    script_action action;
    float x{0}, y{0}; // pixels, origin top left
    unsigned frames{0};
};

// Parses commands separated by ';': "press X Y", "move X Y FRAMES", "release", "wait FRAMES",
// "ray X Y", "shoot X Y". Coordinates are pixels of a width x height image.
// Throws std::invalid_argument naming the command that is wrong: an unknown word, a missing or
// extra number, a pixel outside the image, or frames outside 1 to 10,000.
std::vector<script_command> parse_script(const std::string &text, int width, int height);

} // namespace testbed

#endif // EDYN_TESTBED_SCRIPT_HPP
