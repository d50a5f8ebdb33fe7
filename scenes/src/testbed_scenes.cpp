// Scenes first written for the testbed: billiards, a hinged door, sliders, a vehicle and a
// gallery of every shape. Like the others, they take no drawing or input code.
#include "edyn_scenes/scenes.hpp"
#include "static_box.hpp"
#include <cmath>

namespace edyn::scenes {

namespace {

using detail::make_static_box;

} // namespace

billiards_scene make_billiards(registry &registry, scalar cue_speed) {
    billiards_scene scene;
    const scalar radius = scalar(0.1);
    const scalar half_length = 2, half_width = 1, top = scalar(0.8);
    scene.table = make_static_box(registry, {half_length, scalar(0.1), half_width}, {0, top - scalar(0.1), 0},
                                  scalar(0.2));
    const scalar rail = scalar(0.08), rail_height = scalar(0.1);
    for (int side : {-1, 1}) {
        scene.rails.push_back(make_static_box(registry, {half_length + 2 * rail, rail_height, rail},
                                              {0, top + rail_height, scalar(side) * (half_width + rail)},
                                              scalar(0.2), scalar(0.8)));
        scene.rails.push_back(make_static_box(registry, {rail, rail_height, half_width},
                                              {scalar(side) * (half_length + rail), top + rail_height, 0},
                                              scalar(0.2), scalar(0.8)));
    }

    rigidbody_def def;
    def.mass = scalar(0.17);
    def.shape = sphere_shape{radius};
    def.material->friction = scalar(0.2);
    def.material->restitution = scalar(0.95);
    // A rack of 15 balls in five rows, its apex towards the cue ball.
    const scalar gap = scalar(0.002);
    const scalar row_step = (2 * radius + gap) * std::sqrt(scalar(3)) / 2;
    for (unsigned row = 0; row < 5; ++row) {
        for (unsigned i = 0; i <= row; ++i) {
            def.position = {scalar(0.8) + scalar(row) * row_step, top + radius,
                            (scalar(i) - scalar(row) / 2) * (2 * radius + gap)};
            scene.balls.push_back(make_rigidbody(registry, def));
        }
    }
    def.position = {-scalar(1.0), top + radius, scalar(0.01)};
    def.linvel = {cue_speed, 0, 0};
    scene.cue_ball = make_rigidbody(registry, def);
    scene.balls.push_back(scene.cue_ball);
    return scene;
}

door_scene make_hinge_door(registry &registry, const vector3 &origin) {
    door_scene scene;
    const vector3 door_half{scalar(0.5), 1, scalar(0.04)};
    scene.post = make_static_box(registry, {scalar(0.06), scalar(1.1), scalar(0.06)},
                                 origin + vector3{0, scalar(1.1), 0}, scalar(0.5));
    rigidbody_def def;
    def.mass = 20;
    def.shape = box_shape{door_half};
    def.position = origin + vector3{scalar(0.6), scalar(1.05), 0};
    // Pushed open, turning about the hinge: it swings to its limit, bounces, and the spring
    // closes it again.
    def.angvel = {0, 6, 0};
    def.linvel = {0, 0, -scalar(3.6)};
    scene.door = make_rigidbody(registry, def);
    scene.hinge =
        make_constraint<hinge_constraint>(registry, scene.post, scene.door, [&](hinge_constraint &c) {
            c.pivot[0] = {scalar(0.06), 0, 0};
            c.pivot[1] = {-scalar(0.54), 0, 0};
            c.set_axes(vector3_y, vector3_y);
            c.angle_min = -to_radians(100);
            c.angle_max = to_radians(100);
            c.limit_restitution = scalar(0.3);
            c.stiffness = 10;
            c.damping = 4;
        });
    exclude_collision(registry, scene.post, scene.door);
    return scene;
}

slider_scene make_sliders(registry &registry, const vector3 &origin) {
    slider_scene scene;
    const scalar travel = scalar(1.5);
    for (unsigned i = 0; i < 3; ++i) {
        auto z = scalar(i) * scalar(1.2);
        auto rail = make_static_box(registry, {travel + scalar(0.3), scalar(0.05), scalar(0.05)},
                                    origin + vector3{0, 1, z}, scalar(0.5));
        rigidbody_def def;
        def.mass = 2;
        def.shape = box_shape{scalar(0.25), scalar(0.2), scalar(0.2)};
        def.position = origin + vector3{0, scalar(1.3), z};
        def.linvel = {scalar(4), 0, 0};
        auto block = make_rigidbody(registry, def);
        // Along the rail only, within its ends; the first bounces between them, the second is
        // held by a spring, the third slowed by friction.
        auto joint = make_constraint<generic_constraint>(registry, rail, block, [&](generic_constraint &c) {
            c.pivot[0] = {0, scalar(0.3), 0};
            c.linear[0].mode = dof_mode::limited;
            c.linear[0].min = -travel;
            c.linear[0].max = travel;
            if (i == 1) {
                c.linear[0].stiffness = 40;
                c.linear[0].damping = scalar(0.5);
            } else if (i == 2) {
                c.linear[0].friction = 3;
            }
        });
        exclude_collision(registry, rail, block);
        scene.rails.push_back(rail);
        scene.blocks.push_back(block);
        scene.joints.push_back(joint);
    }
    return scene;
}

vehicle_scene make_vehicle(registry &registry, const vector3 &origin) {
    vehicle_scene scene;
    const scalar wheel_radius = scalar(0.4), wheel_half_width = scalar(0.15);
    const scalar track = scalar(1.1), base = scalar(1.4), ride = scalar(0.9);
    rigidbody_def def;
    def.mass = 600;
    def.shape = box_shape{scalar(0.9), scalar(0.25), scalar(2.0)};
    def.position = origin + vector3{0, ride, 0};
    scene.chassis = make_rigidbody(registry, def);

    for (unsigned i = 0; i < 4; ++i) {
        auto side = i % 2 == 0 ? scalar(-1) : scalar(1);
        auto front = i < 2;
        vector3 mount{side * track, -(ride - wheel_radius), front ? -base : base};
        rigidbody_def hub_def;
        hub_def.mass = 10;
        hub_def.inertia = diagonal_matrix(vector3{1, 1, 1} * scalar(0.2));
        hub_def.position = def.position + mount;
        auto hub = make_rigidbody(registry, hub_def);
        // Suspension: the hub moves only up and down under a damped spring; the front hubs also
        // turn about the vertical to steer (a stiff spring about y, its rest angle the steering).
        auto suspension =
            make_constraint<generic_constraint>(registry, scene.chassis, hub, [&](generic_constraint &c) {
                c.pivot[0] = mount;
                c.linear[1].mode = dof_mode::limited;
                c.linear[1].min = -scalar(0.2);
                c.linear[1].max = scalar(0.2);
                c.linear[1].stiffness = 30000;
                c.linear[1].damping = 2500;
                if (front) {
                    c.angular[1].mode = dof_mode::limited;
                    c.angular[1].min = -scalar(0.6);
                    c.angular[1].max = scalar(0.6);
                    c.angular[1].stiffness = 20000;
                    c.angular[1].damping = 500;
                }
            });
        rigidbody_def wheel_def;
        wheel_def.mass = 20;
        wheel_def.shape = cylinder_shape{wheel_radius, wheel_half_width, coordinate_axis::x};
        wheel_def.material->friction = scalar(1.2);
        wheel_def.position = hub_def.position;
        auto wheel = make_rigidbody(registry, wheel_def);
        auto axle = make_constraint<hinge_constraint>(registry, hub, wheel, [&](hinge_constraint &c) {
            c.set_axes(vector3_x, vector3_x);
            c.damping = scalar(0.5);
        });
        exclude_collision(registry, scene.chassis, wheel);
        scene.hubs[i] = hub;
        scene.wheels[i] = wheel;
        scene.suspension[i] = suspension;
        scene.axles[i] = axle;
    }
    return scene;
}

void drive_vehicle(registry &registry, const vehicle_scene &vehicle, scalar throttle, scalar steering,
                   scalar dt) {
    // Steering: the rest angle of the front hubs' spring about y.
    for (unsigned i = 0; i < 2; ++i) {
        auto &suspension = registry.get<generic_constraint>(vehicle.suspension[i]);
        suspension.angular[1].rest = steering * scalar(0.5);
        registry.patch<generic_constraint>(vehicle.suspension[i]);
    }
    if (throttle == 0) return;
    // Drive: a torque about each rear wheel's axle, applied as a couple of opposite impulses.
    const scalar torque = 600;
    for (unsigned i = 2; i < 4; ++i) {
        auto wheel = vehicle.wheels[i];
        auto &orn = registry.get<orientation>(wheel);
        auto axis = rotate(orn, vector3_x);
        auto u = rotate(orn, vector3_y);
        auto v = cross(axis, u);
        // Two impulses of magnitude J a metre apart make an angular impulse of J along axis.
        auto impulse = v * (-throttle * torque * dt);
        rigidbody_apply_impulse(registry, wheel, impulse, u * scalar(0.5));
        rigidbody_apply_impulse(registry, wheel, -impulse, u * scalar(-0.5));
    }
    wake_up_entity(registry, vehicle.chassis);
}

std::vector<entity> make_shape_gallery(registry &registry, const vector3 &origin) {
    std::vector<entity> bodies;
    rigidbody_def def;
    def.mass = 2;
    auto place = [&](shapes_variant_t shape, scalar x, scalar z) {
        def.shape = std::move(shape);
        def.position = origin + vector3{x, 2, z};
        def.orientation = quaternion_axis_angle(normalize(vector3{1, 0, 1}), scalar(0.3) + x * scalar(0.1));
        bodies.push_back(make_rigidbody(registry, def));
    };
    place(box_shape{scalar(0.5), scalar(0.3), scalar(0.4)}, -4, 0);
    place(sphere_shape{scalar(0.5)}, -2, 0);
    place(capsule_shape{scalar(0.3), scalar(0.5), coordinate_axis::x}, 0, 0);
    place(cylinder_shape{scalar(0.4), scalar(0.4), coordinate_axis::y}, 2, 0);
    place(polyhedron_shape(std::vector<vector3>{{0, scalar(0.7), 0},
                                                {scalar(0.5), 0, 0},
                                                {-scalar(0.5), 0, 0},
                                                {0, 0, scalar(0.5)},
                                                {0, 0, -scalar(0.5)},
                                                {0, -scalar(0.5), 0}}),
          4, 0);
    // Compounds: a dumbbell, a table and an L of boxes.
    compound_shape dumbbell;
    dumbbell.add_shape(cylinder_shape{scalar(0.1), scalar(0.5), coordinate_axis::x});
    dumbbell.add_shape(sphere_shape{scalar(0.3)}, {-scalar(0.6), 0, 0});
    dumbbell.add_shape(sphere_shape{scalar(0.3)}, {scalar(0.6), 0, 0});
    dumbbell.finish();
    place(dumbbell, -3, 3);
    compound_shape table;
    table.add_shape(box_shape{scalar(0.7), scalar(0.05), scalar(0.5)}, {0, scalar(0.5), 0});
    for (int sx : {-1, 1})
        for (int sz : {-1, 1})
            table.add_shape(box_shape{scalar(0.05), scalar(0.25), scalar(0.05)},
                            {scalar(sx) * scalar(0.6), scalar(0.2), scalar(sz) * scalar(0.4)});
    table.finish();
    place(table, 0, 3);
    compound_shape ell;
    ell.add_shape(box_shape{scalar(0.6), scalar(0.15), scalar(0.15)});
    ell.add_shape(box_shape{scalar(0.15), scalar(0.45), scalar(0.15)}, {scalar(0.45), scalar(0.6), 0});
    ell.add_shape(capsule_shape{scalar(0.12), scalar(0.3), coordinate_axis::z},
                  {-scalar(0.45), scalar(0.27), 0});
    ell.finish();
    place(ell, 3, 3);
    return bodies;
}

} // namespace edyn::scenes
