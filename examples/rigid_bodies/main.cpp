// The three kinds of rigid body, the shapes a dynamic body can have, a body without a shape and
// a sensor. Every shape is dropped onto the ground and must come to rest on it.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <vector>

namespace {

struct dropped {
    const char *name;
    edyn::entity entity;
    // Height of the body's origin above the ground when resting.
    edyn::scalar rest_height;
};

// Sensors report contacts without touching anything; counted here.
struct sensor_hits {
    int count{0};
};

void contact_started(edyn::registry &registry, edyn::entity manifold_entity) {
    auto &manifold = registry.get<edyn::contact_manifold>(manifold_entity);
    if (registry.any_of<edyn::sensor_tag>(manifold.body[0]) ||
        registry.any_of<edyn::sensor_tag>(manifold.body[1]))
        ++registry.ctx().get<sensor_hits>().count;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);
    registry.ctx().emplace<sensor_hits>();
    edyn::on_contact_started(registry).connect<&contact_started>(registry);

    // Static: never moves. A plane can only be static.
    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    edyn::make_rigidbody(registry, ground_def);

    // Dynamic, the default kind: one of each shape, 1 m apart, dropped from 1 m.
    auto compound = edyn::compound_shape{};
    compound.add_shape(edyn::box_shape{0.4, 0.1, 0.4}, {0, -0.2, 0});
    compound.add_shape(edyn::sphere_shape{0.2}, {0, 0.1, 0});
    compound.finish();
    auto pyramid = edyn::polyhedron_shape{std::vector<edyn::vector3>{
        {-0.3, 0, -0.3}, {0.3, 0, -0.3}, {0.3, 0, 0.3}, {-0.3, 0, 0.3}, {0, 0.4, 0}}};

    std::vector<dropped> bodies;
    auto drop = [&](const char *name, edyn::shapes_variant_t shape, edyn::scalar rest_height) {
        auto def = edyn::rigidbody_def();
        def.mass = 2;
        def.shape = shape;
        def.position = {edyn::scalar(bodies.size()), rest_height + 1, 0};
        bodies.push_back({name, edyn::make_rigidbody(registry, def), rest_height});
    };
    drop("box", edyn::box_shape{0.3, 0.2, 0.3}, 0.2);
    drop("sphere", edyn::sphere_shape{0.25}, 0.25);
    // Cylinders and capsules lie along a coordinate axis: x here, so they rest on their side.
    drop("cylinder", edyn::cylinder_shape{0.2, 0.3, edyn::coordinate_axis::x}, 0.2);
    drop("capsule", edyn::capsule_shape{0.15, 0.3, edyn::coordinate_axis::x}, 0.15);
    // A polyhedron's origin is where its points are given from; the base lies at y = 0.
    drop("polyhedron", pyramid, 0);
    drop("compound", compound, 0.3);

    // Kinematic: infinite mass, moved by the program; this one moves at its linvel.
    auto platform_def = edyn::rigidbody_def();
    platform_def.kind = edyn::rigidbody_kind::rb_kinematic;
    platform_def.shape = edyn::box_shape{0.5, 0.05, 0.5};
    platform_def.position = {0, 3, 5};
    platform_def.linvel = {1, 0, 0};
    auto platform = edyn::make_rigidbody(registry, platform_def);

    // Amorphous: no shape, so no collisions (it falls through the ground); a dynamic one needs
    // its inertia given, since there is no shape to compute it from.
    auto flywheel_def = edyn::rigidbody_def();
    flywheel_def.mass = 5;
    flywheel_def.inertia = edyn::moment_of_inertia_solid_cylinder(5, 0.3, 0.05, edyn::coordinate_axis::z);
    flywheel_def.position = {0, 1, -5};
    flywheel_def.shape.reset();
    auto flywheel = edyn::make_rigidbody(registry, flywheel_def);

    // Sensor: a material-less box on the ground; a ball dropped into it passes through, and
    // the contact is reported.
    auto sensor_def = edyn::rigidbody_def();
    sensor_def.kind = edyn::rigidbody_kind::rb_static;
    sensor_def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    sensor_def.position = {8, 0.5, 0};
    sensor_def.material.reset();
    edyn::make_rigidbody(registry, sensor_def);
    auto ball_def = edyn::rigidbody_def();
    ball_def.shape = edyn::sphere_shape{0.1};
    ball_def.position = {8, 2, 0};
    auto ball = edyn::make_rigidbody(registry, ball_def);

    for (int step = 0; step < 120; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);

    bool ok = true;
    for (auto &b : bodies) {
        // position is the centre of mass, which lies off the origin in the polyhedron and the
        // compound; the origin is what the shapes are placed from.
        auto y = edyn::get_rigidbody_origin(registry, b.entity).y;
        auto good = std::abs(y - b.rest_height) < 0.02f;
        ok = ok && good;
        std::printf("%-10s origin rests at y = %.3f m (expected %.3f)%s\n", b.name, y, b.rest_height,
                    good ? "" : "  <-- wrong");
    }

    // The kinematic platform moved 1 m/s for 2 s and was not pulled down by gravity.
    auto platform_pos = registry.get<edyn::position>(platform);
    auto platform_ok = std::abs(platform_pos.x - 2) < 0.001f && std::abs(platform_pos.y - 3) < 0.001f;
    std::printf("kinematic platform at x = %.3f m, y = %.3f m (expected 2, 3)\n", platform_pos.x,
                platform_pos.y);

    // Free fall of 2 s through the ground.
    auto flywheel_y = registry.get<edyn::position>(flywheel).y;
    auto expected_fall = 1 - 0.5f * 9.8f * 4;
    auto flywheel_ok = std::abs(flywheel_y - expected_fall) < 0.1f;
    std::printf("amorphous flywheel fell through the ground to y = %.2f m (expected %.2f)\n", flywheel_y,
                expected_fall);

    // The ball fell through the sensor and came to rest on the ground inside it.
    auto ball_y = registry.get<edyn::position>(ball).y;
    auto sensor_ok = std::abs(ball_y - 0.1f) < 0.01f && registry.ctx().get<sensor_hits>().count == 1;
    std::printf("ball fell through the sensor to y = %.3f m (expected 0.1), %d sensor contact reported "
                "(expected 1)\n",
                ball_y, registry.ctx().get<sensor_hits>().count);

    // Kinds change at run time: the platform made static stops where it is.
    edyn::rigidbody_set_kind(registry, platform, edyn::rigidbody_kind::rb_static);
    edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto stopped = registry.get<edyn::position>(platform).x == platform_pos.x;
    std::printf("platform made static %s\n", stopped ? "stopped" : "kept moving");

    edyn::detach(registry);
    return ok && platform_ok && flywheel_ok && sensor_ok && stopped ? 0 : 1;
}
