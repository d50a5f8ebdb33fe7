#ifndef EDYN_COLLISION_COLLISION_FEATURE_HPP
#define EDYN_COLLISION_COLLISION_FEATURE_HPP

#include <cstdint>
#include <variant>

namespace edyn {

/// Kind of feature of a box_shape that a collision point lies on.
///
/// The index that goes with it (collision_feature::index) numbers the vertices 0..7, edges 0..11
/// and faces 0..5 as described at box_shape (face 2 is the upper face, +y).
enum class box_feature : std::uint8_t {
    vertex, ///< A corner; the index is the vertex number 0..7.
    edge,   ///< An edge; the index is the edge number 0..11.
    face    ///< A face; the index is 0..5 for +x, -x, +y, -y, +z, -z.
};

/// Kind of feature of a cylinder_shape that a collision point or a ray hit lies on.
enum class cylinder_feature : std::uint8_t {
    face,     ///< A flat cap; index 0 is the cap at +half_length, 1 the one at -half_length.
    cap_edge, ///< The circular rim of a cap; index as for `face`.
    side_edge ///< The curved side surface (a line along the axis); index 0.
};

/// Kind of feature of a capsule_shape that a collision point or a ray hit lies on.
enum class capsule_feature : std::uint8_t {
    hemisphere, ///< A rounded end; index 0 at +half_length, 1 at -half_length.
    side        ///< The cylindrical side between the hemispheres; index 0.
};

/// Kind of feature of a triangle of a triangle_mesh that a collision point lies on.
///
/// The triangle itself is given by collision_feature::part.
enum class triangle_feature : std::uint8_t {
    vertex, ///< A corner; the index is the vertex 0..2 within the triangle.
    edge,   ///< An edge; the index i names the edge from vertex i to vertex (i + 1) % 3.
    face    ///< The triangle's face; index 0.
};

/// Kind of feature of a polyhedron_shape that a collision point lies on.
///
/// The index refers to the arrays of the shape's convex_mesh (`vertices`, `edges`, `faces`).
enum class polyhedron_feature : std::uint8_t {
    vertex, ///< A vertex; the index is into convex_mesh::vertices.
    edge,   ///< An edge; the index is into convex_mesh::edges.
    face    ///< A face; the index is into convex_mesh::faces.
};

/// The closest feature of a shape in a collision point, e.g. `{box_feature::face, 2}` for a box's
/// upper face.
///
/// Filled by collide() where the closest-point routine finds it without extra work (see
/// collision_result::collision_point::featureA); copied into contact_point::featureA and
/// contact_point::featureB by the narrowphase. Index meanings are documented next to each shape
/// and feature enumeration.
struct collision_feature {
    /// Which kind of feature: one of the per-shape feature enumerations, or `std::monostate` when
    /// only `part` is known (e.g. a compound child whose own pair reports no feature).
    std::variant<std::monostate, box_feature, cylinder_feature, capsule_feature, triangle_feature,
                 polyhedron_feature>
        feature;
    /// Number of the vertex, edge or face within its shape (or triangle); 0 by default.
    std::uint32_t index{0};
    /// Child shape of a compound, or triangle of a mesh, the feature belongs to; -1 when none.
    std::int32_t part{-1};

    /// Two features are equal when their kind, index and part are all equal.
    bool operator==(const collision_feature &) const = default;
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_FEATURE_HPP
