// The colour each body is drawn in, shared by the renderer and the screenshot check: a palette
// colour per dynamic body, a tint where the sample gives one, grey for static bodies and, when
// asked, a pale grey for sleeping ones.
#ifndef EDYN_TESTBED_BODY_COLOUR_HPP
#define EDYN_TESTBED_BODY_COLOUR_HPP

#include <edyn/edyn.hpp>

namespace testbed {

struct colour {
    float r, g, b;
};

// The sky: what the screenshot check expects far from every body.
inline constexpr colour background_colour{0.60f, 0.72f, 0.85f};

colour body_colour(const edyn::registry &registry, edyn::entity body, bool grey_sleeping);

} // namespace testbed

#endif // EDYN_TESTBED_BODY_COLOUR_HPP
