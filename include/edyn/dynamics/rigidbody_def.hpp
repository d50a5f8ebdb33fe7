#ifndef EDYN_DYNAMICS_RIGIDBODY_DEF_HPP
#define EDYN_DYNAMICS_RIGIDBODY_DEF_HPP

#include "edyn/dynamics/material.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/shapes/shapes.hpp"
#include <cstdint>
#include <optional>

namespace edyn {

/// How a rigid body moves: by the simulation, never, or as the program says.
/// Set in rigidbody_def::kind and changed with rigidbody_set_kind; a body carries the matching
/// tag (dynamic_tag, static_tag or kinematic_tag).
enum class rigidbody_kind : std::uint8_t {
    /// Moved by the simulation: forces, contacts and constraints act on it.
    rb_dynamic,
    /// Never moves; infinite mass.
    rb_static,
    /// Infinite mass, moved by the program: it follows its linvel/angvel, or the position and
    /// orientation the program assigns, and pushes dynamic bodies out of its way.
    rb_kinematic
};

/// Everything needed to create a rigid body with make_rigidbody.
/// A plain value the program fills in; make_rigidbody validates it (validate_rigidbody_def
/// lists what it refuses) and turns it into components.
struct rigidbody_def {
    /// Dynamic (the default), static or kinematic.
    rigidbody_kind kind{rigidbody_kind::rb_dynamic};
    /// Mass in kg; default 1. Dynamic bodies need a positive, finite mass within
    /// [`min_body_mass`, `max_body_mass`]; static and kinematic bodies ignore it.
    scalar mass{1};
    /// Inertia tensor about the centre of mass in object space, in kg·m².
    /// Computed from the shape and the mass when empty (the default); required for a dynamic
    /// body without a shape.
    std::optional<matrix3x3> inertia;
    /// Surface material; default a material{} (friction 0.5, no restitution).
    /// Reset it to make a sensor (contacts and events, no contact response).
    std::optional<edyn::material> material{edyn::material{}};
    /// The manual's shorthand for `material->restitution`: when set, it replaces the material's
    /// restitution (in [0, 1]); a sensor, which has no material, refuses it. Empty by default.
    std::optional<scalar> restitution;
    /// Origin of the body in world space, in metres; default the world origin.
    /// The centre of mass is offset from it by center_of_mass.
    vector3 position{vector3_zero};
    /// Orientation in world space, a unit quaternion (x y z w); default the identity.
    quaternion orientation{quaternion_identity};
    /// Linear velocity of the centre of mass, world space, in m/s; default zero. Ignored for a
    /// static body.
    vector3 linvel{vector3_zero};
    /// Angular velocity, world space, in rad/s; default zero. Ignored for a static body.
    vector3 angvel{vector3_zero};
    /// Gravity for this body, in m/s²; empty (the default) uses the world's (set_gravity).
    /// Only dynamic bodies use it, though it is validated for every kind.
    std::optional<vector3> gravity;
    /// The body's shape; empty (the default) for an amorphous body, which takes no part in
    /// collision detection.
    std::optional<shapes_variant_t> shape;
    /// Collision groups the body belongs to, one bit each; default all.
    /// Kept in the body's collision_filter; ignored for an amorphous body.
    std::uint64_t collision_group{~std::uint64_t(0)};
    /// Collision groups the body collides with, one bit each; default all.
    /// Kept in the body's collision_filter; ignored for an amorphous body.
    std::uint64_t collision_mask{~std::uint64_t(0)};
    /// Offset of the centre of mass from the origin in object space, in metres.
    /// When empty (the default): a dynamic body's shape centroid; the origin for a body without
    /// a shape and for static and kinematic bodies.
    std::optional<vector3> center_of_mass;
    /// Keeps the body's island from ever sleeping; default false.
    bool sleeping_disabled{false};
};

} // namespace edyn

#endif // EDYN_DYNAMICS_RIGIDBODY_DEF_HPP
