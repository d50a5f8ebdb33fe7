#ifndef EDYN_COLLISION_COLLISION_RESULT_HPP
#define EDYN_COLLISION_COLLISION_RESULT_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/quaternion.hpp"
#include <array>
#include <cstdint>
#include <optional>

namespace edyn {

/// Inputs of collide(): both shapes' transforms and the distance beyond which no point is
/// reported.
///
/// Positions are those of the shapes' origins in world space (m), orientations are unit
/// quaternions (x y z w). Planes ignore their own position and orientation.
struct collision_context {
    vector3 posA{vector3_zero};           ///< Position of shape A in world space (m), zero default.
    quaternion ornA{quaternion_identity}; ///< Orientation of shape A, identity default.
    vector3 posB{vector3_zero};           ///< Position of shape B in world space (m), zero default.
    quaternion ornB{quaternion_identity}; ///< Orientation of shape B, identity default.
    /// Points whose signed distance exceeds this are not reported (m); 0.02 by default.
    scalar threshold{scalar(0.02)};
};

/// Closest points of two shapes, as computed by collide().
///
/// Holds at most `max_contacts` points; when more are found, the ones spanning the largest area
/// are kept. The caller clears it (a default-constructed result is empty) before calling
/// collide(), which appends.
struct collision_result {
    /// Most points a result holds.
    static constexpr std::size_t max_contacts = 4;

    /// One closest point between the two shapes.
    struct collision_point {
        /// Closest point on shape A, in A's object space (m).
        vector3 pivotA;
        /// Closest point on shape B, in B's object space (m).
        vector3 pivotB;
        /// World-space unit normal pointing from B towards A: moving A along `normal` by
        /// -distance separates the shapes.
        vector3 normal;
        /// Signed distance along `normal` (m); negative when the shapes overlap.
        scalar distance;
        /// Closest feature of shape A, when the routine for this pair of shapes provides it
        /// (not for spheres, planes or polyhedra).
        std::optional<collision_feature> featureA;
        /// Closest feature of shape B, when provided (as `featureA`).
        std::optional<collision_feature> featureB;
    };

    /// Number of valid entries at the front of `point` (0 by default).
    std::size_t num_points{0};
    /// The points; only the first `num_points` are meaningful.
    std::array<collision_point, max_contacts> point;

    /// Adds a point, keeping at most `max_contacts`.
    ///
    /// A point whose pivot on A or on B lies very near an existing point's (within 1 mm) is merged
    /// with it: the deeper of the two is kept. When the result is full, a point is replaced so that
    /// the deepest point is kept and the area spanned by the set grows (nothing changes when no
    /// replacement grows it).
    /// @param p The point to add.
    void add_point(const collision_point &p);

    /// Exchanges the roles of A and B in every point (pivots, features, normal sign).
    ///
    /// Used for pairs computed as (B, A) by a shared routine.
    void swap();
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_RESULT_HPP
