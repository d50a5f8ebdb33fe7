#ifndef EDYN_SHAPES_PLANE_SHAPE_HPP
#define EDYN_SHAPES_PLANE_SHAPE_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

/// Infinite plane of the points p with dot(normal, p) == constant; solid behind the normal.
///
/// For static bodies only; it ignores the body's position and orientation (the plane is given
/// in world space), has no volume or inertia, and collides with every shape but planes and
/// meshes. E.g. `plane_shape{{0, 1, 0}, 0}` is a ground at y = 0 facing up.
struct plane_shape {
    /// Unit normal pointing out of the solid, in world space; it is not normalised for you.
    vector3 normal;
    /// Signed distance of the plane from the world origin along `normal` (m).
    scalar constant;
};

} // namespace edyn

#endif // EDYN_SHAPES_PLANE_SHAPE_HPP
