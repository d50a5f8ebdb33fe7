#ifndef EDYN_SHAPES_MOMENT_OF_INERTIA_HPP
#define EDYN_SHAPES_MOMENT_OF_INERTIA_HPP

#include "edyn/math/matrix3x3.hpp"
#include "edyn/shapes/shapes.hpp"
#include <stdexcept>
#include <type_traits>

namespace edyn {

/// Inertia tensor of a solid sphere of uniform density about its centre: 2/5 m r² on the
/// diagonal.
/// @param mass Mass (kg).
/// @param radius Radius (m), positive and finite.
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia_solid_sphere, when `mass` or `radius`
///         is not positive and finite.
matrix3x3 moment_of_inertia_solid_sphere(scalar mass, scalar radius);
/// Inertia tensor of a solid box of uniform density about its centre: m/3 (h_y² + h_z²) about
/// x, and likewise about y and z, from the half extents h.
/// @param mass Mass (kg).
/// @param half_extents Half of the box's size along each axis (m), each positive and finite.
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia_solid_box, when `mass` or a half
///         extent is not positive and finite.
matrix3x3 moment_of_inertia_solid_box(scalar mass, const vector3 &half_extents);
/// Inertia tensor of a solid cylinder of uniform density about its centre: m r² / 2 about its
/// axis, m (3 r² + 4 h²) / 12 across it.
/// @param mass Mass (kg).
/// @param radius Radius r (m), positive and finite.
/// @param half_length Half length h (m), positive and finite.
/// @param axis The cylinder's main axis.
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia_solid_cylinder, when `mass`, `radius`
///         or `half_length` is not positive and finite.
matrix3x3 moment_of_inertia_solid_cylinder(scalar mass, scalar radius, scalar half_length,
                                           coordinate_axis axis);
/// Inertia tensor of a solid capsule of uniform density about its centre: the cylindrical part
/// plus two exact hemispheres, the mass shared in proportion to their volumes.
/// @param mass Mass (kg).
/// @param radius Radius (m), positive and finite.
/// @param half_length Half length of the cylindrical part (m), positive and finite.
/// @param axis The capsule's main axis.
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia_solid_capsule, when `mass`, `radius`
///         or `half_length` is not positive and finite.
matrix3x3 moment_of_inertia_solid_capsule(scalar mass, scalar radius, scalar half_length,
                                          coordinate_axis axis);

/// Volume of a plane (m³).
///
/// Infinite, as for every static-only shape.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const plane_shape &shape);
/// Volume of a sphere (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const sphere_shape &shape);
/// Volume of a box (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const box_shape &shape);
/// Volume of a cylinder (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const cylinder_shape &shape);
/// Volume of a capsule (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const capsule_shape &shape);
/// Volume of a polyhedron (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const polyhedron_shape &shape);
/// Volume of a compound (m³).
///
/// The sum of its children's volumes; overlapping children count their common volume twice.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const compound_shape &shape);
/// Volume of any shape a compound can hold (m³).
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const compound_child_shape_t &shape);
/// Volume of a triangle mesh (m³).
///
/// Infinite, as for every static-only shape.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const mesh_shape &shape);
/// Volume of a paged triangle mesh (m³).
///
/// Infinite, as for every static-only shape.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³).
scalar shape_volume(const paged_mesh_shape &shape);

/// Volume of a solid shape of uniform density, whatever its type.
///
/// Shapes are assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The volume (m³); infinity for planes and meshes, which are static only.
template<shapes_variant Variant>
scalar shape_volume(const Variant &shape) {
    return std::visit([](const auto &s) { return shape_volume(s); }, shape);
}

/// Centre of volume of a plane, in its object space.
///
/// The origin: static-only shapes have no centre of volume.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const plane_shape &shape);
/// Centre of volume of a sphere, in its object space.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const sphere_shape &shape);
/// Centre of volume of a box, in its object space.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const box_shape &shape);
/// Centre of volume of a cylinder, in its object space.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const cylinder_shape &shape);
/// Centre of volume of a capsule, in its object space.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const capsule_shape &shape);
/// Centre of volume of a polyhedron, in its object space.
///
/// Exact, over a tetrahedral decomposition of its faces; not necessarily the origin.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const polyhedron_shape &shape);
/// Centre of volume of a compound, in its object space.
///
/// The volume-weighted mean of its children's centroids (in the compound's object space).
/// Precondition: at least one child.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const compound_shape &shape);
/// Centre of volume of any shape a compound can hold, in its object space.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const compound_child_shape_t &shape);
/// Centre of volume of a triangle mesh, in its object space.
///
/// The origin: static-only shapes have no centre of volume.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const mesh_shape &shape);
/// Centre of volume of a paged triangle mesh, in its object space.
///
/// The origin: static-only shapes have no centre of volume.
///
/// The shape is assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
vector3 shape_centroid(const paged_mesh_shape &shape);

/// Centre of volume of a shape in its object space, whatever its type: the origin for the
/// symmetric shapes and for the static-only ones (planes, meshes).
///
/// Shapes are assumed valid (see validate_shape()); nothing is checked.
/// @param shape The shape.
/// @return The centroid in object space (m).
template<shapes_variant Variant>
vector3 shape_centroid(const Variant &shape) {
    return std::visit([](const auto &s) { return shape_centroid(s); }, shape);
}

/// Inertia tensor of a sphere of uniform density about its centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const sphere_shape &shape, scalar mass);
/// Inertia tensor of a box of uniform density about its centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const box_shape &shape, scalar mass);
/// Inertia tensor of a cylinder of uniform density about its centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const cylinder_shape &shape, scalar mass);
/// Inertia tensor of a capsule of uniform density about its centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const capsule_shape &shape, scalar mass);
/// Inertia tensor of a polyhedron of uniform density about its centroid.
///
/// Summed exactly over a tetrahedral decomposition of the faces.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const polyhedron_shape &shape, scalar mass);
/// Inertia tensor of a compound of uniform density about its centroid.
///
/// Each child gets a share of the mass proportional to its volume (overlapping children count their
/// common volume twice); the tensor is about the compound's centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const compound_shape &shape, scalar mass);
/// Inertia tensor of any shape a compound can hold of uniform density about its centroid.
///
/// The tensor is in the axes of the shape's object space; the shape is assumed valid (see
/// validate_shape()).
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and
///         finite.
matrix3x3 moment_of_inertia(const compound_child_shape_t &shape, scalar mass);

/// Inertia tensor of a solid shape of uniform density about its centroid (shape_centroid()), in
/// the axes of its object space, whatever its type.
///
/// Shapes are assumed valid (see validate_shape()). make_rigidbody() uses it when no inertia is
/// given.
/// @param shape The shape.
/// @param mass Its mass (kg).
/// @return The tensor (kg·m²).
/// @throws std::invalid_argument Naming moment_of_inertia, when `mass` is not positive and finite,
///         or for a shape that can only be static (plane, mesh), which has no inertia.
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

/// Moves an inertia tensor from the centre of mass to another point by the parallel-axis
/// theorem: inertia + mass (|offset|² E - offset offsetᵀ).
///
/// Used when the centre of mass is shifted (see set_center_of_mass()).
/// @param inertia Inertia tensor about the centre of mass (kg·m²).
/// @param mass The mass (kg), finite and not negative.
/// @param offset Position of the new reference point relative to the centre of mass, in the
///        tensor's axes (m); finite.
/// @return The inertia tensor about that point (kg·m²).
/// @throws std::invalid_argument Naming shift_moment_of_inertia, when `mass` is negative or not
///         finite, or `offset` is not finite.
matrix3x3 shift_moment_of_inertia(const matrix3x3 &inertia, scalar mass, const vector3 &offset);

/// Checks a mass given by the user.
/// @param mass The mass (kg).
/// @param function Name of the calling function, put at the start of the message.
/// @throws std::invalid_argument "<function>: mass must be positive and finite, got <mass>", when
///         `mass` is zero, negative, infinite or NaN.
void validate_mass(scalar mass, const char *function = "moment_of_inertia");

} // namespace edyn

#endif // EDYN_SHAPES_MOMENT_OF_INERTIA_HPP
