// A box and a sphere fall onto the ground and come to rest on it.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0}; // normal up, through the origin
    edyn::make_rigidbody(registry, ground_def);

    auto def = edyn::rigidbody_def();
    def.mass = 10;
    def.shape = edyn::box_shape{0.5, 0.5, 0.5}; // half extents
    def.position = {0, 3, 0};
    auto box = edyn::make_rigidbody(registry, def);
    def.shape = edyn::sphere_shape{0.25};
    def.position = {2, 5, 0};
    auto sphere = edyn::make_rigidbody(registry, def);

    // update() steps up to the time it is given; a game passes its clock, here 60 frames a second.
    // The steps run on edyn's worker thread and update() never waits for them: a game draws
    // what has arrived. This example waits, so that it prints the same numbers on every run.
    edyn::scalar box_y = 0, sphere_y = 0;
    for (int frame = 0; frame <= 120; ++frame) {
        edyn::update(registry, frame / 60.0);
        edyn::wait_for_simulation(registry);
        box_y = registry.get<edyn::present_position>(box).y;
        sphere_y = registry.get<edyn::present_position>(sphere).y;
        if (frame % 30 == 0)
            std::printf("t = %.1f s: box at y = %.3f m, sphere at y = %.3f m\n", frame / 60.0, box_y,
                        sphere_y);
    }
    edyn::detach(registry);

    // At rest on the ground, each centre is half a height above it.
    std::printf("box landed at y = %.3f m (expected 0.5), sphere at y = %.3f m (expected 0.25)\n", box_y,
                sphere_y);
    return std::abs(box_y - 0.5f) < 0.01f && std::abs(sphere_y - 0.25f) < 0.01f ? 0 : 1;
}
