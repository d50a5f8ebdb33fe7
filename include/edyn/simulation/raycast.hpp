#ifndef EDYN_SIMULATION_RAYCAST_HPP
#define EDYN_SIMULATION_RAYCAST_HPP

#include "edyn/collision/shape_raycast.hpp"
#include "edyn/ecs/registry.hpp"
#include <vector>

namespace edyn {

/// The first body a ray hits, as raycast and raycast_async report it.
/// A default-constructed result is a miss.
struct raycast_result {
    /// The body hit, or null when the ray hits nothing.
    edyn::entity entity{null};
    /// Position of the hit along the ray, `lerp(p0, p1, fraction)`, in [0, 1];
    /// raycast_miss_fraction on a miss.
    scalar fraction{raycast_miss_fraction};
    /// World-space unit normal of the surface at the hit, pointing out of the body; zero on a
    /// miss.
    vector3 normal{vector3_zero};
    /// What the body's shape reports of the hit (see shape_raycast.hpp): box_raycast_info for a
    /// box, polyhedron_raycast_info for a polyhedron, std::monostate for a sphere or a plane...
    raycast_info_variant info_var{};

    /// Whether the ray hit a body.
    /// @return True when `entity` is not null.
    bool hit() const noexcept { return entity != null; }
};

/// Casts the segment from p0 to p1 against every rigid body with a shape in an attached
/// registry, and returns the first hit.
/// Bodies are hit sleeping or awake, sensors included. Bodies listed in `ignore_entities` are
/// skipped (a character casting from inside its own capsule, say). A ray that starts inside a
/// body hits it at fraction 0. Equal fractions go to the lower entity value, so the answer
/// does not depend on the broadphase's layout.
///
/// Reads the broadphase, whose AABBs are those of the last step (and of bodies created since):
/// call it between steps or from a step callback, not while a step runs. In asynchronous mode
/// use raycast_async on the main registry; raycast works there only inside step callbacks, on
/// the worker's registry.
/// @param registry An attached registry, not in asynchronous mode.
/// @param p0 Start of the ray, world space, in metres.
/// @param p1 End of the ray, world space, in metres.
/// @param ignore_entities Bodies the ray passes through.
/// @return The first hit, or a result whose hit() is false.
/// @throws std::invalid_argument When the registry is not attached, when p0 or p1 is not
/// finite, or on the main registry of the asynchronous mode.
raycast_result raycast(const registry &registry, const vector3 &p0, const vector3 &p1,
                       const std::vector<entity> &ignore_entities = {});

} // namespace edyn

#endif // EDYN_SIMULATION_RAYCAST_HPP
