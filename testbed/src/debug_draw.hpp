// Lines over the scene, each on demand: contact points and their normals, body AABBs and the
// bounds of each island (grey when it sleeps).
#ifndef EDYN_TESTBED_DEBUG_DRAW_HPP
#define EDYN_TESTBED_DEBUG_DRAW_HPP

#include "renderer.hpp"
#include <edyn/edyn.hpp>

namespace testbed {

struct debug_options {
    bool contacts{false};
    bool normals{false};
    bool aabbs{false};
    bool islands{false};
    bool grey_sleeping{false};
};

void draw_debug(const edyn::registry &registry, renderer &r, const debug_options &options);

void add_line(renderer &r, const edyn::vector3 &a, const edyn::vector3 &b, float red, float green,
              float blue);
void add_cross(renderer &r, const edyn::vector3 &p, float size, float red, float green, float blue);
void add_box(renderer &r, const edyn::AABB &box, float red, float green, float blue);

} // namespace testbed

#endif // EDYN_TESTBED_DEBUG_DRAW_HPP
