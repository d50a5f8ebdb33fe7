// A turning body against Euler's equations: its gyroscopic torque, ω × Iω, in free flight and on
// a pivot (gyroscopic_step in integration.hpp).
#include "joints_support.hpp"
#include <cmath>

using namespace edyn;
using edyn::test::world_fixture;

using free_rotation = world_fixture;
using gyroscope = world_fixture;

namespace rotation_tests {

// A 2 kg box of 0.2 × 0.6 × 1.2 m: its three moments of inertia differ (x the smallest, y the
// intermediate, z the largest), in no gravity.
entity make_tumbling_box(registry &reg, const vector3 &angvel) {
    set_gravity(reg, vector3_zero);
    auto def = edyn::test::box_def({scalar(0.1), scalar(0.3), scalar(0.6)}, vector3_zero, 2);
    def.angvel = angvel;
    def.sleeping_disabled = true;
    return make_rigidbody(reg, def);
}

vector3 world_momentum(const registry &reg, entity e) {
    auto &orn = reg.get<orientation>(e);
    matrix3x3 I = reg.get<inertia>(e);
    return rotate(orn, I * rotate(conjugate(orn), static_cast<vector3>(reg.get<angvel>(e))));
}

scalar kinetic_energy(const registry &reg, entity e) {
    return dot(static_cast<vector3>(reg.get<angvel>(e)), world_momentum(reg, e)) / 2;
}

// The angular velocity in the body's own frame.
vector3 body_angvel(const registry &reg, entity e) {
    return rotate(conjugate(reg.get<orientation>(e)), static_cast<vector3>(reg.get<angvel>(e)));
}

} // namespace rotation_tests

using namespace rotation_tests;

TEST_F(free_rotation, the_angular_momentum_keeps_its_direction_and_the_energy_stays) {
    // Spun about no principal axis, the box wobbles: its angular velocity wanders in the world,
    // but its angular momentum may not, nor may its energy.
    auto box = make_tumbling_box(reg, {3, 2, 1});
    auto L0 = world_momentum(reg, box);
    auto E0 = kinetic_energy(reg, box);
    scalar worst_momentum = 0, worst_energy = 0, moved = 0;
    auto w0 = static_cast<vector3>(reg.get<angvel>(box));
    for (int second = 0; second < 10; ++second) {
        run_for(1);
        worst_momentum = std::max(worst_momentum, length(world_momentum(reg, box) - L0) / length(L0));
        worst_energy = std::max(worst_energy, std::abs(kinetic_energy(reg, box) - E0) / E0);
        moved = std::max(moved, length(static_cast<vector3>(reg.get<angvel>(box)) - w0));
    }
    EXPECT_LT(worst_momentum, scalar(0.02)) << "the angular momentum turned or changed its length";
    EXPECT_LT(worst_energy, scalar(0.005)) << "the kinetic energy changed";
    EXPECT_GT(moved, scalar(0.5)) << "the angular velocity stayed put in the world: no wobble";
}

TEST_F(free_rotation, a_spin_about_the_intermediate_axis_flips_and_the_others_stay) {
    // The tennis racket theorem: a spin about the axis of intermediate inertia is unstable. A
    // hundredth of a rad/s off it, the body turns over (its spin in its own frame reverses) and
    // back again, every 4.4 s; about the smallest and the largest axes it stays.
    auto intermediate = make_tumbling_box(reg, {scalar(0.01), 5, 0});
    auto smallest = make_rigidbody(reg, [] {
        auto def = edyn::test::box_def({scalar(0.1), scalar(0.3), scalar(0.6)}, {10, 0, 0}, 2);
        def.angvel = vector3{5, scalar(0.01), 0};
        def.sleeping_disabled = true;
        return def;
    }());
    auto largest = make_rigidbody(reg, [] {
        auto def = edyn::test::box_def({scalar(0.1), scalar(0.3), scalar(0.6)}, {-10, 0, 0}, 2);
        def.angvel = vector3{scalar(0.01), 0, 5};
        def.sleeping_disabled = true;
        return def;
    }());
    std::vector<double> flips;
    auto sign = body_angvel(reg, intermediate).y > 0;
    scalar least_other = 5, peak = 0;
    for (int i = 0; i < 60 * 14; ++i) {
        edyn::test::step(reg);
        auto w = body_angvel(reg, intermediate);
        if ((w.y > 0) != sign) {
            sign = w.y > 0;
            flips.push_back(get_simulation_time(reg));
        }
        peak = std::max(peak, std::abs(w.y));
        least_other = std::min({least_other, body_angvel(reg, smallest).x, body_angvel(reg, largest).z});
    }
    ASSERT_GE(flips.size(), 3u) << "the intermediate spin did not keep turning over";
    // Each turn over takes the same time: nothing is lost or gained from one to the next.
    auto first = flips[1] - flips[0], second = flips[2] - flips[1];
    EXPECT_NEAR(second, first, 0.05 * first);
    EXPECT_NEAR(peak, 5, 0.05) << "the spin's speed changed";
    EXPECT_GT(least_other, scalar(4.99)) << "a spin about a stable axis wandered off it";
}

TEST_F(gyroscope, a_spinning_wheel_on_a_pivot_precesses_at_m_g_l_over_its_spin_momentum) {
    // A wheel (a disc of radius 0.5 m, 1 kg) spinning at 100 rad/s about its horizontal axle, whose
    // end 0.5 m from its centre rests on a pivot. Gravity's torque turns the spin's momentum:
    // the axle sweeps around the pivot, level, at Ω = m g l / (I ω) instead of falling. The
    // step applies the gyroscopic torque once per step, so the wheel sags by about the torque's
    // work over half a step, each step (τ dt / (2 I_pivot) rad/s): at 240 Hz it stays level
    // to 0.1 rad over two seconds, and precesses at the right rate to 2 %; at 60 Hz, 0.3 rad and
    // 12 %. (Without the gyroscopic torque it sweeps at twice the rate.)
    for (int hz : {240, 60}) {
        registry r;
        attach(r, edyn::test::test_config());
        set_fixed_dt(r, scalar(1) / scalar(hz));
        auto pivot = edyn::test::make_anchor(r, {0, 2, 0});
        rigidbody_def def;
        def.mass = 1;
        def.shape = cylinder_shape{scalar(0.5), scalar(0.025), coordinate_axis::x};
        def.position = {scalar(0.5), 2, 0};
        def.angvel = {100, 0, 0};
        def.sleeping_disabled = true;
        auto wheel = make_rigidbody(r, def);
        make_constraint<point_constraint>(r, pivot, wheel, [](point_constraint &c) {
            c.pivot[0] = vector3_zero;
            c.pivot[1] = {-scalar(0.5), 0, 0};
        });
        auto I = r.get<inertia>(wheel).row[0].x; // ½ m r²
        auto expected_rate = 1 * edyn::test::earth_g * scalar(0.5) / (I * 100);

        double swept = 0, lowest = 0;
        auto previous = vector3_x;
        for (int i = 0; i < 2 * hz; ++i) {
            edyn::test::step(r);
            auto axle = rotate(r.get<orientation>(wheel), vector3_x);
            // About +y, from +x towards -z: the sense that the spin's momentum gives.
            auto flat = normalize(vector3{axle.x, 0, axle.z});
            auto flat_before = normalize(vector3{previous.x, 0, previous.z});
            swept += std::atan2(double(cross(flat_before, flat).y), double(dot(flat_before, flat)));
            lowest = std::min(lowest, std::asin(double(axle.y)));
            previous = axle;
        }
        auto rate = swept / 2;
        EXPECT_NEAR(rate, expected_rate, (hz == 240 ? 0.02 : 0.12) * expected_rate) << hz << " Hz";
        EXPECT_GT(lowest, hz == 240 ? -0.1 : -0.3) << hz << " Hz: the wheel fell";
        detach(r);
    }
}
