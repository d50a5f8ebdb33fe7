#include "edyn_scenes/scenes.hpp"
#include <random>

namespace edyn::scenes {

entity make_ground(registry &registry, scalar friction, scalar restitution) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.material->friction = friction;
    def.material->restitution = restitution;
    def.shape = plane_shape{vector3_y, 0};
    return make_rigidbody(registry, def);
}

std::vector<entity> make_pyramid(registry &registry, unsigned base, scalar half_extent,
                                 const vector3 &origin) {
    std::vector<entity> boxes;
    rigidbody_def def;
    def.mass = 1;
    def.material->friction = scalar(0.6);
    def.shape = box_shape{vector3{half_extent, half_extent, half_extent}};
    auto size = 2 * half_extent;
    for (unsigned row = 0; row < base; ++row) {
        auto count = base - row;
        auto x0 = -scalar(count - 1) * half_extent;
        for (unsigned i = 0; i < count; ++i) {
            def.position = origin + vector3{x0 + scalar(i) * size, half_extent + scalar(row) * size, 0};
            boxes.push_back(make_rigidbody(registry, def));
        }
    }
    return boxes;
}

std::vector<entity> make_tower(registry &registry, unsigned count, scalar half_extent,
                               const vector3 &origin) {
    std::vector<entity> boxes;
    rigidbody_def def;
    def.mass = 1;
    def.material->friction = scalar(0.6);
    def.shape = box_shape{vector3{half_extent, half_extent, half_extent}};
    for (unsigned i = 0; i < count; ++i) {
        def.position = origin + vector3{0, half_extent + scalar(i) * 2 * half_extent, 0};
        boxes.push_back(make_rigidbody(registry, def));
    }
    return boxes;
}

namespace {

// A convex hull of random points on an ellipsoid: an irregular rock-like polyhedron.
polyhedron_shape make_rock(std::mt19937 &rng, scalar size) {
    std::uniform_real_distribution<scalar> unit(-1, 1);
    std::vector<vector3> points;
    while (points.size() < 12) {
        vector3 p{unit(rng), unit(rng), unit(rng)};
        if (!try_normalize(p)) continue;
        points.push_back(p * size);
    }
    return polyhedron_shape(points);
}

} // namespace

std::vector<entity> make_pile(registry &registry, unsigned count, unsigned width, scalar height,
                              pile_shapes shapes, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<scalar> size_dist(scalar(0.5), scalar(1));
    std::uniform_real_distribution<scalar> angle_dist(0, pi2);
    std::uniform_real_distribution<scalar> unit(-1, 1);
    unsigned kinds = shapes == pile_shapes::with_polyhedra ? 5 : 4;

    std::vector<entity> bodies;
    bodies.reserve(count);
    const scalar spacing = scalar(2.2);
    auto offset = -scalar(width - 1) * spacing / 2;
    for (unsigned i = 0; i < count; ++i) {
        auto layer = i / (width * width);
        auto cell = i % (width * width);
        rigidbody_def def;
        def.mass = 1;
        def.material->friction = scalar(0.6);
        def.position = {offset + scalar(cell % width) * spacing,
                        height + scalar(layer) * scalar(1.5) * spacing,
                        offset + scalar(cell / width) * spacing};
        vector3 axis{unit(rng), unit(rng), unit(rng)};
        if (!try_normalize(axis)) axis = vector3_y;
        def.orientation = quaternion_axis_angle(axis, angle_dist(rng));
        // A size for each body: its largest dimension lies between 0.5 and 1.
        auto s = size_dist(rng) / 2;
        switch (i % kinds) {
        case 0:
            def.shape = box_shape{vector3{s, s * scalar(0.8), s * scalar(0.6)}};
            break;
        case 1:
            def.shape = sphere_shape{s};
            break;
        case 2:
            def.shape = capsule_shape{s * scalar(0.5), s * scalar(0.5), coordinate_axis::x};
            break;
        case 3:
            def.shape = cylinder_shape{s * scalar(0.6), s * scalar(0.6), coordinate_axis::y};
            break;
        default:
            def.shape = make_rock(rng, s);
            break;
        }
        bodies.push_back(make_rigidbody(registry, def));
    }
    return bodies;
}

std::vector<entity> make_bouncing_balls(registry &registry, unsigned count, scalar height,
                                        const vector3 &origin) {
    std::vector<entity> balls;
    rigidbody_def def;
    def.shape = sphere_shape{scalar(0.5)};
    for (unsigned i = 0; i < count; ++i) {
        def.material->restitution = count > 1 ? scalar(i) / scalar(count - 1) : scalar(1);
        def.position = origin + vector3{scalar(i) * scalar(1.5), height, 0};
        balls.push_back(make_rigidbody(registry, def));
    }
    return balls;
}

} // namespace edyn::scenes
