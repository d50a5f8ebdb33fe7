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

// Distance along the normal beyond which a contact point is dropped (metres). Also the
// default for contact_manifold::separation_threshold.
inline constexpr scalar contact_breaking_threshold = scalar(0.02);
// Tangential distance between the two pivots of a point, in world space, beyond which the point
// is dropped: the surfaces slid so far that the point no longer describes the contact (metres).
inline constexpr scalar contact_drift_threshold = scalar(0.02);
// A new point without matching features is the same as an existing one when its pivot on
// either body lies within this distance of the existing pivot on that body (metres).
inline constexpr scalar contact_caching_threshold = scalar(0.04);

// A pair's points are reused without running collide() again while neither body has moved
// farther than this since the last collide() (metres), nor turned more than
// contact_reuse_max_angle (radians), and the bodies approach each other by less than this
// within the coming step. Bodies at rest then cost a refresh of their points, not a new
// closest-point search.
inline constexpr scalar contact_reuse_max_distance = scalar(0.001);
inline constexpr scalar contact_reuse_max_angle = scalar(0.0175); // about one degree

// The contact between two bodies whose AABBs overlap: an entity with this component is created
// by the broadphase and destroyed when the AABBs separate. It holds up to `max_contacts`
// points. A point keeps its slot in `point` for its whole life and `ids` lists the live slots:
// `point[ids[i]]` for i < num_points is the i-th live point. Removing a point swaps its id
// with the last live id, so ids of other points never change.
struct contact_manifold {
    static constexpr std::size_t max_contacts = 4;
    using id_type = std::uint8_t;

    std::array<entity, 2> body{null, null};
    // Points farther apart than this along their normal are removed.
    scalar separation_threshold{contact_breaking_threshold};
    std::uint32_t num_points{0};
    std::array<contact_point, max_contacts> point{};
    std::array<id_type, max_contacts> ids{0, 1, 2, 3};

    // The bodies' origins, orientations and shape epochs when collide() last ran for this
    // pair, for deciding whether the points can be reused (see contact_reuse_max_distance).
    struct collide_snapshot {
        vector3 posA{vector3_zero}, posB{vector3_zero};
        quaternion ornA{quaternion_identity}, ornB{quaternion_identity};
        shape_epoch_pair shape_epochs{0, 0};
        bool valid{false};
    } last_collide;

    // Calls fn(contact_point &) for each live point, in `ids` order.
    template<typename Fn>
    void each_point(Fn &&fn) {
        for (std::uint32_t i = 0; i < num_points; ++i)
            fn(point[ids[i]]);
    }

    template<typename Fn>
    void each_point(Fn &&fn) const {
        for (std::uint32_t i = 0; i < num_points; ++i)
            fn(point[ids[i]]);
    }
};

template<>
struct entity_members<contact_manifold> {
    template<typename Fn>
    static void each(contact_manifold &manifold, Fn &&fn) {
        fn(manifold.body[0]);
        fn(manifold.body[1]);
    }
};

} // namespace edyn

#endif // EDYN_COLLISION_CONTACT_MANIFOLD_HPP
