// Checks what a scripted testbed run (edyn-testbed --script) did with the mouse against the
// physics: the cursor ray's hit, the body grabbed, where the drag left it, where a shot ball
// ended, and that the picture shows the dragged body under the cursor.
#ifndef EDYN_TESTBED_CHECK_INTERACTION_CHECK_HPP
#define EDYN_TESTBED_CHECK_INTERACTION_CHECK_HPP

#include "image.hpp"
#include "samples.hpp"
#include <string>

namespace testbed {

// Prints "TX TY BX BY": the pixels (in a width x height image) of the highest body's centre
// and of the lowest body nearest the middle of the image, after `steps` steps: where a script
// grabs and shoots.
int print_targets(const sample &s, unsigned steps, int width, int height);

// Reads the "script: ..." lines the testbed printed to `log_path` for `script`, run after
// `steps` steps, and checks them and `img`. Prints what it checked; 0 when all holds.
int check_interaction(const sample &s, unsigned steps, const std::string &script, const std::string &log_path,
                      const image &img);

} // namespace testbed

#endif // EDYN_TESTBED_CHECK_INTERACTION_CHECK_HPP
