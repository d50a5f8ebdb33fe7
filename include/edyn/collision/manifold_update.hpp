#ifndef EDYN_COLLISION_MANIFOLD_UPDATE_HPP
#define EDYN_COLLISION_MANIFOLD_UPDATE_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/math/quaternion.hpp"
#include <array>
#include <cstdint>

namespace edyn {

/// What one manifold update did, so that the caller can fire the collision events.
///
/// The caller fires `on_contact_point_destroyed` / `on_contact_point_created` (destroyed first:
/// a created point may reuse a destroyed point's slot) and `on_contact_started` /
/// `on_contact_ended`.
struct contact_point_changes {
    /// Type of a point's id (its slot in contact_manifold::point).
    using id_type = contact_manifold::id_type;

    std::uint32_t num_points_before{0}; ///< Live points before the update.
    std::uint32_t num_points_after{0};  ///< Live points after the update.
    std::uint32_t num_destroyed{0};     ///< Number of valid entries in `destroyed`.
    std::uint32_t num_created{0};       ///< Number of valid entries in `created`.
    /// Ids of the points removed, the first `num_destroyed` entries.
    std::array<id_type, contact_manifold::max_contacts> destroyed{};
    /// Ids of the points added, the first `num_created` entries.
    std::array<id_type, contact_manifold::max_contacts> created{};

    /// Whether the manifold went from no points to some (the contact started).
    bool contact_started() const noexcept { return num_points_before == 0 && num_points_after > 0; }
    /// Whether the manifold went from some points to none (the contact ended).
    bool contact_ended() const noexcept { return num_points_before > 0 && num_points_after == 0; }
};

/// Transforms of the bodies' origins (pivots are relative to the origin, not the centre of mass).
struct manifold_transforms {
    vector3 posA{vector3_zero};           ///< Origin of body A in world space (m).
    quaternion ornA{quaternion_identity}; ///< Orientation of body A.
    vector3 posB{vector3_zero};           ///< Origin of body B in world space (m).
    quaternion ornB{quaternion_identity}; ///< Orientation of body B.
};

/// Ages every point by one step and recomputes its distance from its pivots at the current
/// transforms, along its stored normal.
///
/// Removes points that separated beyond manifold.separation_threshold or whose pivots slid apart
/// tangentially beyond contact_drift_threshold. Called by the narrowphase.
/// @param manifold The manifold to refresh.
/// @param tf The bodies' current transforms.
/// @return The points removed.
contact_point_changes refresh_contact_manifold(contact_manifold &manifold, const manifold_transforms &tf);

/// Runs refresh_contact_manifold(), then merges a fresh collision result computed at the same
/// transforms.
///
/// - A result point matches a live point, preferring in this order: equal features (featureA
///   and/or featureB, present on the same sides) and a pivot on A or on B within
///   contact_caching_threshold; a pivot that near with other or no features (a clipped point may
///   change its feature label while staying in place); equal features farther away. The nearest
///   point wins within a preference. Each live point matches at most once. A match takes the new
///   geometry (pivots, normal, distance, features) and keeps impulses, materials and lifetime,
///   so that warm starting works; a held point of a pair that does not touch at one point, still
///   touching one body at the same material point, keeps its surfaces' slip instead, its pivot
///   on the other body moved along the surface (contact_anchor_max_slip).
/// - Result points farther than the separation threshold are ignored; a matched point that is
///   now beyond it is removed.
/// - With `shapes_changed`, live points the result does not match are removed: their pivots lie
///   on the old shapes, so refreshing them would keep a shrunken body standing on its old
///   surface.
/// - Unmatched result points fill free slots. When live and new points exceed max_contacts, the
///   set kept is the one that contains the deepest point and spans the largest area (measured
///   on body A), existing points winning ties; the points left out are destroyed (or never
///   created).
///
/// - With `one_point`, the pair touches at one point at most (a sphere and a convex shape):
///   the result's point, if any, continues the live point wherever its pivots lie, and every
///   other live point is removed. A rolling sphere turns its old pivot away from the surface a
///   little more every step; kept, that point would push on the sphere off its centre.
///
/// New points get zero impulses and default materials; the caller sets their material.
/// @param manifold The manifold to update.
/// @param tf The bodies' current transforms (those `result` was computed at).
/// @param result Closest points from collide() for the manifold's bodies, A being body[0].
/// @param shapes_changed Whether a body's shape was replaced or edited since the live points
///        were found.
/// @param one_point Whether the bodies' shapes touch at one point at most
///        (touches_at_one_point_v).
/// @return The points removed and created.
contact_point_changes update_contact_manifold(contact_manifold &manifold, const manifold_transforms &tf,
                                              const collision_result &result, bool shapes_changed = false,
                                              bool one_point = false);

/// Removes every point, e.g. when a body turns into a sensor or its shape changes.
/// @param manifold The manifold to empty.
/// @return The points removed.
contact_point_changes clear_contact_manifold(contact_manifold &manifold);

/// Whether the manifold's points may be refreshed at `tf` instead of recomputed by collide().
///
/// True when collide() ran for the pair before, with the same shapes (the bodies'
/// `shape_epochs`), neither body has moved or turned past the reuse thresholds since (see
/// contact_reuse_max_distance and contact_reuse_max_angle), and the bodies close in on each
/// other by no more than that distance over the coming step.
/// @param manifold The manifold, with its `last_collide` snapshot.
/// @param tf The bodies' current transforms.
/// @param approach Distance the bodies can approach each other by in the coming step (m).
/// @param shape_epochs The bodies' current shape epochs, in the manifold's body order.
/// @return Whether the points can be reused.
bool can_reuse_contacts(const contact_manifold &manifold, const manifold_transforms &tf, scalar approach,
                        const shape_epoch_pair &shape_epochs) noexcept;

/// Records the transforms and shape epochs that collide() has just run with, in
/// contact_manifold::last_collide.
/// @param manifold The manifold to update.
/// @param tf The transforms collide() ran at.
/// @param shape_epochs The bodies' shape epochs, in the manifold's body order.
void remember_collide(contact_manifold &manifold, const manifold_transforms &tf,
                      const shape_epoch_pair &shape_epochs) noexcept;

} // namespace edyn

#endif // EDYN_COLLISION_MANIFOLD_UPDATE_HPP
