#include "edyn_scenes/scenes.hpp"
#include <cmath>
#include <random>

namespace edyn::scenes {

namespace {

// Eigen-decomposition of a symmetric 3x3 matrix by Jacobi rotations: on return `a` is diagonal
// (the eigenvalues) and the columns of `v` are the eigenvectors, a_in = v a_out v^T.
void jacobi_eigen(double a[3][3], double v[3][3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            v[i][j] = i == j ? 1 : 0;
    const int pairs[3][2]{{0, 1}, {0, 2}, {1, 2}};
    for (int sweep = 0; sweep < 50; ++sweep) {
        auto off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        auto diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-30 * diagonal) break;
        for (const auto &pair : pairs) {
            auto p = pair[0], q = pair[1];
            if (a[p][q] == 0) continue;
            auto theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
            auto t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
            auto c = 1 / std::sqrt(t * t + 1), s = t * c;
            for (int k = 0; k < 3; ++k) {
                auto akp = a[k][p], akq = a[k][q];
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
            }
            for (int k = 0; k < 3; ++k) {
                auto apk = a[p][k], aqk = a[q][k];
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
            for (int k = 0; k < 3; ++k) {
                auto vkp = v[k][p], vkq = v[k][q];
                v[k][p] = c * vkp - s * vkq;
                v[k][q] = s * vkp + c * vkq;
            }
        }
    }
}

// An irregular rock: the convex hull of 12 random points on an ellipsoid of largest semi-axis
// `size`, moved so that its centroid is the origin and turned so that its principal axes of
// inertia are the object axes. Its body then needs no centre of mass offset and has a diagonal
// inertia, which every engine can take as it is.
polyhedron_shape make_principal_rock(std::mt19937 &rng, scalar size) {
    std::uniform_real_distribution<scalar> unit(-1, 1);
    std::uniform_real_distribution<scalar> squash(scalar(0.6), 1);
    vector3 axes{size, size * squash(rng), size * squash(rng)};
    std::vector<vector3> points;
    while (points.size() < 12) {
        vector3 p{unit(rng), unit(rng), unit(rng)};
        if (!try_normalize(p)) continue;
        points.push_back(p * axes);
    }
    polyhedron_shape rough(points);
    auto centroid = shape_centroid(rough);
    for (auto &p : points)
        p -= centroid;
    auto inertia = moment_of_inertia(polyhedron_shape(points), scalar(1));
    double a[3][3], v[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[i][j] = double(inertia[i][j]);
    jacobi_eigen(a, v);
    // In the principal frame a point p has coordinates v^T p.
    for (auto &p : points) {
        double x = p.x, y = p.y, z = p.z;
        p = {scalar(v[0][0] * x + v[1][0] * y + v[2][0] * z), scalar(v[0][1] * x + v[1][1] * y + v[2][1] * z),
             scalar(v[0][2] * x + v[1][2] * y + v[2][2] * z)};
    }
    return polyhedron_shape(points);
}

} // namespace

std::optional<scalar> terrain_surface_height(const mesh_pile_terrain &terrain, scalar x, scalar z) {
    // The grid of make_grid_mesh: vertex (i, j) at x = j * cell_size - half, z = i * cell_size -
    // half; each cell split along its diagonal from (i, j) to (i + 1, j + 1).
    auto half = scalar(terrain.cells) * terrain.cell_size / 2;
    x -= terrain.origin.x;
    z -= terrain.origin.z;
    auto gx = (x + half) / terrain.cell_size, gz = (z + half) / terrain.cell_size;
    auto n = scalar(terrain.cells);
    if (!(gx >= 0 && gx <= n && gz >= 0 && gz <= n)) return std::nullopt;
    auto j = std::min(static_cast<unsigned>(gx), terrain.cells - 1);
    auto i = std::min(static_cast<unsigned>(gz), terrain.cells - 1);
    auto u = gx - scalar(j), w = gz - scalar(i);
    auto height = [&](unsigned vi, unsigned vj) {
        return terrain_height(scalar(vj) * terrain.cell_size - half, scalar(vi) * terrain.cell_size - half,
                              terrain.amplitude);
    };
    auto h00 = height(i, j), h01 = height(i, j + 1), h10 = height(i + 1, j), h11 = height(i + 1, j + 1);
    // Triangle (00, 10, 11) where w >= u, triangle (00, 11, 01) where u >= w.
    if (w >= u) return terrain.origin.y + h00 + u * (h11 - h10) + w * (h10 - h00);
    return terrain.origin.y + h00 + u * (h01 - h00) + w * (h11 - h01);
}

mesh_pile_scene make_mesh_pile(registry &registry, unsigned count, unsigned width, scalar height,
                               const mesh_pile_terrain &terrain, std::uint32_t seed) {
    mesh_pile_scene scene;
    {
        auto amplitude = terrain.amplitude;
        auto mesh = make_grid_mesh(terrain.cells, terrain.cell_size, [amplitude](scalar x, scalar z) {
            return terrain_height(x, z, amplitude);
        });
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.material->friction = terrain.friction;
        def.position = terrain.origin;
        if (terrain.paged) {
            auto v = mesh->get_vertices();
            auto idx = mesh->get_indices();
            def.shape = paged_mesh_shape{create_paged_triangle_mesh(
                {v.begin(), v.end()}, {idx.begin(), idx.end()}, terrain.page_size)};
        } else {
            def.shape = mesh_shape{mesh};
        }
        scene.terrain = make_rigidbody(registry, def);
    }

    std::mt19937 rng(seed);
    std::uniform_real_distribution<scalar> size_dist(scalar(0.5), scalar(1));
    std::uniform_real_distribution<scalar> angle_dist(0, pi2);
    std::uniform_real_distribution<scalar> unit(-1, 1);
    if (width == 0) width = 1;

    scene.bodies.reserve(count);
    const scalar spacing = scalar(2.2);
    auto offset = -scalar(width - 1) * spacing / 2;
    for (unsigned i = 0; i < count; ++i) {
        auto layer = i / (width * width);
        auto cell = i % (width * width);
        rigidbody_def def;
        def.mass = 1;
        def.material->friction = scalar(0.6);
        auto x = offset + scalar(cell % width) * spacing;
        auto z = offset + scalar(cell / width) * spacing;
        def.position = terrain.origin + vector3{x,
                                                terrain_height(x, z, terrain.amplitude) + height +
                                                    scalar(layer) * scalar(1.5) * spacing,
                                                z};
        vector3 axis{unit(rng), unit(rng), unit(rng)};
        if (!try_normalize(axis)) axis = vector3_y;
        def.orientation = quaternion_axis_angle(axis, angle_dist(rng));
        // A size for each body: its largest dimension lies between 0.5 and 1.
        auto s = size_dist(rng) / 2;
        switch (i % 4) {
        case 0:
            def.shape = box_shape{vector3{s, s * scalar(0.8), s * scalar(0.6)}};
            break;
        case 1:
            def.shape = sphere_shape{s};
            break;
        case 2:
            def.shape = capsule_shape{s * scalar(0.5), s * scalar(0.5), coordinate_axis::x};
            break;
        default: {
            auto rock = make_principal_rock(rng, s);
            // The centroid is the origin and the principal axes the object axes, to rounding:
            // pin both, so that the body has no centre of mass offset and a diagonal inertia.
            def.center_of_mass = vector3_zero;
            def.inertia = diagonal_matrix(get_diagonal(moment_of_inertia(rock, def.mass)));
            def.shape = rock;
            break;
        }
        }
        scene.bodies.push_back(make_rigidbody(registry, def));
    }
    return scene;
}

} // namespace edyn::scenes
