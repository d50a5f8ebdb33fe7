// Mouse interaction with the world: dragging a body by a soft spring to a kinematic anchor that
// follows the cursor, casting a ray from the cursor, and shooting a ball. Rays go through
// edyn::raycast_async in every execution mode: cast at once in the sequential modes and in the
// simulation worker in asynchronous mode, the hit arriving with a later update() or
// wait_for_simulation().
#ifndef EDYN_TESTBED_PICKING_HPP
#define EDYN_TESTBED_PICKING_HPP

#include "camera.hpp"
#include <edyn/edyn.hpp>
#include <optional>

namespace testbed {

struct ray_hit {
    edyn::entity body{edyn::null};
    edyn::vector3 point{edyn::vector3_zero};
    edyn::vector3 normal{edyn::vector3_zero};
};

// A ray cast from the cursor whose hit is kept until the next one arrives.
class ray_probe {
public:
    // Casts `r` up to `length` metres; the hit replaces `last` when it arrives.
    void cast(edyn::registry &registry, const ray &r, edyn::scalar length = 500);
    void clear() { last = {}; }
    ray_hit last;

private:
    void on_result(edyn::raycast_id_type, const edyn::raycast_result &result, edyn::vector3 p0,
                   edyn::vector3 p1);
};

class body_dragger {
public:
    // Casts the ray; the dynamic body it hits, if any, is grabbed when the hit arrives (the
    // next poll() after the update() or wait_for_simulation() that delivers it).
    void grab(edyn::registry &registry, const ray &r);
    // Attaches the spring once the grab's hit has arrived. Called every frame.
    void poll(edyn::registry &registry);
    // Moves the anchor to the point of the ray at the grab's distance from the eye.
    void drag(edyn::registry &registry, const ray &r);
    void release(edyn::registry &registry);
    // After the registry is gone: forgets the grab without touching it.
    void forget();
    bool dragging() const { return anchor != edyn::null; }
    edyn::entity body() const { return grabbed; }
    // Where the spring pulls from and to, for drawing it.
    edyn::vector3 anchor_position(const edyn::registry &registry) const;
    edyn::vector3 grab_point(const edyn::registry &registry) const;

private:
    void on_result(edyn::raycast_id_type id, const edyn::raycast_result &result, edyn::vector3 p0,
                   edyn::vector3 p1);

    edyn::entity anchor{edyn::null}, spring{edyn::null}, grabbed{edyn::null};
    edyn::vector3 local_point{edyn::vector3_zero};
    edyn::scalar distance{0};
    // The grab's ray while its hit is on its way, and the hit once it is here.
    std::optional<edyn::raycast_id_type> waiting_for;
    std::optional<ray> pending_ray;
    std::optional<ray_hit> pending_hit;
};

// A ball of radius 0.25 m and 2 kg from the eye along the ray at `speed`.
edyn::entity shoot_ball(edyn::registry &registry, const ray &r, edyn::scalar speed = 30);

} // namespace testbed

#endif // EDYN_TESTBED_PICKING_HPP
