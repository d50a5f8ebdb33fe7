#ifndef EDYN_SHAPES_MOMENT_OF_INERTIA_HPP
#define EDYN_SHAPES_MOMENT_OF_INERTIA_HPP

#include "edyn/math/matrix3x3.hpp"
#include "edyn/shapes/shapes.hpp"
#include <stdexcept>
#include <type_traits>

namespace edyn {

// Mass properties of solid shapes of uniform density, in the shape's object space.
//
// Compounds give each child a share of the mass proportional to its volume; overlapping
// children count their common volume twice. Planes are static only: shape_volume gives
// infinity, shape_centroid the origin and moment_of_inertia throws. Shapes are assumed valid
// (see validate_shape).

// Closed forms about the centre (r radius, h half length, axis along coordinate axis i).
// Sphere: 2/5 m r^2. Box: m/3 (h_y^2 + h_z^2) etc. from half extents. Cylinder: m r^2 / 2 about
// its axis, m (3 r^2 + 4 h^2) / 12 across. Capsule: cylinder part plus two exact hemispheres.
matrix3x3 moment_of_inertia_solid_sphere(scalar mass, scalar radius);
matrix3x3 moment_of_inertia_solid_box(scalar mass, const vector3 &half_extents);
matrix3x3 moment_of_inertia_solid_cylinder(scalar mass, scalar radius, scalar half_length,
                                           coordinate_axis axis);
matrix3x3 moment_of_inertia_solid_capsule(scalar mass, scalar radius, scalar half_length,
                                          coordinate_axis axis);

scalar shape_volume(const plane_shape &shape);
scalar shape_volume(const sphere_shape &shape);
scalar shape_volume(const box_shape &shape);
scalar shape_volume(const cylinder_shape &shape);
scalar shape_volume(const capsule_shape &shape);
scalar shape_volume(const polyhedron_shape &shape);
scalar shape_volume(const compound_shape &shape);
scalar shape_volume(const compound_child_shape_t &shape);
// Planes and meshes: infinite, as static-only shapes.
scalar shape_volume(const mesh_shape &shape);
scalar shape_volume(const paged_mesh_shape &shape);

template<shapes_variant Variant>
scalar shape_volume(const Variant &shape) {
    return std::visit([](const auto &s) { return shape_volume(s); }, shape);
}

// Centre of volume in object space: the origin for the symmetric shapes.
vector3 shape_centroid(const plane_shape &shape);
vector3 shape_centroid(const sphere_shape &shape);
vector3 shape_centroid(const box_shape &shape);
vector3 shape_centroid(const cylinder_shape &shape);
vector3 shape_centroid(const capsule_shape &shape);
vector3 shape_centroid(const polyhedron_shape &shape);
vector3 shape_centroid(const compound_shape &shape);
vector3 shape_centroid(const compound_child_shape_t &shape);
vector3 shape_centroid(const mesh_shape &shape);
vector3 shape_centroid(const paged_mesh_shape &shape);

template<shapes_variant Variant>
vector3 shape_centroid(const Variant &shape) {
    return std::visit([](const auto &s) { return shape_centroid(s); }, shape);
}

// Inertia tensor about the shape's centroid (shape_centroid), axes of the object space. Throws
// std::invalid_argument naming moment_of_inertia when mass is not positive and finite, or for a
// plane. Polyhedra are summed exactly over a tetrahedral decomposition of their faces.
matrix3x3 moment_of_inertia(const sphere_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const box_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const cylinder_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const capsule_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const polyhedron_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const compound_shape &shape, scalar mass);
matrix3x3 moment_of_inertia(const compound_child_shape_t &shape, scalar mass);

// Throws std::invalid_argument for shapes that can only be static (plane, mesh).
template<shapes_variant Variant>
matrix3x3 moment_of_inertia(const Variant &shape, scalar mass) {
    return std::visit(
        [mass](const auto &s) -> matrix3x3 {
            using shape_type = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<shape_type, compound_shape> ||
                          std::is_constructible_v<compound_child_shape_t, shape_type>) {
                return moment_of_inertia(s, mass);
            } else {
                throw std::invalid_argument("moment_of_inertia: the shape can only be static (plane or "
                                            "mesh) and has no inertia");
            }
        },
        shape);
}

// Parallel-axis theorem: the inertia about the point at `offset` from the centre of mass, given
// the inertia about the centre of mass: inertia + mass (|offset|^2 E - offset offset^T).
matrix3x3 shift_moment_of_inertia(const matrix3x3 &inertia, scalar mass, const vector3 &offset);

// Throws std::invalid_argument "<function>: mass must be positive and finite, got <mass>".
void validate_mass(scalar mass, const char *function = "moment_of_inertia");

} // namespace edyn

#endif // EDYN_SHAPES_MOMENT_OF_INERTIA_HPP
