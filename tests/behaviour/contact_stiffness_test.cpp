// Contact stiffness and damping: the global soft contact, and a material's own spring, checked
// against the static deflection, period and overshoot of a mass on a spring.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>
#include <numbers>

using namespace edyn;
using edyn::test::world_fixture;

namespace {

constexpr scalar radius = scalar(0.1);

struct contact_stiffness : world_fixture {
    scalar g() const { return -get_settings(reg).gravity.y; }

    // A 1 kg sphere resting on the ground plane (it touches, unloaded, at y = radius).
    entity make_sphere(scalar stiffness, scalar damping = large_scalar) {
        scenes::make_ground(reg);
        auto def = edyn::test::sphere_def(radius, {0, radius, 0});
        def.material->stiffness = stiffness;
        def.material->damping = damping;
        return make_rigidbody(reg, def);
    }

    // How far the body has sunk below its unloaded height.
    scalar sink(entity e, scalar unloaded) const { return unloaded - pos(e).y; }
};

} // namespace

TEST_F(contact_stiffness, the_default_contact_frequency_is_the_one_the_sub_step_cap_allows) {
    // contact_hertz is capped at max_hertz_ratio times the sub-step rate; the default must be
    // the value that is used, not one the cap silently replaces.
    const auto &s = get_settings(reg);
    auto cap = s.contact.max_hertz_ratio * scalar(s.num_substeps) / s.fixed_dt;
    EXPECT_NEAR(s.contact.contact_hertz, cap, scalar(1e-3) * cap)
        << "contact_hertz " << s.contact.contact_hertz << " Hz, cap " << cap << " Hz";
}

TEST_F(contact_stiffness, a_rigid_contact_sinks_by_its_global_spring_only) {
    auto sphere = make_sphere(large_scalar);
    run_for(2);
    // The global spring: 90 Hz, so g / omega^2 = 0.03 mm.
    auto omega = 2 * std::numbers::pi_v<scalar> * get_settings(reg).contact.contact_hertz;
    auto expected = g() / (omega * omega);
    EXPECT_NEAR(sink(sphere, radius), expected, scalar(0.1) * expected)
        << "sank " << sink(sphere, radius) * 1000
        << " mm, spring of the global contact_hertz: " << expected * 1000 << " mm";
}

TEST_F(contact_stiffness, a_soft_material_sinks_by_load_over_stiffness) {
    const scalar k = 2000;
    auto sphere = make_sphere(k);
    run_for(2);
    auto expected = g() / k; // 4.9 mm for 1 kg
    EXPECT_NEAR(sink(sphere, radius), expected, scalar(0.01) * expected)
        << "sank " << sink(sphere, radius) * 1000 << " mm, expected m g / k = " << expected * 1000 << " mm";
}

TEST_F(contact_stiffness, a_box_on_four_points_sinks_by_load_over_the_whole_contact_stiffness) {
    // The stiffness is the contact's, shared by its points: four corners carry the box, and the
    // box still sinks m g / k, not a quarter of it.
    const scalar k = 4000, mass = 2;
    scenes::make_ground(reg);
    const scalar half = scalar(0.2);
    auto def = edyn::test::box_def({half, half, half}, {0, half, 0}, mass);
    def.material->stiffness = k;
    auto box = make_rigidbody(reg, def);
    run_for(2);
    auto expected = mass * g() / k;
    EXPECT_NEAR(sink(box, half), expected, scalar(0.02) * expected)
        << "sank " << sink(box, half) * 1000 << " mm, expected m g / k = " << expected * 1000 << " mm";
}

TEST_F(contact_stiffness, two_soft_materials_combine_in_series) {
    // A 1 kg box of stiffness 4000 N/m on a static block of 4000 N/m: 2000 N/m together.
    rigidbody_def ground_def;
    ground_def.kind = rigidbody_kind::rb_static;
    ground_def.shape = box_shape{vector3{2, scalar(0.5), 2}};
    ground_def.position = {0, scalar(-0.5), 0};
    ground_def.material->stiffness = 4000;
    make_rigidbody(reg, ground_def);
    const scalar half = scalar(0.1);
    auto def = edyn::test::box_def({half, half, half}, {0, half, 0});
    def.material->stiffness = 4000;
    auto box = make_rigidbody(reg, def);
    run_for(2);
    auto expected = g() / 2000;
    EXPECT_NEAR(sink(box, half), expected, scalar(0.02) * expected)
        << "sank " << sink(box, half) * 1000 << " mm, expected m g / (k/2) = " << expected * 1000 << " mm";
}

TEST_F(contact_stiffness, a_lightly_damped_contact_oscillates_at_the_spring_frequency) {
    // Released touching the ground, the sphere bounces on the contact spring: the time between
    // its deepest points is the period 2 pi sqrt(m / k). Steps of 1/240 s resolve the 0.14 s
    // period (each deepest point is placed by a parabola through three samples); the implicit
    // sub-steps lengthen it by about (omega h)^2 / 3, 0.03 %.
    set_fixed_dt(reg, scalar(1) / 240);
    const scalar k = 2000;
    auto sphere = make_sphere(k, scalar(0.5)); // damping ratio 0.006
    auto dt = get_fixed_dt(reg);
    std::vector<scalar> minima_times;
    scalar y0 = pos(sphere).y, y1 = y0;
    for (int i = 1; i <= 240; ++i) {
        edyn::test::step(reg);
        auto y2 = pos(sphere).y;
        if (i >= 2 && y1 < y0 && y1 <= y2) {
            auto offset = (y0 - y2) / (2 * (y0 - 2 * y1 + y2)); // in steps, from sample i - 1
            minima_times.push_back((scalar(i - 1) + offset) * dt);
        }
        y0 = y1;
        y1 = y2;
    }
    ASSERT_GE(minima_times.size(), 5u) << "the sphere did not oscillate on its contact";
    auto measured = (minima_times[4] - minima_times[0]) / 4;
    auto expected = 2 * std::numbers::pi_v<scalar> * std::sqrt(scalar(1) / k);
    EXPECT_NEAR(measured, expected, scalar(0.005) * expected)
        << "period " << measured << " s, expected 2 pi sqrt(m / k) = " << expected << " s";
}

TEST_F(contact_stiffness, an_underdamped_contact_overshoots_as_a_damped_spring_does) {
    // Load applied at once to a spring of damping ratio zeta: the deepest point is the static
    // deflection times 1 + exp(-pi zeta / sqrt(1 - zeta^2)). The implicit sub-steps add a
    // numerical damping ratio of about omega h / 2 (0.016 with steps of 1/240 s), so the
    // overshoot lies between the closed form with zeta and with zeta + omega h / 2, less what
    // sampling every 1/240 s can miss at the peak (under 1 %).
    set_fixed_dt(reg, scalar(1) / 240);
    const scalar k = 2000, mass = 1, zeta = scalar(0.2);
    auto sphere = make_sphere(k, 2 * zeta * std::sqrt(k * mass));
    scalar deepest = 0;
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        deepest = std::max(deepest, sink(sphere, radius));
    }
    auto overshoot = [](scalar z) {
        return std::exp(-std::numbers::pi_v<scalar> * z / std::sqrt(1 - z * z));
    };
    auto omega = std::sqrt(k / mass);
    auto h = get_fixed_dt(reg) / scalar(get_settings(reg).num_substeps);
    auto measured = deepest / (mass * g() / k) - 1;
    auto highest = overshoot(zeta), lowest = overshoot(zeta + omega * h / 2) - scalar(0.01);
    EXPECT_LE(measured, highest) << "overshoot " << measured << ", closed form " << highest;
    EXPECT_GE(measured, lowest) << "overshoot " << measured << ", closed form " << highest
                                << ", with the integrator's damping " << lowest;
}

TEST_F(contact_stiffness, a_material_stiffer_than_the_cap_is_as_rigid_as_the_default) {
    auto sphere = make_sphere(scalar(1e9));
    run_for(2);
    auto omega = 2 * std::numbers::pi_v<scalar> * get_settings(reg).contact.contact_hertz;
    auto expected = g() / (omega * omega);
    EXPECT_NEAR(sink(sphere, radius), expected, scalar(0.1) * expected)
        << "sank " << sink(sphere, radius) * 1000 << " mm";
    EXPECT_TRUE(std::isfinite(pos(sphere).y));
}
