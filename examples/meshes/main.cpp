// Triangle meshes: a floor of 800 triangles built from a height grid, a box pushed across it
// without friction and a ball rolled across it. Internal edges do not show: the box keeps its
// speed and height, the ball rolls straight. Then the same floor as a paged mesh of 100-triangle
// pages, of which only those near the ball are loaded.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <vector>

namespace {

// A flat floor of n x n one-metre squares centred on the origin, two triangles per square,
// counter-clockwise seen from above (+y).
void make_floor_data(unsigned n, std::vector<edyn::vector3> &vertices, std::vector<std::uint32_t> &indices) {
    auto half = edyn::scalar(n) / 2;
    for (unsigned i = 0; i <= n; ++i)
        for (unsigned j = 0; j <= n; ++j)
            vertices.push_back({edyn::scalar(j) - half, 0, edyn::scalar(i) - half});
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) {
            auto v00 = i * (n + 1) + j, v01 = v00 + 1, v10 = v00 + n + 1, v11 = v10 + 1;
            indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
        }
    }
}

bool report(bool ok, const char *what, double measured, double expected) {
    std::printf("%-40s %.4f (expected %.4f)%s\n", what, measured, expected, ok ? "" : "  <-- wrong");
    return ok;
}

} // namespace

int main() {
    std::vector<edyn::vector3> vertices;
    std::vector<std::uint32_t> indices;
    make_floor_data(20, vertices, indices);

    edyn::registry registry;
    edyn::attach(registry);
    auto mesh = std::make_shared<edyn::triangle_mesh>();
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->initialize();
    edyn::rigidbody_def floor;
    floor.kind = edyn::rigidbody_kind::rb_static;
    floor.material->friction = 0;
    floor.shape = edyn::mesh_shape{mesh};
    edyn::make_rigidbody(registry, floor);

    // A box at 4 m/s, slightly across the grid, without friction: 2 s, 8 m, over many edges.
    edyn::rigidbody_def box;
    box.mass = 1;
    box.shape = edyn::box_shape{0.4f, 0.4f, 0.4f};
    box.position = {-6, 0.4f, 0.3f};
    box.linvel = {4, 0, 0.2f};
    box.material->friction = 0;
    auto b = edyn::make_rigidbody(registry, box);
    edyn::scalar lowest = 1, highest = 0;
    for (int step = 0; step < 120; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        auto y = registry.get<edyn::position>(b).y;
        lowest = std::min(lowest, y);
        highest = std::max(highest, y);
    }
    auto speed = edyn::length(registry.get<edyn::linvel>(b));
    edyn::detach(registry);
    bool ok = true;
    ok &= report(std::abs(speed - std::sqrt(16.04)) < 0.01 * std::sqrt(16.04),
                 "box speed after 8 m (m/s):", speed, std::sqrt(16.04));
    ok &= report(highest - lowest < 0.002f, "box height range over 8 m (m):", highest - lowest, 0);

    // The same floor in pages of at most 100 triangles; a ball rolls along x.
    // Sequential, so that this thread may read the paged mesh's loading state (in the
    // asynchronous mode the worker's copy of the world loads the pages).
    edyn::registry paged_registry;
    edyn::init_config config;
    config.execution_mode = edyn::execution_mode::sequential;
    edyn::attach(paged_registry, config);
    edyn::rigidbody_def paged_floor;
    paged_floor.kind = edyn::rigidbody_kind::rb_static;
    auto paged = edyn::create_paged_triangle_mesh(vertices, indices, 100);
    paged_floor.shape = edyn::paged_mesh_shape{paged};
    edyn::make_rigidbody(paged_registry, paged_floor);
    edyn::rigidbody_def ball;
    ball.mass = 1;
    ball.shape = edyn::sphere_shape{0.5f};
    ball.position = {-8, 0.5f, 0.2f};
    ball.linvel = {3, 0, 0};
    ball.angvel = {0, 0, -6};
    ball.material->friction = 1;
    auto s = edyn::make_rigidbody(paged_registry, ball);
    for (int step = 0; step < 120; ++step)
        edyn::step_simulation(paged_registry);
    auto p = paged_registry.get<edyn::position>(s);
    std::printf("paged floor: %zu pages, %zu loaded (%zu of %zu triangles)\n", paged->num_pages(),
                paged->num_loaded_pages(), paged->num_loaded_triangles(), paged->num_triangles());
    ok &= report(std::abs(p.z - 0.2f) < 0.01f, "ball's z after rolling 6 m (m):", p.z, 0.2);
    ok &= report(paged->num_loaded_pages() < paged->num_pages(),
                 "pages loaded, fewer than all:", double(paged->num_loaded_pages()),
                 double(paged->num_pages()));
    edyn::detach(paged_registry);
    return ok ? 0 : 1;
}
