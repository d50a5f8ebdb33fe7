#include "samples.hpp"
#include <chrono>
#include <edyn_scenes/scenes.hpp>

namespace testbed {

namespace {

orbit_camera make_camera(edyn::vector3 target, float distance, float yaw = 0, float pitch = 0.3f) {
    orbit_camera c;
    c.target = target;
    c.distance = distance;
    c.yaw = yaw;
    c.pitch = pitch;
    return c;
}

template<typename Fn>
std::function<sample_state(edyn::registry &)> with_ground(Fn fn) {
    return [fn](edyn::registry &registry) {
        edyn::scenes::make_ground(registry);
        fn(registry);
        return sample_state{};
    };
}

// A billiard ball hit by another flashes: listeners of contact_started get the manifold.
void flash_on_contact(edyn::registry &registry, edyn::entity manifold_entity) {
    // Ball on ball only: every ball starts in contact with the cloth.
    auto &manifold = registry.get<edyn::contact_manifold>(manifold_entity);
    if (!registry.all_of<body_flash>(manifold.body[0]) || !registry.all_of<body_flash>(manifold.body[1]))
        return;
    for (auto body : manifold.body)
        registry.get<body_flash>(body).time_left = 0.3f;
}

sample_state build_billiards(edyn::registry &registry) {
    edyn::scenes::make_ground(registry);
    auto scene = edyn::scenes::make_billiards(registry);
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
        auto ball = scene.balls[i];
        registry.emplace<body_flash>(ball);
        if (ball == scene.cue_ball) {
            registry.emplace<body_tint>(ball, 0.95f, 0.95f, 0.92f);
        } else {
            static constexpr body_tint tints[] = {
                {0.95f, 0.8f, 0.1f},  {0.1f, 0.2f, 0.8f}, {0.85f, 0.1f, 0.1f}, {0.4f, 0.1f, 0.6f},
                {0.95f, 0.45f, 0.1f}, {0.1f, 0.5f, 0.2f}, {0.5f, 0.1f, 0.1f},  {0.1f, 0.1f, 0.1f}};
            registry.emplace<body_tint>(ball, tints[i % std::size(tints)]);
        }
    }
    registry.emplace_or_replace<body_tint>(scene.table, 0.1f, 0.45f, 0.2f);
    edyn::on_contact_started(registry).connect<&flash_on_contact>(registry);
    sample_state state;
    state.on_frame = [](edyn::registry &reg, const sample_input &, float dt) {
        for (auto [e, flash] : reg.view<body_flash>().each())
            flash.time_left = std::max(0.0f, flash.time_left - dt);
    };
    state.help = "Balls flash white when a contact starts.";
    return state;
}

sample_state build_vehicle(edyn::registry &registry) {
    edyn::scenes::make_ground(registry, edyn::scalar(0.9));
    // A ramp and a few boxes to drive into.
    edyn::rigidbody_def ramp;
    ramp.kind = edyn::rigidbody_kind::rb_static;
    ramp.shape = edyn::box_shape{3, edyn::scalar(0.2), 4};
    ramp.position = {0, edyn::scalar(0.3), -18};
    ramp.orientation = edyn::quaternion_axis_angle(edyn::vector3_x, edyn::scalar(0.2));
    edyn::make_rigidbody(registry, ramp);
    edyn::scenes::make_pyramid(registry, 4, edyn::scalar(0.4), {8, 0, -10});
    auto vehicle = edyn::scenes::make_vehicle(registry);
    sample_state state;
    state.on_frame = [vehicle](edyn::registry &reg, const sample_input &input, float dt) {
        edyn::scenes::drive_vehicle(reg, vehicle, input.throttle, input.steering, dt);
    };
    state.help = "Drive with the arrow keys (up/down: throttle, left/right: steer).";
    state.follow = vehicle.chassis;
    return state;
}

std::vector<sample> make_samples() {
    using edyn::scalar;
    namespace sc = edyn::scenes;
    std::vector<sample> s;
    s.push_back({"pyramid", "Stacking", "A pyramid of 210 boxes, 20 at its base.",
                 make_camera({0, 8, 0}, 34, 0.3f, 0.15f),
                 with_ground([](auto &r) { sc::make_pyramid(r, 20); })});
    s.push_back({"tower", "Stacking", "A tower of 20 unit boxes.", make_camera({0, 8, 0}, 28, 0.3f, 0.15f),
                 with_ground([](auto &r) { sc::make_tower(r, 20); })});
    s.push_back({"mixed_tower", "Stacking", "Boxes of different sizes and masses, heavy on light.",
                 make_camera({0, 5, 0}, 20, 0.3f, 0.2f),
                 with_ground([](auto &r) { sc::make_mixed_tower(r); })});
    s.push_back({"brick_wall", "Stacking", "A wall of bricks in running bond.",
                 make_camera({0, 1, 0}, 9, 0.4f, 0.2f),
                 with_ground([](auto &r) { sc::make_brick_wall(r, 10, 10); })});
    s.push_back({"spheres_in_box", "Stacking", "Spheres stacked as fruit in a box.",
                 make_camera({0, 0.5f, 0}, 6, 0.5f, 0.6f), [](auto &r) {
                     sc::make_spheres_in_box(r);
                     return sample_state{};
                 }});
    s.push_back({"pile", "Piles", "1,024 boxes, spheres, capsules, cylinders and rocks dropped in a heap.",
                 make_camera({0, 2, 0}, 36, 0.6f, 0.45f),
                 with_ground([](auto &r) { sc::make_pile(r, 1024); })});
    s.push_back({"shapes", "Piles", "One body of every shape, compounds included.",
                 make_camera({0, 1, 1.5f}, 12, 0.2f, 0.35f),
                 with_ground([](auto &r) { sc::make_shape_gallery(r); })});
    s.push_back({"balls", "Materials", "Bouncing balls, restitution 0 (left) to 1 (right).",
                 make_camera({5.25f, 2, 0}, 16, 0, 0.1f),
                 with_ground([](auto &r) { sc::make_bouncing_balls(r, 8); })});
    s.push_back({"billiards", "Materials", "A break: contact events flash the balls.",
                 make_camera({0.3f, 0.8f, 0}, 5.5f, 0, 0.75f), build_billiards});
    s.push_back({"chain", "Joints", "A chain of 20 links on point constraints.",
                 make_camera({5, 6, 0}, 20, 0, 0.15f), with_ground([](auto &r) { sc::make_chain(r, 20); })});
    s.push_back({"bridge", "Joints", "A rope bridge of hinged planks, a box dropped on it.",
                 make_camera({4, 2, 0}, 12, 0.5f, 0.35f), [](edyn::registry &r) {
                     sc::make_ground(r);
                     sc::make_bridge(r, 16);
                     edyn::rigidbody_def box;
                     box.mass = 20;
                     box.shape = edyn::box_shape{scalar(0.3), scalar(0.3), scalar(0.3)};
                     box.position = {4, 5, 0};
                     edyn::make_rigidbody(r, box);
                     return sample_state{};
                 }});
    s.push_back({"door", "Joints", "A hinged door with limits and a spring that closes it.",
                 make_camera({0.4f, 1, 0}, 5, 0.9f, 0.35f),
                 with_ground([](auto &r) { sc::make_hinge_door(r); })});
    s.push_back({"slider", "Joints", "Generic-constraint sliders: bouncing on limits, sprung, with friction.",
                 make_camera({0, 1, 1.2f}, 8, 0.3f, 0.5f),
                 with_ground([](auto &r) { sc::make_sliders(r); })});
    s.push_back({"ragdolls", "Joints", "A pile of 8 rag dolls.", make_camera({0, 1.2f, 0}, 7.5f, 0.4f, 0.3f),
                 with_ground([](auto &r) { sc::make_ragdoll_pile(r, 8); })});
    s.push_back({"vehicle", "Joints", "A car: hinged wheels on generic-constraint suspension.",
                 make_camera({0, 1, 0}, 12, 0.7f, 0.35f), build_vehicle});
    s.push_back({"terrain", "Meshes", "225 bodies on a terrain of 20,000 triangles.",
                 make_camera({0, 2, 0}, 45, 0.5f, 0.45f), [](edyn::registry &r) {
                     sc::make_mesh_pile(r, 225, 15);
                     return sample_state{};
                 }});
    s.push_back(
        {"paged_terrain", "Meshes",
         "The same terrain as a paged mesh: pages load near the bodies (only loaded pages are drawn).",
         make_camera({0, 2, 0}, 62, 0.5f, 0.6f), [](edyn::registry &r) {
             sc::mesh_pile_terrain terrain;
             terrain.paged = true;
             terrain.page_size = 500; // 40 pages
             sc::make_mesh_pile(r, 225, 15, 2, terrain);
             return sample_state{};
         }});
    return s;
}

} // namespace

void run_steps(edyn::registry &registry, sample_state &state, unsigned steps,
               const std::function<void(double)> &after_step) {
    auto dt = float(edyn::get_fixed_dt(registry));
    for (unsigned i = 0; i < steps; ++i) {
        if (state.on_frame) state.on_frame(registry, {}, dt);
        auto start = std::chrono::steady_clock::now();
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry); // asynchronous mode: the step is applied here
        if (after_step)
            after_step(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
}

const std::vector<sample> &all_samples() {
    static const std::vector<sample> samples = make_samples();
    return samples;
}

const sample *find_sample(const std::string &name) {
    for (auto &s : all_samples())
        if (s.name == name) return &s;
    return nullptr;
}

std::string sample_names() {
    std::string out;
    for (auto &s : all_samples()) {
        if (!out.empty()) out += ", ";
        out += s.name;
    }
    return out;
}

} // namespace testbed
