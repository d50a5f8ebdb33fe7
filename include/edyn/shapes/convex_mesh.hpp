#ifndef EDYN_SHAPES_CONVEX_MESH_HPP
#define EDYN_SHAPES_CONVEX_MESH_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// Closed convex polyhedral surface in object space: the geometry of a polyhedron_shape.
///
/// Faces are convex polygons whose vertices run counter-clockwise seen from outside. Feature
/// indices (polyhedron_feature in collision results, face_index in raycasts) index these arrays:
/// a vertex is an index into `vertices`, an edge an index into `edges` (and `edge_faces`), a face
/// an index into `faces` (and `normals`, `plane_constants`). Build one with make_convex_mesh() or
/// convex_hull(); the data after the first three arrays is derived from them.
struct convex_mesh {
    /// Where a face's vertex indices lie in `indices`: the vertices of face f are
    /// indices[faces[f].first] .. indices[faces[f].first + faces[f].count - 1].
    struct face_range {
        std::uint32_t first; ///< Position of the face's first vertex index in `indices`.
        std::uint32_t count; ///< Number of vertices of the face (at least 3).

        /// Two ranges are equal when both members are.
        constexpr bool operator==(const face_range &) const noexcept = default;
    };

    /// Vertex positions in object space (m).
    std::vector<vector3> vertices;
    /// Vertex indices of every face, face after face.
    std::vector<std::uint32_t> indices;
    /// One range of `indices` per face.
    std::vector<face_range> faces;

    /// Outward unit normal of each face (Newell's method, robust for polygons). Derived, as the
    /// members below, by make_convex_mesh() / update_convex_mesh_features().
    std::vector<vector3> normals;
    /// Plane constant of each face (m): points p of face f satisfy
    /// dot(normals[f], p) == plane_constants[f]; the solid lies behind.
    std::vector<scalar> plane_constants;
    /// Unique edges as vertex pairs. The edge runs edges[e][0] -> edges[e][1] in face
    /// edge_faces[e][0] (counter-clockwise order) and the other way in face edge_faces[e][1].
    std::vector<std::array<std::uint32_t, 2>> edges;
    /// The two faces adjacent to each edge, in the order described at `edges`.
    std::vector<std::array<std::uint32_t, 2>> edge_faces;
    /// Unit edge directions with parallel edges (either sense) kept once: the candidate axes
    /// edge x edge of SAT. A cube has three.
    std::vector<vector3> unique_edge_directions;
    /// Largest distance of a vertex from the object-space origin (m).
    scalar bounding_radius{0};

    /// Number of vertices.
    std::size_t num_vertices() const noexcept { return vertices.size(); }
    /// Number of faces.
    std::size_t num_faces() const noexcept { return faces.size(); }
    /// Number of unique edges (derived data).
    std::size_t num_edges() const noexcept { return edges.size(); }

    /// The vertex indices of a face, counter-clockwise seen from outside.
    /// @param face Index of the face (checked in debug builds only).
    /// @return A view into `indices`.
    std::span<const std::uint32_t> face_indices(std::size_t face) const noexcept {
        EDYN_ASSERT(face < faces.size());
        return {indices.data() + faces[face].first, faces[face].count};
    }

    /// The i-th vertex of a face.
    /// @param face Index of the face.
    /// @param i Position of the vertex in the face, below the face's count (both checked in debug
    ///        builds only).
    /// @return The vertex position in object space (m).
    const vector3 &face_vertex(std::size_t face, std::size_t i) const noexcept {
        EDYN_ASSERT(face < faces.size() && i < faces[face].count);
        return vertices[indices[faces[face].first + i]];
    }

    /// Index of the vertex farthest along `dir` (the lowest index on ties).
    /// @param dir Direction in object space; need not be unit length.
    /// @return Index into `vertices`; the mesh must not be empty.
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

/// Builds a mesh from vertices and faces given as lists of vertex indices (counter-clockwise
/// seen from outside), validates it (see validate_convex_mesh()) and fills the derived data.
/// @param vertices Vertex positions in object space (m).
/// @param faces One list of indices into `vertices` per face.
/// @return The complete mesh.
/// @throws std::invalid_argument Naming polyhedron_shape, the field and the value, when the
///         geometry fails the checks of validate_convex_mesh().
convex_mesh make_convex_mesh(std::vector<vector3> vertices,
                             const std::vector<std::vector<std::uint32_t>> &faces);

/// Checks a mesh, e.g. one that came from a file or the network.
///
/// Requires at least 4 vertices, all finite and all used by some face; at least 4 faces of
/// 3 or more distinct in-range vertices each; every face planar and of non-zero area; every
/// edge shared by exactly two faces that traverse it in opposite senses (closed surface,
/// consistent winding); positive volume (counter-clockwise winding) above degeneracy; convex (no
/// vertex in front of any face plane); derived arrays of matching sizes, with normals and plane
/// constants that match the faces. Tolerances are relative to the mesh's size (see
/// convex_mesh_tolerance()).
/// @param mesh The mesh to check.
/// @throws std::invalid_argument Naming polyhedron_shape, the field and the value, for the first
///         check that fails.
void validate_convex_mesh(const convex_mesh &mesh);

/// Distance tolerance used by validate_convex_mesh() for planarity and convexity.
///
/// 1e-5 of the mesh's largest extent, or 16 scalar epsilons of its largest absolute coordinate
/// when larger (above the merging tolerance of convex_hull(), so that hulls always validate).
/// @param vertices The mesh's vertices (m).
/// @return The tolerance (m).
scalar convex_mesh_tolerance(std::span<const vector3> vertices) noexcept;

/// Recomputes normals, plane_constants, edges, edge_faces, unique_edge_directions and
/// bounding_radius from vertices, indices and faces.
/// @param mesh The mesh to complete. Precondition: it passes validation except for the derived
///        arrays (not checked).
void update_convex_mesh_features(convex_mesh &mesh);

} // namespace edyn

#endif // EDYN_SHAPES_CONVEX_MESH_HPP
