#ifndef EDYN_COLLISION_COLLISION_RESULT_HPP
#define EDYN_COLLISION_COLLISION_RESULT_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/quaternion.hpp"
#include <array>
#include <cstdint>
#include <optional>

namespace edyn {

// Inputs of collide(): both shapes' transforms and the distance beyond which no point is
// reported.
struct collision_context {
    vector3 posA{vector3_zero};
    quaternion ornA{quaternion_identity};
    vector3 posB{vector3_zero};
    quaternion ornB{quaternion_identity};
    scalar threshold{scalar(0.02)};
};

// Closest points of two shapes. A manifold holds at most `max_contacts` points; when more are
// found, the ones spanning the largest area are kept.
struct collision_result {
    static constexpr std::size_t max_contacts = 4;

    struct collision_point {
        // Closest point on each shape, in that shape's object space.
        vector3 pivotA;
        vector3 pivotB;
        // World-space unit normal pointing from B towards A: moving A along `normal` by
        // -distance separates the shapes.
        vector3 normal;
        // Signed distance along `normal`; negative when the shapes overlap.
        scalar distance;
        std::optional<collision_feature> featureA;
        std::optional<collision_feature> featureB;
    };

    std::size_t num_points{0};
    std::array<collision_point, max_contacts> point;

    // Adds a point, keeping at most max_contacts; when full, replaces a point so that the
    // deepest point is kept and the area spanned by the set grows. Defined in collision/.
    void add_point(const collision_point &p);

    // Exchanges the roles of A and B in every point (pivots, features, normal sign), for pairs
    // computed as (B, A) by a shared routine.
    void swap();
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_RESULT_HPP
