#ifndef EDYN_DYNAMICS_TAGS_HPP
#define EDYN_DYNAMICS_TAGS_HPP

namespace edyn {

// Every rigid body has rigidbody_tag and exactly one of dynamic_tag, static_tag, kinematic_tag.
struct rigidbody_tag {};
struct dynamic_tag {};
struct static_tag {};
struct kinematic_tag {};
// On every entity of a sleeping island.
struct sleeping_tag {};
// Keeps the body's island awake.
struct sleeping_disabled_tag {};
// A body without a contact response: collisions are detected and reported, not resolved.
struct sensor_tag {};

} // namespace edyn

#endif // EDYN_DYNAMICS_TAGS_HPP
