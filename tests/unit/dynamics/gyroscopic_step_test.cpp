// gyroscopic_step (integration.hpp): one implicit midpoint step of Euler's equations for a body
// turning with no torque.
#include <cmath>
#include <edyn/dynamics/integration.hpp>
#include <edyn/math/math.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>

using namespace edyn;

namespace gyroscopic_step_tests {

constexpr scalar step_60hz = scalar(1) / 60;

// Kinetic energy (times 2) and angular momentum, world space, of a body of object-space inertia
// `I` at orientation `orn` turning at `w`.
scalar energy(const matrix3x3 &I, const quaternion &orn, const vector3 &w) {
    auto wb = rotate(conjugate(orn), w);
    return dot(wb, I * wb);
}
vector3 momentum(const matrix3x3 &I, const quaternion &orn, const vector3 &w) {
    return rotate(orn, I * rotate(conjugate(orn), w));
}

quaternion random_orientation(std::mt19937 &rng) {
    std::normal_distribution<float> n;
    return normalize(quaternion{scalar(n(rng)), scalar(n(rng)), scalar(n(rng)), scalar(n(rng))});
}

} // namespace gyroscopic_step_tests

using namespace gyroscopic_step_tests;

TEST(gyroscopic_step, no_torque_leaves_the_angular_velocity_as_it_is) {
    auto orn = quaternion_axis_angle(normalize(vector3{1, 2, 3}), scalar(0.7));
    vector3 w{3, -2, 5};
    // A sphere's or a cube's inertia: the same about every axis.
    EXPECT_EQ(gyroscopic_step(w, diagonal_matrix(vector3{2, 2, 2}), orn, step_60hz), w);
    // Spinning about a principal axis of a box: exactly so in its own frame, to rounding in
    // another (the turn into the body's frame leaves a little off the axis).
    auto box = diagonal_matrix(vector3{1, 2, 3});
    EXPECT_EQ(gyroscopic_step(vector3{0, 4, 0}, box, quaternion_identity, step_60hz), (vector3{0, 4, 0}));
    auto about_y = rotate(orn, vector3{0, 4, 0});
    EXPECT_LE(length(gyroscopic_step(about_y, box, orn, step_60hz) - about_y), scalar(4e-6));
    EXPECT_EQ(gyroscopic_step(vector3_zero, box, orn, step_60hz), vector3_zero);
    // An inertia that is not positive, or not finite, is left alone rather than made a NaN of.
    EXPECT_EQ(gyroscopic_step(w, matrix3x3_zero, orn, step_60hz), w);
    auto inf = std::numeric_limits<scalar>::infinity();
    EXPECT_EQ(gyroscopic_step(w, diagonal_matrix(vector3{inf, 1, 1}), orn, step_60hz), w);
}

TEST(gyroscopic_step, keeps_the_momentum_s_length_never_adds_energy_and_ignores_the_inertia_s_scale) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1, 1), extent(scalar(0.05), 1);
    scalar worst_momentum = 0;
    for (int i = 0; i < 2000; ++i) {
        // A box's inertia (1 kg), sometimes in a frame turned from its principal axes (a full matrix).
        vector3 e{scalar(extent(rng)), scalar(extent(rng)), scalar(extent(rng))};
        auto I =
            diagonal_matrix(vector3{e.y * e.y + e.z * e.z, e.x * e.x + e.z * e.z, e.x * e.x + e.y * e.y} / 3);
        if (i % 2) {
            auto turn = to_matrix3x3(random_orientation(rng));
            I = turn * I * transpose(turn);
        }
        auto orn = random_orientation(rng);
        auto speed = scalar(i < 1000 ? 1 : 30); // h |ω| up to 0.03, then up to 0.9 rad a step
        vector3 w = vector3{scalar(unit(rng)), scalar(unit(rng)), scalar(unit(rng))} * speed;
        auto next = gyroscopic_step(w, I, orn, step_60hz);
        ASSERT_TRUE(isfinite(next)) << i;
        EXPECT_LE(energy(I, orn, next), energy(I, orn, w) * scalar(1 + 1e-5)) << i;
        auto L = length(momentum(I, orn, w));
        auto change = std::abs(length(momentum(I, orn, next)) - L) / L;
        if (i < 1000) worst_momentum = std::max(worst_momentum, change);
        // Only the ratios of the inertia count: a body a million times heavier turns the same.
        auto heavy = gyroscopic_step(w, I * scalar(1e6), orn, step_60hz);
        EXPECT_LE(length(heavy - next), scalar(1e-5) * length(w)) << i;
    }
    // The angular momentum keeps its length to second order in h |ω|. (Its direction, measured
    // at the step's orientation, turns back by h ω: the body's own turn over the step, which the
    // step's integration then makes, brings it back; the behaviour tests check it over time.)
    EXPECT_LT(worst_momentum, scalar(2e-4)) << worst_momentum;
}

TEST(gyroscopic_step, a_principal_frame_and_a_turned_one_give_the_same_result) {
    // The same body described twice: by its diagonal inertia, and by that inertia in a frame
    // turned by `turn`, at an orientation that undoes the turn. The world inertia is the same,
    // so must the step be.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1, 1);
    auto I = diagonal_matrix(vector3{scalar(0.3), scalar(0.5), scalar(0.7)});
    for (int i = 0; i < 200; ++i) {
        auto orn = random_orientation(rng);
        auto turn = random_orientation(rng);
        auto R = to_matrix3x3(turn);
        vector3 w = vector3{scalar(unit(rng)), scalar(unit(rng)), scalar(unit(rng))} * scalar(10);
        auto diagonal = gyroscopic_step(w, I, orn, step_60hz);
        auto full = gyroscopic_step(w, R * I * transpose(R), normalize(orn * conjugate(turn)), step_60hz);
        EXPECT_LE(length(full - diagonal), scalar(2e-5) * length(w)) << i;
        EXPECT_NE(diagonal, w) << "the step changed nothing: the test would not see a difference";
    }
}
