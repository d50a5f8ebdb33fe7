#ifndef EDYN_DYNAMICS_TAGS_HPP
#define EDYN_DYNAMICS_TAGS_HPP

namespace edyn {

/// Component: marks a rigid body.
/// Every rigid body has rigidbody_tag and exactly one of dynamic_tag, static_tag,
/// kinematic_tag. make_rigidbody emplaces it last and clear_rigidbody removes it first, so that
/// its listeners see a complete body.
struct rigidbody_tag {};
/// Component: marks a dynamic body (rigidbody_kind::rb_dynamic), moved by the simulation.
struct dynamic_tag {};
/// Component: marks a static body (rigidbody_kind::rb_static), which never moves.
struct static_tag {};
/// Component: marks a kinematic body (rigidbody_kind::rb_kinematic), moved by the program.
struct kinematic_tag {};
/// Component: on every entity of a sleeping island (the island, its bodies and its edges).
/// Written by the engine: sleeping bodies are skipped by the step until something wakes them.
struct sleeping_tag {};
/// Component: keeps the body's island awake.
/// Emplaced by make_rigidbody when rigidbody_def::sleeping_disabled is set.
struct sleeping_disabled_tag {};
/// Component: a body without a contact response: collisions are detected and reported, not
/// resolved.
/// Emplaced by make_rigidbody when rigidbody_def::material is empty; such a body has no
/// material component.
struct sensor_tag {};

} // namespace edyn

#endif // EDYN_DYNAMICS_TAGS_HPP
