#ifndef EDYN_COLLISION_CONTACT_MANIFOLD_HPP
#define EDYN_COLLISION_CONTACT_MANIFOLD_HPP

#include "edyn/collision/contact_point.hpp"
#include "edyn/collision/shape_epoch.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_members.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstddef>
#include <cstdint>

namespace edyn {

/// Distance along the normal beyond which a contact point is dropped (m).
///
/// Also the default for contact_manifold::separation_threshold.
inline constexpr scalar contact_breaking_threshold = scalar(0.02);
/// Tangential distance between the two pivots of a point, in world space, beyond which the point
/// is dropped (m): the surfaces slid so far that the point no longer describes the contact.
inline constexpr scalar contact_drift_threshold = scalar(0.02);
/// Steps a contact point must have lasted (contact_point::lifetime) before static friction holds
/// it where its surfaces stuck across steps (contact_solver_settings::friction_anchor_hertz);
/// half a second at 60 Hz. Younger points are held only against the sliding of the current step.
/// The first moments of a contact, an impact or a tumble, are then decided as in a world rebuilt
/// from the bodies' positions and velocities alone, as a network client's extrapolation is
/// (a few steps long), while bodies that have come to rest stay where they are.
inline constexpr std::uint32_t contact_anchor_min_lifetime = 30;
/// Slip of a held contact point's surfaces beyond which a new collide() holds the point again
/// where its surfaces now touch, not where they stuck (m).
///
/// A point old enough to be held (contact_anchor_min_lifetime) that touches one of its bodies at
/// the same material point keeps its pivots' distance along the surfaces when collide() finds
/// it again, up to this slip, as it does while its pair's points are reused: static friction
/// then holds the surfaces where they stuck also on a body that moves or turns, a box on a
/// turning platform or on an accelerating truck. A point that slid farther starts again where
/// it touches, before contact_drift_threshold would end it.
inline constexpr scalar contact_anchor_max_slip = scalar(0.005);
/// Distance within which a new point without matching features is the same as an existing one
/// (m): its pivot on either body lies within this distance of the existing pivot on that body.
inline constexpr scalar contact_caching_threshold = scalar(0.04);

/// Largest motion of either body since the last collide() of a pair for which its contact points
/// are reused instead of recomputed (m).
///
/// A pair's points are reused without running collide() again while neither body has moved
/// farther than this since the last collide(), nor turned more than contact_reuse_max_angle,
/// and the bodies approach each other by less than this within the coming step. Bodies at rest
/// then cost a refresh of their points, not a new closest-point search.
inline constexpr scalar contact_reuse_max_distance = scalar(0.001);
/// Largest rotation of either body since the last collide() of a pair for which its contact
/// points are reused (radians; about one degree). See contact_reuse_max_distance.
inline constexpr scalar contact_reuse_max_angle = scalar(0.0175);

/// The contact between two bodies whose AABBs overlap.
///
/// An entity with this component is created by the broadphase when the bodies' (fattened) AABBs
/// start to overlap and their filters let them collide, and destroyed when the AABBs separate;
/// the engine writes it, the user reads it (e.g. in the collision events `on_contact_started`,
/// `on_contact_point_created`). It holds up to `max_contacts` points. A point keeps its slot in
/// `point` for its whole life and `ids` lists the live slots: `point[ids[i]]` for
/// i < num_points is the i-th live point. Removing a point swaps its id with the last live id,
/// so ids of other points never change.
struct contact_manifold {
    /// Most points a manifold holds.
    static constexpr std::size_t max_contacts = 4;
    /// Type of a point's id: its slot index in `point`.
    using id_type = std::uint8_t;

    /// The two bodies in contact (A, then B); body[0] has the lower entity value.
    std::array<entity, 2> body{null, null};
    /// Points farther apart than this along their normal are removed (m); by default
    /// contact_breaking_threshold.
    scalar separation_threshold{contact_breaking_threshold};
    /// Number of live points, at the front of `ids` (0 by default).
    std::uint32_t num_points{0};
    /// Ids of the live points first (the first `num_points` entries), then the free ones.
    std::array<id_type, max_contacts> ids{0, 1, 2, 3};

    /// The bodies' origins, orientations and shape epochs when collide() last ran for this
    /// pair, for deciding whether the points can be reused (see contact_reuse_max_distance).
    /// Written by the engine.
    struct collide_snapshot {
        /// Origin of body A in world space (m).
        vector3 posA{vector3_zero}, posB{vector3_zero}; ///< Origin of body B in world space (m).
        /// Orientation of body A.
        quaternion ornA{quaternion_identity}, ornB{quaternion_identity}; ///< Orientation of body B.
        shape_epoch_pair shape_epochs{0, 0}; ///< Shape epochs of A and B (see shape_epoch).
        bool valid{false};                   ///< Whether collide() has run for the pair yet.
    } last_collide;                          ///< The state at the last collide() of this pair.

    /// Point slots, indexed by point id; only the slots listed in the first `num_points` entries
    /// of `ids` are live. (Last, each on whole cache lines: everything above, which every
    /// visit reads, shares the manifold's first two.)
    std::array<contact_point, max_contacts> point{};

    /// Calls `fn(contact_point &)` for each live point, in `ids` order.
    /// @param fn Callable taking a `contact_point &`.
    template<typename Fn>
    void each_point(Fn &&fn) {
        for (std::uint32_t i = 0; i < num_points; ++i)
            fn(point[ids[i]]);
    }

    /// Calls `fn(const contact_point &)` for each live point, in `ids` order.
    /// @param fn Callable taking a `const contact_point &`.
    template<typename Fn>
    void each_point(Fn &&fn) const {
        for (std::uint32_t i = 0; i < num_points; ++i)
            fn(point[ids[i]]);
    }
};

/// Declares the entity-valued members of contact_manifold (its two bodies), so that they are
/// mapped between registries (simulation worker, network).
template<>
struct entity_members<contact_manifold> {
    /// Calls `fn(entity &)` for body[0] and body[1].
    /// @param manifold The manifold whose bodies are visited.
    /// @param fn Callable taking an `entity &`; it may rewrite the entity in place.
    template<typename Fn>
    static void each(contact_manifold &manifold, Fn &&fn) {
        fn(manifold.body[0]);
        fn(manifold.body[1]);
    }
};

} // namespace edyn

#endif // EDYN_COLLISION_CONTACT_MANIFOLD_HPP
