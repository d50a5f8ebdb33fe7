#ifndef EDYN_SHAPES_TRIANGLE_MESH_HPP
#define EDYN_SHAPES_TRIANGLE_MESH_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/static_tree.hpp"
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// A concave surface made of triangles, for static (and kinematic) bodies such as terrain: the
/// geometry of a mesh_shape.
///
/// Fill it with insert_vertices() and insert_indices() (and optionally
/// per-vertex friction and restitution), then call initialize() once; after that it is read-only
/// and may be shared by any number of shapes and threads.
///
/// Triangles are one-sided: their vertices run counter-clockwise seen from the front, and bodies
/// are pushed out through the front. Each triangle collides as the top of a solid prism as deep as
/// its longest edge, whose sides under the mesh's open edges push away what comes beside them
/// below the surface. Each edge is classified by initialize(): an edge shared with a
/// triangle that lies flat or concave with this one is inactive, so that a body sliding from one
/// triangle onto the next never catches on the edge between them (contact normals on an inactive
/// edge or vertex are replaced by the triangle's normal); convex edges sharper than
/// active_edge_cosine and edges on the boundary stay active.
///
/// Features in collision results: collision_feature{triangle_feature::face|edge|vertex, i, t},
/// with `part` the triangle index t, `index` the vertex (0..2) or the edge (edge i runs from vertex
/// i to vertex (i + 1) % 3) within the triangle.
class triangle_mesh {
public:
    /// Edges whose adjacent triangles' normals have a cosine above this are inactive even when
    /// convex (an angle of about 5 degrees).
    static constexpr scalar active_edge_cosine = scalar(0.996);

    /// Appends vertices, before initialize().
    /// @param first Start of a range of vector3, in the mesh's object space (m).
    /// @param last End of the range.
    /// @throws std::invalid_argument Naming the function and the vertex, when one is not finite;
    ///         naming the function, when the mesh is initialized (read-only, perhaps shared by
    ///         other threads). Nothing is appended then.
    template<typename It>
    void insert_vertices(It first, It last) {
        std::vector<vector3> values(first, last);
        append_vertices(values);
    }

    /// Appends vertex indices, three per triangle, counter-clockwise seen from the front, before
    /// initialize(). Whether they are in range is checked by initialize().
    /// @param first Start of a range of integers.
    /// @param last End of the range.
    /// @throws std::invalid_argument Naming the function and the index, when a value is negative or
    ///         not below 2^32 - 1; naming the function, when the mesh is initialized. Nothing is
    ///         appended then.
    template<typename It>
    void insert_indices(It first, It last) {
        std::vector<std::uint64_t> values;
        for (; first != last; ++first) {
            auto v = *first;
            append_index_checked(values, static_cast<long long>(v));
        }
        append_indices(values);
    }

    /// Appends per-vertex friction coefficients, one per vertex in vertex order.
    ///
    /// At a contact they are interpolated over the triangle and then mixed with the other body's
    /// material (a material mixing pair overrides them). initialize() checks that there is one
    /// per vertex.
    /// @param first Start of a range of scalars (dimensionless).
    /// @param last End of the range.
    /// @throws std::invalid_argument Naming the function and the value, when one is negative or not
    ///         finite; naming the function, when the mesh is initialized. Nothing is appended then.
    template<typename It>
    void insert_friction_coefficients(It first, It last) {
        std::vector<scalar> values(first, last);
        append_coefficients(values, friction, "insert_friction_coefficients", large_scalar);
    }

    /// Appends per-vertex restitution coefficients, one per vertex in vertex order, as
    /// insert_friction_coefficients() does.
    /// @param first Start of a range of scalars in [0, 1].
    /// @param last End of the range.
    /// @throws std::invalid_argument Naming the function and the value, when one is negative, not
    ///         finite or above 1; naming the function, when the mesh is initialized. Nothing is
    ///         appended then.
    template<typename It>
    void insert_restitution_coefficients(It first, It last) {
        std::vector<scalar> values(first, last);
        append_coefficients(values, restitution, "insert_restitution_coefficients", scalar(1));
    }

    /// Validates the data and computes triangle normals, edge adjacency and activity, and the
    /// bounding volume tree; afterwards the mesh is read-only.
    ///
    /// Triangles of zero area (below 1e-12 of the squared size of the mesh) are dropped and
    /// counted in num_degenerate_triangles(); the remaining triangles are renumbered in order.
    /// @throws std::invalid_argument Naming triangle_mesh::initialize and the value, for: no
    ///         vertices or no triangles, an index count not a multiple of 3, an index out of range,
    ///         coefficient arrays whose length is not the vertex count, or no triangle left. The
    ///         mesh is unchanged (and not initialized) when it throws.
    void initialize();

    /// As initialize(), with each triangle's edge activity given instead of derived from this mesh
    /// alone: for a page of a larger mesh, whose edges on the page's border are shared with
    /// triangles of other pages.
    /// @param active_edges One entry per triangle; bit i set: edge i is active.
    /// @throws std::invalid_argument As initialize() does, and when a triangle is degenerate or
    ///         the count of flags is not the triangle count.
    void initialize(std::span<const std::uint8_t> active_edges);

    /// Each triangle's active edges (bit i: edge i), as initialize() derived or was given them.
    std::span<const std::uint8_t> get_edge_flags() const noexcept { return edge_flags; }

    /// Whether initialize() has succeeded since the last insertion.
    bool initialized() const noexcept { return is_initialized; }

    /// Number of vertices.
    std::size_t num_vertices() const noexcept { return vertices.size(); }
    /// Number of triangles (after initialize(), those kept).
    std::size_t num_triangles() const noexcept { return indices.size() / 3; }
    /// Number of zero-area triangles that initialize() dropped.
    std::size_t num_degenerate_triangles() const noexcept { return degenerate_count; }

    /// Position of vertex `i` in the mesh's object space (m).
    const vector3 &get_vertex(std::size_t i) const noexcept { return vertices[i]; }
    /// The vertices as inserted (m).
    std::span<const vector3> get_vertices() const noexcept { return vertices; }
    /// The indices as inserted, three per triangle (after initialize(), those of the triangles
    /// kept).
    std::span<const std::uint32_t> get_indices() const noexcept { return indices; }
    /// The per-vertex friction coefficients as inserted; empty when there are none.
    std::span<const scalar> get_friction_coefficients() const noexcept { return friction; }
    /// The per-vertex restitution coefficients as inserted; empty when there are none.
    std::span<const scalar> get_restitution_coefficients() const noexcept { return restitution; }
    /// Index of the i-th vertex (0..2) of a triangle.
    /// @param triangle Index of the triangle.
    /// @param i Vertex of the triangle, 0..2.
    std::uint32_t get_vertex_index(std::size_t triangle, std::size_t i) const noexcept {
        return indices[triangle * 3 + i];
    }
    /// Positions of the triangle's three vertices (m), counter-clockwise seen from the front.
    std::array<vector3, 3> get_triangle_vertices(std::size_t triangle) const noexcept {
        return {vertices[indices[triangle * 3]], vertices[indices[triangle * 3 + 1]],
                vertices[indices[triangle * 3 + 2]]};
    }
    /// Unit normal of the triangle's front. Precondition: initialized().
    const vector3 &get_triangle_normal(std::size_t triangle) const noexcept { return normals[triangle]; }
    /// Whether edge `edge` (0..2) of the triangle is active (see triangle_mesh).
    /// @param triangle Index of the triangle.
    /// @param edge Edge i runs from vertex i to vertex (i + 1) % 3.
    bool is_edge_active(std::size_t triangle, std::size_t edge) const noexcept {
        return (edge_flags[triangle] >> edge) & 1u;
    }
    /// Whether vertex `vertex` (0..2) of the triangle is active: one of the triangle's two edges
    /// through it is.
    /// @param triangle Index of the triangle.
    /// @param vertex Vertex of the triangle, 0..2.
    bool is_vertex_active(std::size_t triangle, std::size_t vertex) const noexcept {
        return is_edge_active(triangle, vertex) || is_edge_active(triangle, (vertex + 2) % 3);
    }
    /// The triangle across edge `edge` (0..2), or -1 on the boundary (or where more than two meet).
    /// @param triangle Index of the triangle.
    /// @param edge Edge i runs from vertex i to vertex (i + 1) % 3.
    std::int64_t get_adjacent_triangle(std::size_t triangle, std::size_t edge) const noexcept {
        auto t = adjacency[triangle * 3 + edge];
        return t == no_triangle ? -1 : std::int64_t(t);
    }

    /// Whether per-vertex friction coefficients were inserted.
    bool has_per_vertex_friction() const noexcept { return !friction.empty(); }
    /// Whether per-vertex restitution coefficients were inserted.
    bool has_per_vertex_restitution() const noexcept { return !restitution.empty(); }
    /// Friction coefficient at barycentric coordinates (w0, w1, w2) of the triangle,
    /// interpolated from its vertices. Precondition: has_per_vertex_friction().
    /// @param triangle Index of the triangle.
    /// @param barycentric Weights of the triangle's vertices 0, 1, 2 (see
    ///        barycentric_coordinates()).
    scalar get_friction(std::size_t triangle, const vector3 &barycentric) const noexcept;
    /// Restitution coefficient at barycentric coordinates of the triangle, interpolated from its
    /// vertices. Precondition: has_per_vertex_restitution().
    /// @param triangle Index of the triangle.
    /// @param barycentric Weights of the triangle's vertices 0, 1, 2.
    scalar get_restitution(std::size_t triangle, const vector3 &barycentric) const noexcept;

    /// Bounds of the whole mesh in its object space. Precondition: initialized().
    const AABB &get_aabb() const noexcept { return tree.root_aabb(); }
    /// Bounds of one triangle in the mesh's object space. Precondition: initialized().
    const AABB &get_triangle_aabb(std::size_t triangle) const noexcept { return triangle_aabbs[triangle]; }

    /// Calls `func(triangle_index)` for every triangle whose AABB overlaps `aabb`, in a fixed
    /// order. Precondition: initialized() (checked in debug builds only).
    /// @param aabb The query box in the mesh's object space (m).
    /// @param func Callable taking a `std::size_t` triangle index.
    template<typename Func>
    void visit_triangles(const AABB &aabb, Func &&func) const {
        EDYN_ASSERT(is_initialized, "triangle_mesh used before initialize()");
        tree.visit([&](const AABB &node) { return intersect(node, aabb); }, func);
    }

    /// Calls `func(triangle_index)` for every triangle whose AABB the segment [p0, p1] touches.
    /// Precondition: initialized() (checked in debug builds only).
    /// @param p0 Start of the segment in the mesh's object space (m).
    /// @param p1 End of the segment (m).
    /// @param func Callable taking a `std::size_t` triangle index.
    template<typename Func>
    void visit_triangles_segment(const vector3 &p0, const vector3 &p1, Func &&func) const {
        EDYN_ASSERT(is_initialized, "triangle_mesh used before initialize()");
        tree.visit([&](const AABB &node) { return intersect_segment(node, p0, p1); }, func);
    }

private:
    static constexpr std::uint32_t no_triangle = ~std::uint32_t(0);

    void initialize_with(const std::span<const std::uint8_t> *given_flags);

    // Inserting into an initialized mesh is refused: it may be shared across threads.
    void check_not_initialized(const char *function) const;
    void append_vertices(const std::vector<vector3> &values);
    static void append_index_checked(std::vector<std::uint64_t> &values, long long value);
    void append_indices(const std::vector<std::uint64_t> &values);
    void append_coefficients(const std::vector<scalar> &values, std::vector<scalar> &target,
                             const char *function, scalar max);

    std::vector<vector3> vertices;
    // Three per triangle, counter-clockwise seen from the front.
    std::vector<std::uint32_t> indices;
    std::vector<scalar> friction;
    std::vector<scalar> restitution;

    // Derived by initialize().
    std::vector<vector3> normals;
    std::vector<std::uint8_t> edge_flags; // Bit i: edge i is active.
    std::vector<std::uint32_t> adjacency; // Three per triangle.
    std::vector<AABB> triangle_aabbs;
    static_tree tree;
    std::size_t degenerate_count{0};
    bool is_initialized{false};
};

/// Barycentric coordinates of p's projection onto the plane of triangle (a, b, c).
/// @param p The point.
/// @param a First vertex of the triangle.
/// @param b Second vertex.
/// @param c Third vertex.
/// @return Weights (w0, w1, w2) of a, b and c, summing to 1.
vector3 barycentric_coordinates(const vector3 &p, const vector3 &a, const vector3 &b,
                                const vector3 &c) noexcept;

} // namespace edyn

#endif // EDYN_SHAPES_TRIANGLE_MESH_HPP
