#ifndef EDYN_TESTS_SUPPORT_GRID_MESH_HPP
#define EDYN_TESTS_SUPPORT_GRID_MESH_HPP

// The tessellated floor the unit tests of meshes share, numbered so that their expected
// triangle indices can be written out by hand: vertex (i, j) lies at origin + (i cell,
// height(i, j), j cell), and cell (i, j) (i along x, j along z) gives triangles
// first + 2 (i n + j), where z - j >= x - i, and first + 2 (i n + j) + 1, both facing +y.
// (scenes::make_grid_mesh is centred and numbered along z first: fine for scenes, not for
// expectations written by hand.)
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/mesh_shape.hpp"
#include "edyn/shapes/triangle_mesh.hpp"
#include <functional>
#include <memory>
#include <vector>

namespace edyn::test {

/// Height of grid vertex (i, j).
using grid_height = std::function<scalar(int, int)>;

inline scalar flat_height(int, int) { return 0; }

/// Appends an n x n grid of square cells of side `cell` to (vertices, indices); its first
/// triangle is the number of triangles `indices` held before.
template<typename Index>
void append_grid(std::vector<vector3> &vertices, std::vector<Index> &indices, int n, scalar cell = 1,
                 const vector3 &origin = vector3_zero, const grid_height &height = flat_height) {
    auto base = Index(vertices.size());
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j)
            vertices.push_back(origin + vector3{scalar(i) * cell, height(i, j), scalar(j) * cell});
    }
    auto at = [&](int i, int j) { return Index(base + Index(i * (n + 1) + j)); };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            // (x, z) -> (x, z + 1) -> (x + 1, z + 1) runs counter-clockwise seen from +y.
            indices.insert(indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            indices.insert(indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
}

/// An initialized triangle mesh of the given vertices and indices.
template<typename Index>
std::shared_ptr<triangle_mesh> make_triangle_mesh(const std::vector<vector3> &vertices,
                                                  const std::vector<Index> &indices) {
    auto mesh = std::make_shared<triangle_mesh>();
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->initialize();
    return mesh;
}

/// A mesh shape of the given vertices and indices.
inline mesh_shape make_mesh(const std::vector<vector3> &vertices, const std::vector<int> &indices) {
    return mesh_shape{make_triangle_mesh(vertices, indices)};
}

/// An initialized mesh of one grid (see append_grid).
inline std::shared_ptr<triangle_mesh> make_grid(int n, scalar cell = 1, const vector3 &origin = vector3_zero,
                                                const grid_height &height = flat_height) {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    append_grid(vertices, indices, n, cell, origin, height);
    return make_triangle_mesh(vertices, indices);
}

} // namespace edyn::test

#endif // EDYN_TESTS_SUPPORT_GRID_MESH_HPP
