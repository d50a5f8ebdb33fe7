// Row math of the joint solver against hand-computed values.
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>

using namespace edyn;

namespace {

solver_body unit_body(scalar inv_mass, scalar inv_inertia) {
    solver_body b;
    b.inv_mass = inv_mass;
    b.inv_inertia = diagonal_matrix(vector3_one * inv_inertia);
    return b;
}

constraint_solve_context relax_context(scalar h) {
    return make_constraint_solve_context(constraint_solver_settings{}, h, false);
}

} // namespace

TEST(constraint_row, effective_mass_of_a_linear_row_includes_the_lever_arms) {
    auto a = unit_body(scalar(0.5), 2);
    auto b = unit_body(scalar(0.25), 4);
    // Direction x with lever arms along y: r x n = -z for A, the same for B.
    auto j = linear_jacobian(vector3_x, {0, 1, 0}, {0, 1, 0});
    // K = 0.5 + 0.25 + 1 * 2 * 1 + 1 * 4 * 1.
    EXPECT_NEAR(row_effective_mass(j, a, b), scalar(1) / scalar(6.75), 1e-6);
}

TEST(constraint_row, relax_pass_of_an_equality_row_stops_the_relative_motion) {
    auto a = unit_body(1, 1);
    auto b = unit_body(1, 1);
    a.linvel = {3, 0, 0};
    b.linvel = {-1, 0, 0};
    scalar impulse = 0;
    auto j = linear_jacobian(vector3_x, vector3_zero, vector3_zero);
    solve_equality_row(j, 0, impulse, a, b, relax_context(scalar(0.01)));
    EXPECT_NEAR(row_velocity(j, a, b), 0, 1e-6);
    // Momentum is conserved and the impulse is half the relative velocity times reduced mass.
    EXPECT_NEAR(a.linvel.x + b.linvel.x, 2, 1e-6);
    EXPECT_NEAR(impulse, -2, 1e-6);
}

TEST(constraint_row, limit_row_only_pushes_and_lets_a_gap_close_within_the_substep) {
    auto a = unit_body(1, 0);
    auto b = unit_body(0, 0);
    auto j = linear_jacobian(vector3_y, vector3_zero, vector3_zero);
    a.linvel = {0, -5, 0};
    scalar impulse = 0;
    auto ctx = relax_context(scalar(0.01));
    // A gap of 1 cm may close at 1 m/s in 0.01 s: the row brakes to -1 m/s, no more.
    solve_limit_row(j, scalar(0.01), impulse, a, b, ctx);
    EXPECT_NEAR(a.linvel.y, -1, 1e-5);
    // Moving away: nothing to do, and the impulse never pulls.
    a.linvel = {0, 5, 0};
    impulse = 0;
    solve_limit_row(j, 0, impulse, a, b, ctx);
    EXPECT_EQ(impulse, 0);
    EXPECT_EQ(a.linvel.y, 5);
}

TEST(constraint_row, friction_row_is_bounded) {
    auto a = unit_body(0, 1);
    auto b = unit_body(0, 0);
    a.angvel = {0, 0, 10};
    scalar impulse = 0;
    solve_friction_row(angular_jacobian(vector3_z), scalar(0.5), impulse, a, b);
    EXPECT_NEAR(impulse, -0.5, 1e-6);
    EXPECT_NEAR(a.angvel.z, 9.5, 1e-6);
}

// Angular rows leave out the jacobian's zero linear parts and measure their mass when made: every
// row solver must give the same bits either way, for a non-unit axis, turned inertias, each pass
// and a body that does not move.
TEST(constraint_row, an_angular_row_gives_the_bits_of_its_jacobian) {
    auto turned_body = [](scalar inv_mass, const vector3 &diagonal, const quaternion &q) {
        solver_body body;
        body.inv_mass = inv_mass;
        auto r = to_matrix3x3(q);
        body.inv_inertia = r * diagonal_matrix(diagonal) * transpose(r);
        body.linvel = {scalar(0.3), scalar(-1.1), scalar(0.7)};
        body.angvel = vector3{scalar(1.7), scalar(-0.4), scalar(2.3)} * inv_mass;
        return body;
    };
    const vector3 axis{scalar(0.3), scalar(-0.8), scalar(0.45)};
    const auto a0 = turned_body(scalar(0.5), {scalar(2), scalar(3), scalar(5)},
                                quaternion_axis_angle(normalize(vector3{1, 2, 3}), scalar(0.7)));
    // The bodies turn at different rates, so that every row has something to stop.
    const auto b0 = turned_body(scalar(0.25), {scalar(4), scalar(1), scalar(7)},
                                quaternion_axis_angle(normalize(vector3{-2, 1, 1}), scalar(1.9)));
    const solver_body fixed{};
    const auto full = angular_jacobian(axis);

    for (const auto *b_start : {&b0, &fixed}) {
        // The row measures its mass when made, from the bodies' inertia as they start.
        const auto angular = make_angular_row(axis, a0, *b_start);
        EXPECT_EQ(angular.mass, row_effective_mass(full, a0, *b_start));
        for (bool biased : {false, true}) {
            auto ctx = make_constraint_solve_context(constraint_solver_settings{}, scalar(1) / 240, biased);
            // Each solver runs twice in a row, so that the second works from a non-zero impulse.
            auto run = [&](auto &&solve_once) {
                solver_body a1 = a0, b1 = *b_start, a2 = a0, b2 = *b_start;
                scalar impulse1 = scalar(0.02), impulse2 = scalar(0.02);
                for (int k = 0; k < 2; ++k) {
                    solve_once(full, impulse1, a1, b1);
                    solve_once(angular, impulse2, a2, b2);
                }
                EXPECT_EQ(impulse1, impulse2);
                for (int i = 0; i < 3; ++i) {
                    EXPECT_EQ(a1.linvel[i], a2.linvel[i]);
                    EXPECT_EQ(a1.angvel[i], a2.angvel[i]);
                    EXPECT_EQ(b1.linvel[i], b2.linvel[i]);
                    EXPECT_EQ(b1.angvel[i], b2.angvel[i]);
                }
            };
            run([&](const auto &row, scalar &impulse, solver_body &a, solver_body &b) {
                solve_equality_row(row, scalar(0.01), impulse, a, b, ctx);
            });
            run([&](const auto &row, scalar &impulse, solver_body &a, solver_body &b) {
                solve_limit_row(row, scalar(-0.01), impulse, a, b, ctx);
            });
            run([&](const auto &row, scalar &impulse, solver_body &a, solver_body &b) {
                solve_limit_row(row, scalar(0.001), impulse, a, b, ctx);
            });
            run([&](const auto &row, scalar &impulse, solver_body &a, solver_body &b) {
                solve_friction_row(row, scalar(0.05), impulse, a, b);
            });
            run([&](const auto &row, scalar &impulse, solver_body &a, solver_body &b) {
                solve_spring_row(row, scalar(0.1), 50, 2, impulse, a, b, ctx);
            });
        }
    }
    EXPECT_EQ(row_velocity(full, a0, b0), row_velocity(make_angular_row(axis, a0, b0), a0, b0));
    EXPECT_EQ(make_angular_row(axis, fixed, fixed).mass, 0);
    // The reversed row is the row made about -axis, mass included.
    auto reversed = -make_angular_row(axis, a0, b0);
    auto made = make_angular_row(-axis, a0, b0);
    EXPECT_EQ(reversed.mass, made.mass);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(reversed.axis[i], made.axis[i]);
}

TEST(constraint_row, spring_softness_matches_implicit_euler) {
    // m x'' = -k x - c x' integrated implicitly: v1 = (v0 - h k x0 / m) / (1 + h (c + h k) / m).
    const scalar k = 100, c = 3, m = 2, h = scalar(0.01), x0 = scalar(0.2), v0 = scalar(-1);
    auto a = unit_body(1 / m, 0);
    auto b = unit_body(0, 0);
    a.linvel = {v0, 0, 0};
    scalar impulse = 0;
    // Springs act in the biased pass only (once per sub-step).
    auto ctx = make_constraint_solve_context(constraint_solver_settings{}, h, true);
    solve_spring_row(linear_jacobian(vector3_x, vector3_zero, vector3_zero), x0, k, c, impulse, a, b, ctx);
    auto expected = (v0 - h * k * x0 / m) / (1 + h * (c + h * k) / m);
    EXPECT_NEAR(a.linvel.x, expected, 1e-5) << "measured " << a.linvel.x << ", expected " << expected;
}

TEST(constraint_row, current_pose_follows_the_bodies_motion) {
    joint_anchor anchor;
    anchor.rA = {1, 0, 0};
    anchor.rB = {0, 0, 0};
    anchor.separation = {0, 0, 0};
    solver_body a, b;
    a.delta_rotation = quaternion_axis_angle(vector3_z, half_pi);
    b.delta_position = {0, 1, 0};
    auto pose = current_pose(anchor, a, b);
    // rA turned to +y; A's pivot moved by (-1, 1, 0), B's by (0, 1, 0).
    EXPECT_NEAR(pose.rA.y, 1, 1e-6);
    EXPECT_NEAR(pose.d.x, -1, 1e-6);
    EXPECT_NEAR(pose.d.y, 0, 1e-6);
}

TEST(constraint_row, refresh_pose_keeps_the_pose_the_velocity_passes_read) {
    joint_anchor anchor;
    anchor.rA = {0, scalar(0.5), 0};
    anchor.rB = {scalar(-0.25), 0, 0};
    anchor.separation = {scalar(0.01), 0, 0};
    solver_body a, b;
    a.delta_rotation = quaternion_axis_angle(normalize(vector3{1, 2, 3}), scalar(0.3));
    a.delta_position = {scalar(0.1), 0, scalar(-0.2)};
    b.delta_rotation = quaternion_axis_angle(vector3_y, scalar(-0.7));
    refresh_pose(anchor, a, b);
    auto pose = current_pose(anchor, a, b);
    EXPECT_EQ(anchor.pose.rA, pose.rA);
    EXPECT_EQ(anchor.pose.rB, pose.rB);
    EXPECT_EQ(anchor.pose.d, pose.d);
}

TEST(constraint_row, point_mass_inverts_the_pivots_response_to_an_impulse) {
    // Bodies with full, non-diagonal inverse inertias and oblique lever arms.
    solver_body a, b;
    a.inv_mass = scalar(0.5);
    b.inv_mass = scalar(0.2);
    auto ra = to_matrix3x3(quaternion_axis_angle(normalize(vector3{1, 1, 0}), scalar(0.6)));
    auto rb = to_matrix3x3(quaternion_axis_angle(normalize(vector3{0, 1, 2}), scalar(-1.1)));
    a.inv_inertia = ra * diagonal_matrix(vector3{2, 3, 5}) * transpose(ra);
    b.inv_inertia = rb * diagonal_matrix(vector3{1, 4, scalar(0.5)}) * transpose(rb);
    joint_pose pose{
        {scalar(0.3), scalar(-0.4), scalar(0.2)}, {scalar(-0.1), scalar(0.5), scalar(0.35)}, vector3_zero};
    matrix3x3 inverse_k;
    ASSERT_TRUE(inverse_point_mass(a, b, pose, inverse_k));
    // K is the change of the pivots' relative velocity per unit impulse, measured by applying
    // unit impulses to the bodies.
    for (int i = 0; i < 3; ++i) {
        vector3 p = vector3_zero;
        p[i] = 1;
        auto sa = a, sb = b;
        auto before = relative_velocity(sa, sb, pose.rA, pose.rB);
        apply_impulse(sa, sb, inverse_k * p, pose.rA, pose.rB);
        auto change = relative_velocity(sa, sb, pose.rA, pose.rB) - before;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(change[k], k == i ? 1 : 0, 1e-5) << "impulse " << i << ", axis " << k;
        }
    }
    // Neither body moves: no inverse.
    solver_body fixed_a, fixed_b;
    EXPECT_FALSE(inverse_point_mass(fixed_a, fixed_b, pose, inverse_k));
}

TEST(constraint_row, an_open_limit_the_motion_does_not_reach_does_nothing) {
    auto a = unit_body(1, 0);
    auto b = unit_body(0, 0);
    auto j = linear_jacobian(vector3_y, vector3_zero, vector3_zero);
    auto ctx = relax_context(scalar(0.01));
    // 1 cm away, closing at 0.5 m/s: 5 mm in the sub-step, so the limit is not reached.
    a.linvel = {0, scalar(-0.5), 0};
    scalar impulse = 0;
    solve_limit_row(j, scalar(0.01), impulse, a, b, ctx);
    EXPECT_EQ(impulse, 0);
    EXPECT_EQ(a.linvel.y, scalar(-0.5));
    // Holding an impulse from earlier passes, the same open limit gives it back until the gap
    // closes exactly within the sub-step (1 m/s), keeping the rest.
    impulse = 2;
    solve_limit_row(j, scalar(0.01), impulse, a, b, ctx);
    EXPECT_NEAR(impulse, scalar(1.5), 1e-5);
    EXPECT_NEAR(a.linvel.y, -1, 1e-5);
}

TEST(constraint_row, unwrap_angle_continues_past_half_a_turn) {
    // Within half a turn of the last angle: the measured angle itself, bit for bit.
    EXPECT_EQ(unwrap_angle(scalar(0.5), scalar(0.7)), scalar(0.7));
    EXPECT_EQ(unwrap_angle(scalar(-3), scalar(-2.5)), scalar(-2.5));
    // Across the cut at +-pi, and several turns on.
    EXPECT_NEAR(unwrap_angle(3, -3), 2 * pi - 3, 1e-5);
    EXPECT_NEAR(unwrap_angle(-3, 3), 3 - 2 * pi, 1e-5);
    EXPECT_NEAR(unwrap_angle(scalar(4) * pi + scalar(0.1), scalar(0.2)), scalar(4) * pi + scalar(0.2), 1e-5);
}
