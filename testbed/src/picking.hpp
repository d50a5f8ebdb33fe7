// Mouse interaction with the world: dragging a body by a soft spring to a kinematic anchor that
// follows the cursor, casting a ray from the cursor, and shooting a ball. Rays need the
// registry's broadphase on this thread, so these work in the sequential modes only.
#ifndef EDYN_TESTBED_PICKING_HPP
#define EDYN_TESTBED_PICKING_HPP

#include "camera.hpp"
#include <edyn/edyn.hpp>

namespace testbed {

class body_dragger {
public:
    // Grabs the dynamic body under the ray, if any: returns whether one was grabbed.
    bool grab(edyn::registry &registry, const ray &r);
    // Moves the anchor to the point of the ray at the grab's distance from the eye.
    void drag(edyn::registry &registry, const ray &r);
    void release(edyn::registry &registry);
    bool dragging() const { return anchor != edyn::null; }
    edyn::entity body() const { return grabbed; }
    // Where the spring pulls from and to, for drawing it.
    edyn::vector3 anchor_position(const edyn::registry &registry) const;
    edyn::vector3 grab_point(const edyn::registry &registry) const;

private:
    edyn::entity anchor{edyn::null}, spring{edyn::null}, grabbed{edyn::null};
    edyn::vector3 local_point{edyn::vector3_zero};
    edyn::scalar distance{0};
};

struct ray_hit {
    edyn::entity body{edyn::null};
    edyn::vector3 point{edyn::vector3_zero};
    edyn::vector3 normal{edyn::vector3_zero};
};
// The first body along the ray within `length` metres.
ray_hit cast_ray(const edyn::registry &registry, const ray &r, edyn::scalar length = 500);

// A ball of radius 0.25 m and 2 kg from the eye along the ray at `speed`.
edyn::entity shoot_ball(edyn::registry &registry, const ray &r, edyn::scalar speed = 30);

} // namespace testbed

#endif // EDYN_TESTBED_PICKING_HPP
