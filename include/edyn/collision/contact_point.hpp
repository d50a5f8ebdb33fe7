#ifndef EDYN_COLLISION_CONTACT_POINT_HPP
#define EDYN_COLLISION_CONTACT_POINT_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstdint>
#include <optional>

namespace edyn {

/// One persistent point of contact between the two bodies of a contact_manifold.
///
/// Written by the engine only: the narrowphase refreshes the geometry every step and the
/// solvers write the impulses; read it, e.g. in a collision event listener
/// (`manifold.point[manifold.ids[i]]`). The impulses survive from step to step while the point
/// is matched, which is what warm starting feeds on.
struct alignas(64) contact_point {
    /// Contact point on body A, in A's object space relative to its origin (not its centre of
    /// mass), in metres; zero by default. A held point's pivot may lie up to
    /// contact_anchor_max_slip along the surface from where collide() found the bodies touching:
    /// where the surfaces stuck (see update_contact_manifold).
    vector3 pivotA{vector3_zero};
    /// Contact point on body B, in B's object space relative to its origin (m); zero by default.
    vector3 pivotB{vector3_zero};
    /// World-space unit normal pointing from B towards A (as in collision_result); +y by default.
    vector3 normal{vector3_y};
    /// Signed distance between the pivots along `normal` (m); negative while penetrating.
    scalar distance{0};
    /// Pivot A in world space when the manifold was last updated (m), for the solver.
    vector3 positionA{vector3_zero};
    /// Pivot B in world space when the manifold was last updated (m), for the solver.
    vector3 positionB{vector3_zero};

    // What the solver reads and writes every step, kept to two cache lines: the geometry
    // above, then the following line of lifetime, warm start and impulses.

    /// Number of steps the point has existed (0 in the step it was created).
    std::uint32_t lifetime{0};

    /// The impulses of the last step's final sub-step: the solver's first guess for the next
    /// step (warm starting). Internal; read the impulses of contact_point instead.
    struct warm_start_impulses {
        scalar normal{0};                     ///< Normal impulse (N·s).
        std::array<scalar, 2> friction{0, 0}; ///< Friction impulses along the two tangents (N·s).
        scalar spin{0};                       ///< Spinning friction angular impulse (N·m·s).
        std::array<scalar, 2> roll{0, 0};     ///< Rolling friction angular impulses (N·m·s).
    } warm_start;                             ///< Warm-starting impulses (engine internal).

    /// Normal impulse applied by the constraint solver over the whole last step, all its
    /// sub-steps (N·s).
    ///
    /// Does not include the restitution solver's share, `normal_restitution_impulse`; add both
    /// to get the full normal impulse.
    scalar normal_impulse{0};
    /// Normal impulse applied by the restitution solver in the last step (N·s).
    ///
    /// Kept apart from `normal_impulse` because mixing them would let the constraint solver
    /// undo part of the propagated shock (see the manual's "Restitution"); zero when the
    /// restitution solver is off (no restitution iterations).
    scalar normal_restitution_impulse{0};
    /// Friction impulses of the constraint solver over the last step along the two tangents
    /// given by `plane_space(normal)` (N·s).
    ///
    /// The total friction impulse magnitude is the length of the 2D vector of both entries,
    /// after adding `friction_restitution_impulse`.
    std::array<scalar, 2> friction_impulse{0, 0};
    /// Friction impulses of the restitution solver in the last step, along the same tangents as
    /// `friction_impulse` (N·s); add both to get the full friction impulse.
    std::array<scalar, 2> friction_restitution_impulse{0, 0};
    /// Rolling friction angular impulses over the last step about the two tangents given by
    /// `plane_space(normal)` (N·m·s).
    std::array<scalar, 2> roll_friction_impulse{0, 0};
    /// Spinning friction angular impulse over the last step about the normal (N·m·s).
    scalar spin_friction_impulse{0};

    /// Friction coefficient mixed from both bodies' materials for this point (dimensionless).
    ///
    /// Per point because triangle meshes may carry per-vertex materials.
    scalar friction{0};
    /// Coefficient of restitution mixed for this point, in [0, 1].
    scalar restitution{0};
    /// Rolling friction mixed for this point: torque per unit of normal force (m).
    scalar roll_friction{0};
    /// Spinning friction mixed for this point: torque per unit of normal force (m).
    scalar spin_friction{0};
    /// Contact stiffness mixed for this point (N/m); `large_scalar` (infinite), the default, for
    /// a rigid contact.
    scalar stiffness{large_scalar};
    /// Contact damping mixed for this point (N·s/m); `large_scalar` (infinite), the default, for
    /// a rigid contact or to use the solver's damping ratio.
    scalar damping{large_scalar};

    /// Closest feature on body A, when the collision routine provides it.
    std::optional<collision_feature> featureA;
    /// Closest feature on body B, when the collision routine provides it.
    std::optional<collision_feature> featureB;
};

} // namespace edyn

#endif // EDYN_COLLISION_CONTACT_POINT_HPP
