#include "edyn/shapes/shape_bounding_radius.hpp"
#include "edyn/math/scalar.hpp"
#include <cmath>

namespace edyn {

scalar shape_bounding_radius(const sphere_shape &shape) { return shape.radius; }

scalar shape_bounding_radius(const box_shape &shape) { return length(shape.half_extents); }

scalar shape_bounding_radius(const capsule_shape &shape) { return shape.half_length + shape.radius; }

// The rim of a cap is the farthest.
scalar shape_bounding_radius(const cylinder_shape &shape) {
    return std::sqrt(shape.radius * shape.radius + shape.half_length * shape.half_length);
}

scalar shape_bounding_radius(const polyhedron_shape &shape) {
    return shape.mesh ? shape.mesh->bounding_radius : large_scalar;
}

// A compound's bound would cost a pass over its children at every call: none is given.
scalar shape_bounding_radius(const compound_shape &) { return large_scalar; }

scalar shape_bounding_radius(const plane_shape &) { return large_scalar; }

scalar shape_bounding_radius(const mesh_shape &) { return large_scalar; }

scalar shape_bounding_radius(const paged_mesh_shape &) { return large_scalar; }

} // namespace edyn
