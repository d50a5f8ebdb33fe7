#include "edyn_scenes/scenes.hpp"
#include "static_box.hpp"
#include <cmath>

namespace edyn::scenes {

namespace {

rigidbody_def stacked_body(const vector3 &half_extents, scalar mass) {
    rigidbody_def def;
    def.mass = mass;
    def.material->friction = scalar(0.6);
    def.shape = box_shape{half_extents};
    return def;
}

using detail::make_static_box;

} // namespace

std::vector<entity> make_mixed_tower(registry &registry, unsigned count, const vector3 &origin) {
    // Half extents and masses, gone round from the bottom: each mass is 8 times or 2.5 to 3.2
    // times its neighbour's, one way or the other, and widths change by up to a factor of two.
    struct block {
        vector3 half_extents;
        scalar mass;
    };
    const block blocks[]{{{scalar(0.5), scalar(0.2), scalar(0.4)}, 4},
                         {{scalar(0.3), scalar(0.35), scalar(0.3)}, scalar(0.5)},
                         {{scalar(0.6), scalar(0.15), scalar(0.45)}, 4},
                         {{scalar(0.35), scalar(0.3), scalar(0.5)}, 10},
                         {{scalar(0.45), scalar(0.25), scalar(0.25)}, scalar(1.25)}};
    std::vector<entity> boxes;
    scalar base = 0;
    for (unsigned i = 0; i < count; ++i) {
        auto &b = blocks[i % std::size(blocks)];
        auto def = stacked_body(b.half_extents, b.mass);
        def.position = origin + vector3{0, base + b.half_extents.y, 0};
        base += 2 * b.half_extents.y;
        boxes.push_back(make_rigidbody(registry, def));
    }
    return boxes;
}

std::vector<entity> make_brick_wall(registry &registry, unsigned rows, unsigned bricks_per_row,
                                    const vector3 &brick_half_extents, const vector3 &origin) {
    const auto hx = brick_half_extents.x, hy = brick_half_extents.y;
    const auto n = scalar(bricks_per_row);
    auto brick = stacked_body(brick_half_extents, 2);
    auto half_brick = stacked_body({hx / 2, hy, brick_half_extents.z}, 1);
    std::vector<entity> bricks;
    auto place = [&](rigidbody_def &def, scalar x, scalar y) {
        def.position = origin + vector3{x, y, 0};
        bricks.push_back(make_rigidbody(registry, def));
    };
    for (unsigned row = 0; row < rows; ++row) {
        auto y = hy + scalar(row) * 2 * hy;
        if (row % 2 == 0) {
            for (unsigned i = 0; i < bricks_per_row; ++i)
                place(brick, (2 * scalar(i) + 1 - n) * hx, y);
        } else {
            // Shifted by half a brick: a half brick at each end keeps the ends flush.
            place(half_brick, (scalar(0.5) - n) * hx, y);
            for (unsigned i = 0; i + 1 < bricks_per_row; ++i)
                place(brick, (2 * scalar(i) + 2 - n) * hx, y);
            place(half_brick, (n - scalar(0.5)) * hx, y);
        }
    }
    return bricks;
}

spheres_in_box_scene make_spheres_in_box(registry &registry, unsigned layers, unsigned width, scalar radius,
                                         const vector3 &origin) {
    spheres_in_box_scene scene;
    // A full layer fills the box wall to wall with a sliver of room, so that the spheres
    // neither wedge against the walls nor roll about.
    const scalar clearance = scalar(0.01) * radius, thickness = scalar(0.1);
    const scalar layer_height = std::sqrt(scalar(2)) * radius; // centres of touching square layers
    scene.inner_half_width = scalar(width) * radius + clearance;
    auto last_full_layer = layers == 0 ? 0 : (layers - 1) / 2 * 2;
    scene.wall_height = 2 * radius + scalar(last_full_layer) * layer_height;

    const auto w = scene.inner_half_width, h = scene.wall_height;
    scene.container.push_back(make_static_box(registry, {w + 2 * thickness, thickness, w + 2 * thickness},
                                              origin - vector3{0, thickness, 0}, scalar(0.6)));
    for (scalar side : {scalar(-1), scalar(1)}) {
        scene.container.push_back(make_static_box(registry, {w + 2 * thickness, h / 2, thickness},
                                                  origin + vector3{0, h / 2, side * (w + thickness)},
                                                  scalar(0.6)));
        scene.container.push_back(make_static_box(registry, {thickness, h / 2, w},
                                                  origin + vector3{side * (w + thickness), h / 2, 0},
                                                  scalar(0.6)));
    }

    rigidbody_def def;
    def.mass = 1;
    def.material->friction = scalar(0.6);
    def.shape = sphere_shape{radius};
    for (unsigned layer = 0; layer < layers; ++layer) {
        auto count = layer % 2 == 0 ? width : width - 1;
        if (count == 0) continue;
        auto first = -scalar(count - 1) * radius;
        for (unsigned i = 0; i < count; ++i) {
            for (unsigned j = 0; j < count; ++j) {
                def.position =
                    origin + vector3{first + 2 * radius * scalar(i), radius + scalar(layer) * layer_height,
                                     first + 2 * radius * scalar(j)};
                scene.spheres.push_back(make_rigidbody(registry, def));
            }
        }
    }
    return scene;
}

} // namespace edyn::scenes
