#ifndef EDYN_DYNAMICS_RIGIDBODY_DEF_HPP
#define EDYN_DYNAMICS_RIGIDBODY_DEF_HPP

#include "edyn/dynamics/material.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/shapes/shapes.hpp"
#include <cstdint>
#include <optional>

namespace edyn {

enum class rigidbody_kind : std::uint8_t {
    // Moved by the simulation.
    rb_dynamic,
    // Never moves; infinite mass.
    rb_static,
    // Infinite mass, moved by the program: it follows its linvel/angvel, or the position and
    // orientation the program assigns, and pushes dynamic bodies out of its way.
    rb_kinematic
};

// Everything needed to create a rigid body with make_rigidbody.
struct rigidbody_def {
    rigidbody_kind kind{rigidbody_kind::rb_dynamic};
    // Mass in kg; dynamic bodies need a positive, finite mass.
    scalar mass{1};
    // Inertia tensor about the centre of mass in object space. Computed from the shape and the
    // mass when empty; required for a dynamic body without a shape.
    std::optional<matrix3x3> inertia;
    // Surface material; reset it to make a sensor (contacts and events, no contact response).
    std::optional<edyn::material> material{edyn::material{}};
    // The manual's shorthand for material->restitution: when set, it replaces the material's
    // restitution (in [0, 1]); a sensor, which has no material, refuses it.
    std::optional<scalar> restitution;
    // Origin of the body in world space (the centre of mass is offset from it by center_of_mass).
    vector3 position{vector3_zero};
    quaternion orientation{quaternion_identity};
    vector3 linvel{vector3_zero};
    vector3 angvel{vector3_zero};
    // Gravity for this body; empty uses the world's (set_gravity).
    std::optional<vector3> gravity;
    // Empty for an amorphous body, which takes no part in collision detection.
    std::optional<shapes_variant_t> shape;
    std::uint64_t collision_group{~std::uint64_t(0)};
    std::uint64_t collision_mask{~std::uint64_t(0)};
    // Offset of the centre of mass from the origin in object space; the shape's centroid when
    // empty.
    std::optional<vector3> center_of_mass;
    // Keeps the body's island from ever sleeping.
    bool sleeping_disabled{false};
};

} // namespace edyn

#endif // EDYN_DYNAMICS_RIGIDBODY_DEF_HPP
