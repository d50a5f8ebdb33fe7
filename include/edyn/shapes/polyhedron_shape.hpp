#ifndef EDYN_SHAPES_POLYHEDRON_SHAPE_HPP
#define EDYN_SHAPES_POLYHEDRON_SHAPE_HPP

#include "edyn/shapes/convex_mesh.hpp"
#include <cstdint>
#include <memory>
#include <vector>

namespace edyn {

/// Convex polyhedron, a shape for rigid bodies of any kind.
///
/// The geometry is immutable and shared, so copying the shape (into a component, across
/// threads, into a compound) copies a pointer.
///
/// Features (polyhedron_feature in collision results, polyhedron_raycast_info::face_index):
/// vertex i is mesh->vertices[i], edge i is mesh->edges[i] (adjacent faces mesh->edge_faces[i]),
/// face i is mesh->faces[i] with normal mesh->normals[i]. All in object space.
struct polyhedron_shape {
    /// The shared, immutable geometry in object space (m); null for a default-constructed shape.
    std::shared_ptr<const convex_mesh> mesh;

    /// No geometry (mesh is null), e.g. to assign to later; validate_shape() rejects it.
    polyhedron_shape() = default;

    /// Convex hull of `points` (see convex_hull()): interior, duplicate and coplanar points are
    /// discarded and coplanar triangles merged into polygons.
    /// @param points The point cloud in object space (m).
    /// @throws std::invalid_argument Naming polyhedron_shape, for non-finite points or points that
    ///         do not span a volume (fewer than 4, or all coincident, collinear or coplanar).
    explicit polyhedron_shape(const std::vector<vector3> &points);

    /// Explicit vertices and faces, each face a list of vertex indices counter-clockwise seen from
    /// outside (see make_convex_mesh()).
    /// @param vertices The vertices in object space (m).
    /// @param faces One list of indices into `vertices` per face.
    /// @throws std::invalid_argument Naming polyhedron_shape, the field and the value when the mesh
    ///         is not a closed, consistently wound, convex polyhedron with planar faces (see
    ///         validate_convex_mesh()).
    polyhedron_shape(std::vector<vector3> vertices, const std::vector<std::vector<std::uint32_t>> &faces);

    /// Shares an existing mesh, e.g. one held by another shape.
    /// @param mesh A mesh that passes validate_convex_mesh() (not checked here; validate_shape()
    ///        checks it when the shape is given to a body).
    explicit polyhedron_shape(std::shared_ptr<const convex_mesh> mesh)
        : mesh(std::move(mesh)) {}
};

} // namespace edyn

#endif // EDYN_SHAPES_POLYHEDRON_SHAPE_HPP
