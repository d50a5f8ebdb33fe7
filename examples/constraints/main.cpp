// Every kind of constraint once, each in a small world of its own, checked against what it
// promises: a pendulum keeps its length, a spring stretches by m g / k, a hinge keeps its
// plane, a CV joint turns its output at the input's speed, and so on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

constexpr edyn::scalar g = 9.8f;

bool report(bool ok, const char *line) {
    std::printf("%s%s\n", line, ok ? "" : "  <-- wrong");
    return ok;
}

// A fixed point to hang things from: static and without a shape, so nothing collides with it.
edyn::entity make_anchor(edyn::registry &registry, const edyn::vector3 &position) {
    auto def = edyn::rigidbody_def();
    def.kind = edyn::rigidbody_kind::rb_static;
    def.position = position;
    return edyn::make_rigidbody(registry, def);
}

edyn::entity make_ball(edyn::registry &registry, const edyn::vector3 &position, edyn::scalar mass = 1) {
    auto def = edyn::rigidbody_def();
    def.mass = mass;
    def.shape = edyn::sphere_shape{0.1};
    def.position = position;
    return edyn::make_rigidbody(registry, def);
}

edyn::vector3 pivot_in_world(const edyn::registry &registry, edyn::entity body, const edyn::vector3 &pivot) {
    return edyn::get_rigidbody_origin(registry, body) +
           edyn::rotate(registry.get<edyn::orientation>(body), pivot);
}

// A 1 m pendulum released from the horizontal: the ball joint keeps the ball on its circle.
bool point() {
    edyn::registry registry;
    edyn::attach(registry);
    auto anchor = make_anchor(registry, {0, 5, 0});
    auto bob = make_ball(registry, {1, 5, 0});
    edyn::make_constraint<edyn::point_constraint>(registry, anchor, bob, [](edyn::point_constraint &c) {
        c.pivot[0] = {0, 0, 0};
        c.pivot[1] = {-1, 0, 0};
    });
    edyn::scalar worst = 0;
    for (int step = 0; step < 120; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        auto length = edyn::distance(registry.get<edyn::position>(bob), edyn::vector3{0, 5, 0});
        worst = std::max(worst, std::abs(length - 1));
    }
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line,
                  "point:         pendulum length off 1 m by at most %.2f mm over 2 s (under 5)",
                  worst * 1000);
    return report(worst < 0.005f, line);
}

// A rigid rod between the pivots: the same test as the pendulum, with the bob hanging 1.5 m
// away and the rod free to turn at both ends.
bool distance() {
    edyn::registry registry;
    edyn::attach(registry);
    auto anchor = make_anchor(registry, {0, 5, 0});
    auto bob = make_ball(registry, {1.5, 5, 0});
    edyn::make_constraint<edyn::distance_constraint>(registry, anchor, bob,
                                                     [](edyn::distance_constraint &c) { c.distance = 1.5; });
    edyn::scalar worst = 0;
    for (int step = 0; step < 120; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        auto length = edyn::distance(registry.get<edyn::position>(bob), edyn::vector3{0, 5, 0});
        worst = std::max(worst, std::abs(length - 1.5f));
    }
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line,
                  "distance:      rod length off 1.5 m by at most %.2f mm over 2 s (under 5)", worst * 1000);
    return report(worst < 0.005f, line);
}

// A spring of rest length 1 m and 100 N/m, critically damped, holding 1 kg: Hooke's law says
// it settles m g / k longer.
bool soft_distance() {
    edyn::registry registry;
    edyn::attach(registry);
    auto anchor = make_anchor(registry, {0, 5, 0});
    auto bob = make_ball(registry, {0, 3.5, 0});
    const edyn::scalar k = 100, m = 1;
    edyn::make_constraint<edyn::soft_distance_constraint>(registry, anchor, bob,
                                                          [&](edyn::soft_distance_constraint &c) {
                                                              c.distance = 1;
                                                              c.stiffness = k;
                                                              c.damping = 2 * std::sqrt(k * m);
                                                          });
    for (int step = 0; step < 180; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto length = 5 - registry.get<edyn::position>(bob).y;
    auto expected = 1 + m * g / k;
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line, "soft distance: spring settled at %.3f m (expected 1 + m g / k = %.3f)",
                  length, expected);
    return report(std::abs(length - expected) < 0.002f, line);
}

// Six degrees of freedom, each locked, limited or free: only vertical motion left free makes
// a rail. A body pushed sideways and spun falls straight down it, without turning.
bool generic() {
    edyn::registry registry;
    edyn::attach(registry);
    auto anchor = make_anchor(registry, {0, 5, 0});
    auto def = edyn::rigidbody_def();
    def.shape = edyn::box_shape{0.2, 0.2, 0.2};
    def.position = {0, 5, 0};
    def.linvel = {2, 0, 1};
    def.angvel = {0, 3, 0};
    auto car = edyn::make_rigidbody(registry, def);
    edyn::make_constraint<edyn::generic_constraint>(
        registry, anchor, car, [](edyn::generic_constraint &c) { c.linear[1].mode = edyn::dof_mode::free; });
    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto p = registry.get<edyn::position>(car);
    auto turned = edyn::length(registry.get<edyn::angvel>(car));
    auto fell = 5 - p.y;
    edyn::detach(registry);
    char line[200];
    std::snprintf(
        line, sizeof line,
        "generic:       rail car fell %.2f m in 1 s (expected g t^2 / 2 = %.2f), %.1f mm off the rail", fell,
        g / 2, 1000 * std::hypot(p.x, p.z));
    return report(std::abs(fell - g / 2) < 0.05f && std::hypot(p.x, p.z) < 0.001f && turned < 0.01f, line);
}

// A bar hinged about z, swinging down, pushed along z at its tip: the hinge keeps it in the
// xy plane.
bool hinge() {
    edyn::registry registry;
    edyn::attach(registry);
    auto anchor = make_anchor(registry, {0, 5, 0});
    auto def = edyn::rigidbody_def();
    def.shape = edyn::box_shape{0.5, 0.05, 0.05};
    def.position = {0.5, 5, 0};
    auto bar = edyn::make_rigidbody(registry, def);
    edyn::make_constraint<edyn::hinge_constraint>(registry, anchor, bar, [](edyn::hinge_constraint &c) {
        c.pivot[1] = {-0.5, 0, 0};
        c.set_axes({0, 0, 1}, {0, 0, 1});
    });
    edyn::rigidbody_apply_impulse(registry, bar, {0, 0, 2}, {0.5, 0, 0});
    edyn::scalar worst = 0;
    for (int step = 0; step < 120; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        worst = std::max(worst, std::abs(registry.get<edyn::position>(bar).z));
    }
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line,
                  "hinge:         bar left its plane by at most %.2f mm over 2 s (under 2)", worst * 1000);
    return report(worst < 0.002f, line);
}

// A drive shaft along x turned at 2 rad/s drives a second one bent up by 30 degrees through a
// CV joint; each turns in a bearing (a hinge to the world). A constant-velocity joint turns its
// output exactly as fast as its input, whatever the bend.
bool cvjoint() {
    edyn::registry registry;
    edyn::attach(registry);
    const auto bend = edyn::to_radians(30);
    const edyn::vector3 out_axis{std::cos(bend), std::sin(bend), 0};
    const edyn::scalar rate = 2;
    auto anchor = make_anchor(registry, {0, 0, 0});
    auto def = edyn::rigidbody_def();
    def.gravity = edyn::vector3_zero; // weightless shafts, so only the drive loads the joint
    def.material.reset();             // the shafts overlap at the joint: no contacts
    def.shape = edyn::box_shape{0.5, 0.05, 0.05};
    def.position = {-0.5, 0, 0};
    auto input = edyn::make_rigidbody(registry, def);
    def.shape = edyn::box_shape{0.5, 0.2, 0.02};
    def.position = out_axis * edyn::scalar(0.5);
    def.orientation = edyn::quaternion_axis_angle({0, 0, 1}, bend);
    auto output = edyn::make_rigidbody(registry, def);
    edyn::make_constraint<edyn::hinge_constraint>(registry, anchor, input, [](edyn::hinge_constraint &c) {
        c.pivot[1] = {0.5, 0, 0};
        c.set_axes({1, 0, 0}, {1, 0, 0});
    });
    edyn::make_constraint<edyn::hinge_constraint>(registry, anchor, output, [&](edyn::hinge_constraint &c) {
        c.pivot[1] = {-0.5, 0, 0};
        c.set_axes(out_axis, {1, 0, 0});
    });
    edyn::make_constraint<edyn::cvjoint_constraint>(registry, input, output, [](edyn::cvjoint_constraint &c) {
        c.pivot[0] = {0.5, 0, 0};
        c.pivot[1] = {-0.5, 0, 0};
    });
    for (int step = 0; step < 120; ++step) {
        // The motor: the input is set back to its speed before every step.
        registry.replace<edyn::angvel>(input, edyn::vector3{rate, 0, 0});
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
    }
    auto output_rate = edyn::dot(registry.get<edyn::angvel>(output), out_axis);
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line,
                  "CV joint:      output shaft turns at %.4f rad/s through a 30 degree bend (expected %.4f)",
                  output_rate, rate);
    return report(std::abs(output_rate - rate) < 0.001f * rate, line);
}

// A 1 m rod on a ball joint, kept inside a 30 degree cone and kicked hard enough to swing it
// past the horizontal: its tilt never passes the cone's wall.
bool cone() {
    edyn::registry registry;
    edyn::attach(registry);
    const edyn::vector3 apex{0, 5, 0};
    const auto span = edyn::to_radians(30);
    auto anchor = make_anchor(registry, apex);
    auto def = edyn::rigidbody_def();
    def.shape = edyn::box_shape{0.05, 0.5, 0.05};
    def.position = {0, 4.5, 0};
    auto rod = edyn::make_rigidbody(registry, def);
    edyn::make_constraint<edyn::point_constraint>(registry, anchor, rod, [](edyn::point_constraint &c) {
        c.pivot[1] = {0, 0.5, 0};
    });
    edyn::make_constraint<edyn::cone_constraint>(registry, anchor, rod, [&](edyn::cone_constraint &c) {
        c.pivot[1] = {0, -0.5, 0};
        // The cone's axis is the frame's first column: straight down.
        c.frame = edyn::matrix3x3_columns({0, -1, 0}, {1, 0, 0}, {0, 0, 1});
        c.span_angle[0] = c.span_angle[1] = span;
    });
    edyn::rigidbody_apply_impulse(registry, rod, {4, 0, 1.5}, {0, -0.5, 0});
    edyn::scalar largest = 0;
    for (int step = 0; step < 180; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        auto tip = pivot_in_world(registry, rod, {0, -0.5, 0}) - apex;
        largest = std::max(largest, std::atan2(std::hypot(tip.x, tip.z), -tip.y));
    }
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line, "cone:          kicked rod tilted at most %.1f degrees (cone: 30)",
                  edyn::to_degrees(largest));
    return report(largest < span + edyn::to_radians(1) && largest > span - edyn::to_radians(1), line);
}

// Newton's law of gravitation between two bodies, the world's gravity off: a moon released
// 100 m from a 10^14 kg planet falls towards it at G M / r^2 (r shrinks by under 0.4%
// in the second it falls, so the acceleration barely grows).
bool gravity() {
    edyn::registry registry;
    edyn::attach(registry);
    edyn::set_gravity(registry, edyn::vector3_zero);
    const edyn::scalar planet_mass = 1e14, r = 100;
    auto planet = make_ball(registry, {0, 0, 0}, planet_mass);
    auto moon = make_ball(registry, {r, 0, 0});
    edyn::make_constraint<edyn::gravity_constraint>(registry, planet, moon);
    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto fell = r - registry.get<edyn::position>(moon).x;
    auto expected = edyn::gravitational_constant * planet_mass / (r * r) / 2;
    edyn::detach(registry);
    char line[200];
    std::snprintf(
        line, sizeof line,
        "gravity:       moon fell %.4f m towards the planet in 1 s (expected G M t^2 / 2 r^2 = %.4f)", fell,
        expected);
    return report(std::abs(fell - expected) < 0.01f * expected, line);
}

// No force at all, only an edge in the entity graph: two bodies 50 m apart share an island
// (so they sleep, wake and are simulated together).
bool null() {
    edyn::registry registry;
    // Islands are kept where the simulation runs: here, in the calling thread.
    edyn::attach(registry, edyn::init_config{edyn::execution_mode::sequential});
    auto a = make_ball(registry, {0, 5, 0});
    auto b = make_ball(registry, {50, 5, 0});
    auto island_of = [&](edyn::entity e) { return registry.get<edyn::island_resident>(e).island_entity; };
    auto apart = island_of(a) != island_of(b);
    edyn::make_constraint<edyn::null_constraint>(registry, a, b);
    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto together = island_of(a) == island_of(b);
    auto still_apart = registry.get<edyn::position>(b).x - registry.get<edyn::position>(a).x;
    edyn::detach(registry);
    char line[200];
    std::snprintf(line, sizeof line, "null:          bodies %.1f m apart in %s island (expected 50 m, one)",
                  still_apart, together ? "one" : "two");
    return report(apart && together && std::abs(still_apart - 50) < 0.001f, line);
}

} // namespace

int main() {
    // Evaluated one by one, so that every line is printed even when one fails.
    int failures = 0;
    for (auto example : {point, distance, soft_distance, generic, hinge, cvjoint, cone, gravity, null})
        failures += example() ? 0 : 1;
    return failures == 0 ? 0 : 1;
}
