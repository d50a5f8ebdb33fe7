#ifndef EDYN_SHAPES_POLYHEDRON_SHAPE_HPP
#define EDYN_SHAPES_POLYHEDRON_SHAPE_HPP

#include "edyn/shapes/convex_mesh.hpp"
#include <cstdint>
#include <memory>
#include <vector>

namespace edyn {

// Convex polyhedron. The geometry is immutable and shared, so copying the shape (into a
// component, across threads, into a compound) copies a pointer.
//
// Features (polyhedron_feature in collision results, polyhedron_raycast_info::face_index):
// vertex i is mesh->vertices[i], edge i is mesh->edges[i] (adjacent faces mesh->edge_faces[i]),
// face i is mesh->faces[i] with normal mesh->normals[i]. All in object space.
struct polyhedron_shape {
    std::shared_ptr<const convex_mesh> mesh;

    // No geometry (mesh is null), e.g. to assign to later; validate_shape rejects it.
    polyhedron_shape() = default;

    // Convex hull of `points` (see convex_hull()): interior, duplicate and coplanar points are
    // discarded and coplanar triangles merged into polygons. Throws std::invalid_argument naming
    // polyhedron_shape for non-finite points or points that do not span a volume.
    explicit polyhedron_shape(const std::vector<vector3> &points);

    // Explicit vertices and faces, each face a list of vertex indices counter-clockwise seen from
    // outside. Throws std::invalid_argument naming polyhedron_shape, the field and the value when
    // the mesh is not a closed, consistently wound, convex polyhedron with planar faces (see
    // validate_convex_mesh).
    polyhedron_shape(std::vector<vector3> vertices, const std::vector<std::vector<std::uint32_t>> &faces);

    // Shares an existing mesh. Precondition: `mesh` passes validate_convex_mesh.
    explicit polyhedron_shape(std::shared_ptr<const convex_mesh> mesh)
        : mesh(std::move(mesh)) {}
};

} // namespace edyn

#endif // EDYN_SHAPES_POLYHEDRON_SHAPE_HPP
