#ifndef EDYN_SHAPES_CONVEX_MESH_HPP
#define EDYN_SHAPES_CONVEX_MESH_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

// Closed convex polyhedral surface in object space: the geometry of a polyhedron_shape.
//
// Faces are convex polygons whose vertices run counter-clockwise seen from outside. Feature
// indices (polyhedron_feature in collision results, face_index in raycasts) index these arrays:
// a vertex is an index into `vertices`, an edge an index into `edges` (and `edge_faces`), a face
// an index into `faces` (and `normals`, `plane_constants`).
struct convex_mesh {
    // The vertices of face f are indices[faces[f].first] .. indices[faces[f].first + faces[f].count - 1].
    struct face_range {
        std::uint32_t first;
        std::uint32_t count;

        constexpr bool operator==(const face_range &) const noexcept = default;
    };

    std::vector<vector3> vertices;
    // Vertex indices of every face, face after face.
    std::vector<std::uint32_t> indices;
    std::vector<face_range> faces;

    // Derived data, filled by make_convex_mesh() / update_convex_mesh_features().

    // Outward unit normal of each face (Newell's method, robust for polygons).
    std::vector<vector3> normals;
    // Points p of face f satisfy dot(normals[f], p) == plane_constants[f]; the solid lies behind.
    std::vector<scalar> plane_constants;
    // Unique edges as vertex pairs. The edge runs edges[e][0] -> edges[e][1] in face
    // edge_faces[e][0] (counter-clockwise order) and the other way in face edge_faces[e][1].
    std::vector<std::array<std::uint32_t, 2>> edges;
    std::vector<std::array<std::uint32_t, 2>> edge_faces;
    // Unit edge directions with parallel edges (either sense) kept once: the candidate axes
    // edge x edge of SAT. A cube has three.
    std::vector<vector3> unique_edge_directions;
    // Largest distance of a vertex from the object-space origin.
    scalar bounding_radius{0};

    std::size_t num_vertices() const noexcept { return vertices.size(); }
    std::size_t num_faces() const noexcept { return faces.size(); }
    std::size_t num_edges() const noexcept { return edges.size(); }

    std::span<const std::uint32_t> face_indices(std::size_t face) const noexcept {
        EDYN_ASSERT(face < faces.size());
        return {indices.data() + faces[face].first, faces[face].count};
    }

    const vector3 &face_vertex(std::size_t face, std::size_t i) const noexcept {
        EDYN_ASSERT(face < faces.size() && i < faces[face].count);
        return vertices[indices[faces[face].first + i]];
    }

    // Index of the vertex farthest along `dir` (the lowest index on ties).
    std::size_t support_vertex(const vector3 &dir) const noexcept {
        EDYN_ASSERT(!vertices.empty());
        std::size_t best = 0;
        auto best_proj = dot(vertices[0], dir);
        for (std::size_t i = 1; i < vertices.size(); ++i) {
            auto proj = dot(vertices[i], dir);
            if (proj > best_proj) {
                best_proj = proj;
                best = i;
            }
        }
        return best;
    }
};

// Builds a mesh from vertices and faces given as lists of vertex indices (counter-clockwise
// seen from outside), validates it (see validate_convex_mesh) and fills the derived data.
// Throws std::invalid_argument naming polyhedron_shape, the field and the value.
convex_mesh make_convex_mesh(std::vector<vector3> vertices,
                             const std::vector<std::vector<std::uint32_t>> &faces);

// Checks a mesh: at least 4 vertices, all finite and all used by some face; at least 4 faces of
// 3 or more distinct in-range vertices each; every face planar and of non-zero area; every
// edge shared by exactly two faces that traverse it in opposite senses (closed surface,
// consistent winding); positive volume (counter-clockwise winding) above degeneracy; convex (no
// vertex in front of any face plane); derived arrays of matching sizes. Tolerances are relative
// to the mesh's size (see convex_mesh_tolerance). Throws std::invalid_argument naming
// polyhedron_shape, the field and the value.
void validate_convex_mesh(const convex_mesh &mesh);

// Distance tolerance used by validate_convex_mesh for planarity and convexity: 1e-5 of the
// mesh's largest extent, or 16 scalar epsilons of its largest absolute coordinate when larger
// (above the merging tolerance of convex_hull, so that hulls always validate).
scalar convex_mesh_tolerance(std::span<const vector3> vertices) noexcept;

// Recomputes normals, plane_constants, edges, edge_faces, unique_edge_directions and
// bounding_radius from vertices, indices and faces. Precondition: the mesh passes validation
// except for the derived arrays.
void update_convex_mesh_features(convex_mesh &mesh);

} // namespace edyn

#endif // EDYN_SHAPES_CONVEX_MESH_HPP
