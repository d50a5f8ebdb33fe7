#ifndef EDYN_SCENES_SRC_STATIC_BOX_HPP
#define EDYN_SCENES_SRC_STATIC_BOX_HPP

#include "edyn/edyn.hpp"

// A fixed box for the scenes' floors, walls, rails and posts. Private to scenes/src.
namespace edyn::scenes::detail {

inline entity make_static_box(registry &registry, const vector3 &half_extents, const vector3 &position,
                              scalar friction, scalar restitution = 0) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = box_shape{half_extents};
    def.position = position;
    def.material->friction = friction;
    def.material->restitution = restitution;
    return make_rigidbody(registry, def);
}

} // namespace edyn::scenes::detail

#endif // EDYN_SCENES_SRC_STATIC_BOX_HPP
