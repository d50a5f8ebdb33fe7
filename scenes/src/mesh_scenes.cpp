#include "edyn_scenes/scenes.hpp"
#include <cmath>

namespace edyn::scenes {

std::shared_ptr<triangle_mesh> make_grid_mesh(unsigned cells, scalar cell_size,
                                              const std::function<scalar(scalar, scalar)> &height) {
    auto n = cells + 1;
    auto half = scalar(cells) * cell_size / 2;
    std::vector<vector3> vertices;
    vertices.reserve(std::size_t(n) * n);
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) {
            auto x = scalar(j) * cell_size - half;
            auto z = scalar(i) * cell_size - half;
            vertices.push_back({x, height(x, z), z});
        }
    }
    // Counter-clockwise seen from above (+y): (i, j), (i + 1, j), (i, j + 1) with z along i.
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(cells) * cells * 6);
    for (unsigned i = 0; i < cells; ++i) {
        for (unsigned j = 0; j < cells; ++j) {
            auto v00 = i * n + j, v01 = i * n + j + 1, v10 = (i + 1) * n + j, v11 = (i + 1) * n + j + 1;
            indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
        }
    }
    auto mesh = std::make_shared<triangle_mesh>();
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->initialize();
    return mesh;
}

entity make_mesh_floor(registry &registry, unsigned cells, scalar cell_size, scalar friction,
                       scalar restitution) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.material->friction = friction;
    def.material->restitution = restitution;
    def.shape = mesh_shape{make_grid_mesh(cells, cell_size, [](scalar, scalar) { return scalar(0); })};
    return make_rigidbody(registry, def);
}

scalar terrain_height(scalar x, scalar z, scalar amplitude) {
    auto h = std::sin(x * scalar(0.11)) * std::cos(z * scalar(0.07)) * scalar(0.6) +
             std::sin((x + z) * scalar(0.23)) * scalar(0.3) +
             std::cos(x * scalar(0.41) - z * scalar(0.29)) * scalar(0.1);
    return h * amplitude;
}

entity make_terrain(registry &registry, unsigned cells, scalar cell_size, scalar amplitude, scalar friction) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.material->friction = friction;
    def.shape = mesh_shape{make_grid_mesh(
        cells, cell_size, [amplitude](scalar x, scalar z) { return terrain_height(x, z, amplitude); })};
    return make_rigidbody(registry, def);
}

} // namespace edyn::scenes
