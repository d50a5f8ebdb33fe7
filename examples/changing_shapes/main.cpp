// Changing a body's shape at run time. A ball resting on the ground is grown in place (its
// shape's own fields, then patch), replaced by a box (rigidbody_set_shape), and finally left
// without a shape, when it falls through the ground. Each time it settles where the new shape
// says it should.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

bool settle_and_check(edyn::registry &registry, edyn::entity body, const char *what, edyn::scalar expected,
                      edyn::scalar tolerance = 0.01f) {
    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto y = registry.get<edyn::position>(body).y;
    auto ok = std::abs(y - expected) < tolerance;
    std::printf("%-28s y = %.3f m (expected %.3f)%s\n", what, y, expected, ok ? "" : "  <-- wrong");
    return ok;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    edyn::make_rigidbody(registry, ground_def);

    auto def = edyn::rigidbody_def();
    def.shape = edyn::sphere_shape{0.5};
    def.position = {0, 0.5, 0};
    auto body = edyn::make_rigidbody(registry, def);
    bool ok = settle_and_check(registry, body, "ball of radius 0.5", 0.5);

    // The same shape with other dimensions: change it and tell the registry (patch), which
    // asynchronous mode needs to see the change.
    registry.patch<edyn::sphere_shape>(body, [](auto &sphere) { sphere.radius = 0.75; });
    ok = settle_and_check(registry, body, "grown to radius 0.75", 0.75) && ok;

    // Another kind of shape: rigidbody_set_shape, which also recomputes the inertia.
    edyn::rigidbody_set_shape(registry, body, edyn::box_shape{0.3, 0.1, 0.3});
    ok = settle_and_check(registry, body, "replaced by a box 0.2 m tall", 0.1) && ok;

    // No shape: amorphous, it no longer collides and falls through the ground, g t^2 / 2 =
    // 4.9 m in 1 s (4.91 m in sub-steps of 1/360 s).
    edyn::rigidbody_set_shape(registry, body, std::nullopt);
    ok = settle_and_check(registry, body, "made amorphous, after 1 s", 0.1f - 4.9f, 0.05f) && ok;

    edyn::detach(registry);
    return ok ? 0 : 1;
}
