#ifndef EDYN_COLLISION_CONTACT_POINT_HPP
#define EDYN_COLLISION_CONTACT_POINT_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstdint>
#include <optional>

namespace edyn {

// One persistent point of contact between the two bodies of a contact_manifold. The geometry
// is refreshed every step by the narrowphase; the impulses survive from step to step while the
// point is matched, which is what warm starting feeds on.
struct contact_point {
    // Contact point on each body, in that body's object space relative to its origin (not its
    // centre of mass).
    vector3 pivotA{vector3_zero};
    vector3 pivotB{vector3_zero};
    // World-space unit normal pointing from B towards A (as in collision_result).
    vector3 normal{vector3_y};
    // Signed distance between the pivots along `normal`; negative while penetrating.
    scalar distance{0};
    // The pivots in world space when the manifold was last updated (for the solver).
    vector3 positionA{vector3_zero};
    vector3 positionB{vector3_zero};

    // Impulses applied by the constraint solver over the whole last step (all its sub-steps).
    // Friction and rolling friction act along the two tangents given by plane_space(normal),
    // spin friction about the normal. The restitution solver's share is kept apart (see the
    // manual's "Restitution"): add both to get the full impulse.
    scalar normal_impulse{0};
    scalar normal_restitution_impulse{0};
    std::array<scalar, 2> friction_impulse{0, 0};
    std::array<scalar, 2> friction_restitution_impulse{0, 0};
    std::array<scalar, 2> roll_friction_impulse{0, 0};
    scalar spin_friction_impulse{0};

    // The impulses of the last step's final sub-step: the solver's first guess for the next
    // step (warm starting). Internal; read the impulses above.
    struct warm_start_impulses {
        scalar normal{0};
        std::array<scalar, 2> friction{0, 0};
        scalar spin{0};
        std::array<scalar, 2> roll{0, 0};
        // Normal speed (negative) at which the point was approaching when the speculative
        // contact braked it short of the surface, not yet answered by a bounce: the restitution
        // solver bounces from this speed, not the braked one, when the point touches.
        scalar approach{0};
    } warm_start;

    // Material values mixed for this point (per point because triangle meshes may carry
    // per-vertex materials). Stiffness and damping are infinite for rigid contacts.
    scalar friction{0};
    scalar restitution{0};
    scalar roll_friction{0};
    scalar spin_friction{0};
    scalar stiffness{large_scalar};
    scalar damping{large_scalar};

    // Number of steps the point has existed (0 in the step it was created).
    std::uint32_t lifetime{0};

    // Closest features, when the collision routine provides them.
    std::optional<collision_feature> featureA;
    std::optional<collision_feature> featureB;
};

} // namespace edyn

#endif // EDYN_COLLISION_CONTACT_POINT_HPP
