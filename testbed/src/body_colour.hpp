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
// Triangle meshes and the loaded pages of paged meshes.
inline constexpr colour terrain_colour{0.55f, 0.62f, 0.45f};

colour body_colour(const edyn::registry &registry, edyn::entity body, bool grey_sleeping);

// The palette colour a dynamic body without a tint is drawn in, picked by its entity's index.
colour palette_colour(edyn::entity body);

} // namespace testbed

#endif // EDYN_TESTBED_BODY_COLOUR_HPP
