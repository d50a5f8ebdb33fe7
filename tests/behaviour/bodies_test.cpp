// Centre of mass shifts, and changing a body's kind and shape at run time.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>
#include <limits>
#include <string>

using namespace edyn;
using edyn::test::fall;
using edyn::test::world_fixture;

namespace {

// Velocity of the body's material point at world position p.
vector3 point_velocity(const registry &reg, entity e, const vector3 &p) {
    return static_cast<vector3>(reg.get<linvel>(e)) + cross(reg.get<angvel>(e), p - reg.get<position>(e));
}

void expect_near(const vector3 &measured, const vector3 &expected, scalar tolerance, const char *what) {
    EXPECT_LE(length(measured - expected), tolerance)
        << what << ": measured (" << measured.x << ", " << measured.y << ", " << measured.z << "), expected ("
        << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

} // namespace

using center_of_mass_shift = world_fixture;

// A sphere whose centre of mass is offset sideways lands on frictionless ground. The contact
// acts at the point under the sphere's centre, off the centre of mass by r, so the normal
// impulse J n gives dv = J n / m and dw = I^-1 (r x n) J: whatever J, dw_z / dv_y =
// m (r x n)_z / I_zz. With radius 0.5, m = 1, offset 0.2: r = (-0.2, -0.5, 0), (r x n)_z = -0.2,
// I_zz = 2/5 m R^2 + m 0.2^2 = 0.14, so the ratio is -1.4286. Without the offset it is 0.
TEST_F(center_of_mass_shift, an_offset_centre_of_mass_turns_a_vertical_impact_into_rotation) {
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.material->friction = 0;
    ground.shape = plane_shape{vector3_y, 0};
    make_rigidbody(reg, ground);

    const scalar R = scalar(0.5), m = 1, d = scalar(0.2);
    auto def = edyn::test::sphere_def(R, {0, R + scalar(0.01), 0}, m);
    def.material->friction = 0;
    def.gravity = vector3_zero;
    def.linvel = {0, -2, 0};
    def.center_of_mass = vector3{d, 0, 0};
    auto ball = make_rigidbody(reg, def);
    // The same ball, centred, far away.
    def.center_of_mass.reset();
    def.position.x = 10;
    auto centred = make_rigidbody(reg, def);

    EXPECT_NEAR(pos(ball).x, d, scalar(1e-6)) << "position is the centre of mass";
    EXPECT_NEAR(get_rigidbody_origin(reg, ball).x, 0, scalar(1e-6));
    auto I_zz = scalar(0.4) * m * R * R + m * d * d;
    EXPECT_NEAR(reg.get<inertia>(ball).row[2].z, I_zz, scalar(1e-5)) << "parallel axis theorem";

    edyn::test::step(reg);
    auto dv = vel(ball).y + 2;
    auto dw = angular(ball).z;
    ASSERT_GT(dv, scalar(0.5)) << "the ball did not hit the ground in the first step";
    auto expected_ratio = m * -d / I_zz;
    EXPECT_NEAR(dw / dv, expected_ratio, scalar(0.03) * std::abs(expected_ratio))
        << "dw_z / dv_y measured " << dw / dv << ", expected " << expected_ratio;
    // Restitution 0: the contact point stops, v_y + (w x r)_y = v_y - 0.2 w_z = 0, which with the
    // ratio above gives J = 2 / (1 + 0.2^2 / 0.14) and v_y = J - 2.
    auto J = 2 / (1 + d * d / I_zz);
    EXPECT_NEAR(vel(ball).y, J - 2, scalar(0.05)) << "rebound velocity, J = " << J;

    EXPECT_NEAR(angular(centred).z, 0, scalar(1e-6)) << "a centred ball must not turn";
    EXPECT_NEAR(vel(centred).y, 0, scalar(0.05));
}

TEST_F(center_of_mass_shift, moving_the_centre_of_mass_at_run_time_keeps_the_origin_and_its_motion) {
    auto def = edyn::test::box_def(test::unit_half, {1, 2, 3}, 2);
    def.orientation = normalize(quaternion{scalar(0.1), scalar(0.7), scalar(-0.2), scalar(0.6)});
    def.linvel = {1, 2, 3};
    def.angvel = {scalar(0.5), -1, 2};
    def.gravity = vector3_zero;
    auto box = make_rigidbody(reg, def);
    run_for(scalar(0.25));

    auto origin = get_rigidbody_origin(reg, box);
    auto origin_velocity = point_velocity(reg, box, origin);
    auto corner = origin + rotate(reg.get<orientation>(box), test::unit_half);
    auto corner_velocity = point_velocity(reg, box, corner);

    const vector3 com{scalar(0.1), scalar(-0.2), scalar(0.3)};
    set_center_of_mass(reg, box, com);
    expect_near(get_rigidbody_origin(reg, box), origin, scalar(1e-5), "origin");
    expect_near(pos(box), origin + rotate(reg.get<orientation>(box), com), scalar(1e-5), "centre of mass");
    expect_near(point_velocity(reg, box, origin), origin_velocity, scalar(1e-4), "origin velocity");
    expect_near(point_velocity(reg, box, corner), corner_velocity, scalar(1e-4), "corner velocity");
    ASSERT_TRUE(reg.all_of<center_of_mass>(box));
    expect_near(reg.get<center_of_mass>(box), com, 0, "center_of_mass component");
    // The box's inertia about the new centre: (m/3)(b^2 + c^2) + m (|d|^2 - d_x^2) and so on.
    auto I = reg.get<inertia>(box);
    auto m = scalar(2), base = m / 3 * (scalar(0.25) + scalar(0.25));
    EXPECT_NEAR(I.row[0].x, base + m * (com.y * com.y + com.z * com.z), scalar(1e-5));
    EXPECT_NEAR(I.row[0].y, -m * com.x * com.y, scalar(1e-5));

    // Back to the centroid: the same again.
    set_center_of_mass(reg, box, vector3_zero);
    expect_near(get_rigidbody_origin(reg, box), origin, scalar(1e-5), "origin after reset");
    expect_near(pos(box), origin, scalar(1e-5), "position after reset");
    EXPECT_FALSE(reg.all_of<center_of_mass>(box));
    expect_near(point_velocity(reg, box, corner), corner_velocity, scalar(1e-4),
                "corner velocity after reset");
}

TEST_F(center_of_mass_shift, a_body_free_of_torque_spins_about_its_centre_of_mass) {
    // Spinning about z at w, the shifted box's origin circles its centre of mass at radius
    // |com| and speed w |com|; the centre of mass does not move.
    auto def = edyn::test::box_def(test::unit_half, {0, 5, 0});
    def.gravity = vector3_zero;
    def.center_of_mass = vector3{scalar(0.3), 0, 0};
    def.angvel = {0, 0, 2};
    auto box = make_rigidbody(reg, def);
    auto com_start = pos(box);
    run_for(scalar(0.5));
    expect_near(pos(box), com_start, scalar(1e-5), "centre of mass");
    auto origin = get_rigidbody_origin(reg, box);
    EXPECT_NEAR(length(origin - com_start), scalar(0.3), scalar(1e-4));
    // After 0.5 s at 2 rad/s the origin has turned 1 rad about the centre of mass.
    auto angle = std::atan2((origin - com_start).y, (origin - com_start).x);
    EXPECT_NEAR(angle, -std::numbers::pi_v<scalar> + 1, scalar(2e-3)) << "origin angle " << angle;
}

using change_kind = world_fixture;

TEST_F(change_kind, a_falling_body_made_static_stops_and_made_dynamic_again_falls) {
    auto box = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, 10, 0}, 2));
    run_for(scalar(0.5));
    ASSERT_LT(vel(box).y, -4);

    rigidbody_set_kind(reg, box, rigidbody_kind::rb_static);
    EXPECT_TRUE(reg.all_of<static_tag>(box));
    EXPECT_FALSE((reg.any_of<dynamic_tag, kinematic_tag>(box)));
    EXPECT_EQ(reg.get<mass_inv>(box).s, 0);
    EXPECT_EQ(vel(box), vector3_zero);
    auto frozen = pos(box);
    // A ball dropped on it lands on it: the static body collides.
    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), frozen + vector3{0, 2, 0}));
    run_for(2);
    EXPECT_EQ(pos(box), frozen) << "a static body moved";
    EXPECT_NEAR(pos(ball).y, frozen.y + scalar(0.75), scalar(0.01)) << "ball on the static box";

    rigidbody_set_kind(reg, box, rigidbody_kind::rb_dynamic);
    EXPECT_TRUE(reg.all_of<dynamic_tag>(box));
    EXPECT_EQ(reg.get<mass>(box).s, 2) << "the mass it had before becoming static";
    run_for(scalar(0.5));
    EXPECT_NEAR(vel(box).y, -test::earth_g / 2, scalar(1e-3)) << "the box falls freely again";
    EXPECT_NEAR(pos(box).y, frozen.y - fall(reg, scalar(0.5)), scalar(1e-3));
    // The ball resting on it falls with it.
    EXPECT_NEAR(pos(ball).y - pos(box).y, scalar(0.75), scalar(0.02))
        << "the ball was left behind at " << pos(ball).y << " while the box fell to " << pos(box).y;
}

TEST_F(change_kind, a_body_made_kinematic_follows_its_velocity) {
    auto box = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, 10, 0}));
    rigidbody_set_kind(reg, box, rigidbody_kind::rb_kinematic);
    EXPECT_TRUE(reg.all_of<kinematic_tag>(box));
    reg.replace<linvel>(box, vector3{1, 0, 0});
    run_for(1);
    EXPECT_NEAR(pos(box).x, 1, scalar(1e-3));
    EXPECT_NEAR(pos(box).y, 10, scalar(1e-6)) << "gravity moved a kinematic body";
}

using change_shape = world_fixture;

TEST_F(change_shape, a_resting_sphere_given_a_smaller_radius_settles_lower) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, scalar(0.5), 0}, 2));
    // Long enough to fall asleep.
    run_for(2);
    EXPECT_NEAR(pos(ball).y, scalar(0.5), scalar(0.01));

    rigidbody_set_shape(reg, ball, shapes_variant_t{sphere_shape{scalar(0.25)}});
    auto I = scalar(0.4) * 2 * scalar(0.25) * scalar(0.25);
    EXPECT_NEAR(reg.get<inertia>(ball).row[0].x, I, scalar(1e-6)) << "inertia of the new shape";
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.25), scalar(0.01)) << "ball centre at " << pos(ball).y;

    // A box overlapping the ground is pushed out onto it.
    rigidbody_set_shape(reg, ball, shapes_variant_t{box_shape{test::unit_half}});
    EXPECT_TRUE(reg.all_of<box_shape>(ball));
    EXPECT_FALSE(reg.all_of<sphere_shape>(ball));
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.5), scalar(0.01)) << "box centre at " << pos(ball).y;

    // Amorphous: no collisions, it falls through the ground.
    rigidbody_set_shape(reg, ball, std::nullopt);
    EXPECT_FALSE((reg.any_of<box_shape, AABB>(ball)));
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.5) - fall(reg, 1), scalar(1e-3)) << "amorphous body at " << pos(ball).y;
}

// A shape replaced in place keeps the body's manifolds: their points, which a body at rest
// reuses from step to step, must be recomputed with the new shape.
TEST_F(change_shape, a_resting_sphere_given_a_larger_radius_in_place_rises) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto def = edyn::test::sphere_def(scalar(0.5), {0, scalar(0.5), 0}, 2);
    def.sleeping_disabled = true;
    auto ball = make_rigidbody(reg, def);
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.5), scalar(0.01));

    reg.replace<sphere_shape>(ball, sphere_shape{scalar(0.75)});
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.75), scalar(0.01)) << "ball centre at " << pos(ball).y;
}

// Shrunk in place, the ball must not stay standing on the point its old surface touched: that
// point, refreshed from pivots on the old shape, held it 25 cm up for good.
TEST_F(change_shape, a_resting_sphere_given_a_smaller_radius_in_place_settles_lower) {
    scenes::make_ground(reg, scalar(0.5), 0);
    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, scalar(0.5), 0}, 2));
    run_for(2);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(ball));

    reg.replace<sphere_shape>(ball, sphere_shape{scalar(0.25)});
    run_for(1);
    EXPECT_NEAR(pos(ball).y, scalar(0.25), scalar(0.01)) << "ball centre at " << pos(ball).y;
    auto &manifold = reg.get<contact_manifold>(reg.view<contact_manifold>().front());
    ASSERT_EQ(manifold.num_points, 1u);
    EXPECT_NEAR(manifold.point[manifold.ids[0]].distance, 0, scalar(0.01));
}

// A compound changed in place through the registry is finished again by the simulation: a
// child grown by patch holds a ball and stops rays where it now reaches, and a child removed
// lets them through. Before, its old bounds hid the grown child, and the removed one stayed in
// its tree, where a query read past the children.
TEST_F(change_shape, a_compound_changed_in_place_collides_as_it_now_is) {
    compound_shape shelf;
    shelf.add_shape(box_shape{scalar(0.1), scalar(0.1), scalar(0.1)});
    shelf.finish();
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = shelf;
    def.position = {0, 1, 0};
    auto grown = make_rigidbody(reg, def);

    // Twelve small boxes in a row 10 m away, the last under the point where a ball will fall.
    compound_shape row;
    for (int i = 0; i < 12; ++i)
        row.add_shape(box_shape{scalar(0.2), scalar(0.1), scalar(0.2)}, {scalar(i) * scalar(0.5), 0, 0});
    row.finish();
    def.shape = row;
    def.position = {10, 1, 0};
    auto shrunk = make_rigidbody(reg, def);
    run_for(0.1);

    reg.patch<compound_shape>(grown, [](compound_shape &c) {
        std::get<box_shape>(c.children[0].shape).half_extents = {1, scalar(0.1), 1};
    });
    reg.patch<compound_shape>(shrunk, [](compound_shape &c) { c.children.pop_back(); });
    auto on_grown = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {scalar(0.8), 2, scalar(0.8)}));
    auto past_shrunk = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {scalar(15.5), 2, 0}));
    auto on_shrunk = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {scalar(15), 2, 0}));
    run_for(2);
    EXPECT_NEAR(pos(on_grown).y, scalar(1.2), scalar(0.01)) << "the ball did not land on the grown child";
    EXPECT_NEAR(pos(on_shrunk).y, scalar(1.2), scalar(0.01))
        << "the ball did not land on the row's last child";
    EXPECT_LT(pos(past_shrunk).y, 0) << "the removed child still held the ball";

    if (!edyn::test::simulates_here(reg)) return; // rays are cast on the worker (raycast_async)
    auto hit = raycast(reg, {scalar(0.9), 3, scalar(-0.9)}, {scalar(0.9), -1, scalar(-0.9)});
    EXPECT_EQ(hit.entity, grown);
    EXPECT_NEAR(hit.fraction, scalar(0.475), scalar(1e-4))
        << "the ray stops on the grown child's top, 1.1 m up";
    EXPECT_EQ(raycast(reg, {scalar(15.5), scalar(1.5), 1}, {scalar(15.5), scalar(1.5), -1}).entity, null);
}

// Only the changed body's manifolds are recomputed: another pair resting nearby keeps reusing
// its points.
TEST_F(change_shape, other_resting_pairs_keep_reusing_their_contact_points) {
    if (!edyn::test::simulates_here(reg))
        GTEST_SKIP() << "contact reuse is the worker's own state in the asynchronous mode";
    scenes::make_ground(reg, scalar(0.5), 0);
    auto make_ball = [&](scalar x) {
        auto def = edyn::test::sphere_def(scalar(0.5), {x, scalar(0.5), 0}, 2);
        def.sleeping_disabled = true;
        return make_rigidbody(reg, def);
    };
    auto changed = make_ball(-5), other = make_ball(5);
    run_for(1);

    auto manifold_of = [&](entity body) -> contact_manifold & {
        for (auto m : reg.view<contact_manifold>()) {
            auto &manifold = reg.get<contact_manifold>(m);
            if (manifold.body[0] == body || manifold.body[1] == body) return manifold;
        }
        throw std::runtime_error("no manifold");
    };
    // Where body A was when collide() last ran, nudged by less than the reuse threshold: only
    // a new collide() overwrites it, and a reused pair keeps it.
    auto mark = [&](entity body) {
        auto &snapshot = manifold_of(body).last_collide;
        snapshot.posA.y += contact_reuse_max_distance / 10;
        return snapshot.posA;
    };
    auto still_marked = [&](entity body, const vector3 &marked) {
        return manifold_of(body).last_collide.posA == marked;
    };

    auto marked_changed = mark(changed), marked_other = mark(other);
    edyn::test::step(reg);
    ASSERT_TRUE(still_marked(changed, marked_changed)) << "a resting pair recomputed its points";
    ASSERT_TRUE(still_marked(other, marked_other)) << "a resting pair recomputed its points";

    reg.replace<sphere_shape>(changed, sphere_shape{scalar(0.75)});
    edyn::test::step(reg);
    EXPECT_FALSE(still_marked(changed, marked_changed)) << "points reused with the old shape";
    EXPECT_TRUE(still_marked(other, marked_other)) << "another body's shape change stopped this pair's reuse";
    run_for(1);
    EXPECT_NEAR(pos(changed).y, scalar(0.75), scalar(0.01)) << "ball centre at " << pos(changed).y;
    EXPECT_NEAR(pos(other).y, scalar(0.5), scalar(0.01)) << "ball centre at " << pos(other).y;
}

// A plane ignores its body's transform (the manual's "Rigid bodies"): the surface is where its
// normal and constant put it, wherever the body stands and however it is turned, and what rests
// on it rests still.
using plane_body = world_fixture;

TEST_F(plane_body, bodies_rest_and_sleep_on_a_plane_whose_body_is_moved_and_turned) {
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.shape = plane_shape{vector3_y, 0};
    ground.position = {3, 1, -2};
    ground.orientation = quaternion_axis_angle(normalize(vector3{1, 2, 3}), scalar(0.7));
    make_rigidbody(reg, ground);
    auto box = make_rigidbody(reg, edyn::test::box_def({0.5, 0.5, 0.5}, {0, scalar(0.6), 0}));
    auto ball = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.25), {4, scalar(0.3), 0}));
    auto capsule_def = rigidbody_def{};
    capsule_def.mass = 1;
    capsule_def.shape = capsule_shape{scalar(0.2), scalar(0.5), coordinate_axis::x};
    capsule_def.position = {-4, scalar(0.25), 0};
    auto capsule = make_rigidbody(reg, capsule_def);
    run_for(3);
    EXPECT_NEAR(pos(box).y, scalar(0.5), scalar(2e-3));
    EXPECT_NEAR(pos(ball).y, scalar(0.25), scalar(2e-3));
    EXPECT_NEAR(pos(capsule).y, scalar(0.2), scalar(2e-3));
    for (auto e : {box, ball, capsule}) {
        EXPECT_TRUE(reg.all_of<sleeping_tag>(e)) << "body " << to_integral(e) << " still awake after 3 s at "
                                                 << pos(e).x << ", " << pos(e).y << ", " << pos(e).z;
    }
    // Resting, not drifting: the box stayed where it landed.
    EXPECT_LT(std::hypot(pos(box).x, pos(box).z), scalar(0.01));
}

using written_motion = world_fixture;

// A position, orientation or velocity the program writes that is not finite (or an orientation
// of zero) is refused before the step that would use it, naming the body: integrated, it would
// spread through the contacts to every body touching it. The world steps on once it is mended.
TEST_F(written_motion, motion_that_is_not_finite_is_refused_before_the_step_naming_the_body) {
    scenes::make_ground(reg);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    run_for(0.5);
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto inf = std::numeric_limits<scalar>::infinity();

    auto expect_refused = [&](const char *component, const char *value) {
        try {
            run_for(0.1);
            ADD_FAILURE() << component << ": the step took it";
        } catch (const std::invalid_argument &e) {
            auto expected = "step: body entity " + std::to_string(to_index(bottom)) +
                            ", changed after it was made: " + component;
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(value), std::string::npos) << e.what();
        }
        EXPECT_TRUE(isfinite(pos(top))) << component << " spread to the box on top";
    };
    auto resting = pos(bottom);
    reg.replace<linvel>(bottom, vector3{nan, 0, 0});
    expect_refused("linvel must be finite", "(nan, 0, 0)");
    reg.replace<linvel>(bottom, vector3_zero);
    reg.patch<angvel>(bottom, [&](angvel &w) { w.y = inf; });
    expect_refused("angvel must be finite", "(0, inf, 0)");
    reg.replace<angvel>(bottom, vector3_zero);
    reg.replace<orientation>(bottom, quaternion{0, 0, 0, 0});
    expect_refused("orientation must be finite and not zero", "(0, 0, 0, 0)");
    reg.replace<orientation>(bottom, quaternion_identity);
    reg.patch<position>(bottom, [&](position &p) { p.x = -inf; });
    expect_refused("position must be finite", "(-inf");

    // Mended, the stack steps on and rests where it was.
    reg.replace<position>(bottom, resting);
    run_for(1);
    EXPECT_NEAR(pos(bottom).y, scalar(0.5), scalar(0.01));
    EXPECT_NEAR(pos(top).y, scalar(1.5), scalar(0.01));
}

// A shape, material or gravity the program patches, replaces or gives out of the ranges
// make_rigidbody accepts is refused before the step, naming the body, as written motion is: a
// box of NaN size would turn NaN every body it touches, and a restitution of 5 makes energy.
// The step names the first field at fault with the checks' own words.
TEST_F(written_motion, shapes_materials_and_gravity_out_of_range_are_refused_before_the_step) {
    auto ground = scenes::make_ground(reg);
    auto half = vector3{scalar(0.5), scalar(0.5), scalar(0.5)};
    auto bottom = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(0.5), 0}));
    auto top = make_rigidbody(reg, edyn::test::box_def(half, {0, scalar(1.5), 0}));
    auto shelf_def = edyn::test::box_def(half, {5, scalar(0.5), 0});
    shelf_def.kind = rigidbody_kind::rb_static;
    auto shelf = make_rigidbody(reg, shelf_def);
    run_for(0.5);
    auto nan = std::numeric_limits<scalar>::quiet_NaN();

    auto expect_refused = [&](entity body, const char *problem) {
        try {
            run_for(0.1);
            ADD_FAILURE() << problem << ": the step took it";
        } catch (const std::invalid_argument &e) {
            auto expected = "step: body entity " + std::to_string(to_index(body)) +
                            ", changed after it was made: " + problem;
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
        EXPECT_TRUE(isfinite(pos(top))) << problem << " spread to the box on top";
    };
    reg.patch<box_shape>(bottom, [&](box_shape &box) { box.half_extents.x = nan; });
    expect_refused(bottom, "box_shape: half_extents.x must be positive and finite, got nan");
    reg.patch<box_shape>(bottom, [&](box_shape &box) { box.half_extents.x = -scalar(0.5); });
    expect_refused(bottom, "box_shape: half_extents.x must be positive and finite, got -0.5");
    reg.replace<box_shape>(bottom, half);
    reg.patch<box_shape>(shelf, [&](box_shape &box) { box.half_extents.y = nan; });
    expect_refused(shelf, "box_shape: half_extents.y must be positive and finite, got nan");
    reg.replace<box_shape>(shelf, half);
    reg.patch<plane_shape>(ground, [](plane_shape &plane) { plane.normal = {0, 2, 0}; });
    expect_refused(ground, "plane_shape: normal must be a unit vector");
    reg.patch<plane_shape>(ground, [](plane_shape &plane) { plane.normal = vector3_y; });

    reg.patch<material>(bottom, [](material &m) { m.restitution = 5; });
    expect_refused(bottom, "material.restitution must be in [0, 1], got 5");
    reg.patch<material>(bottom, [](material &m) { m.restitution = 0; });
    reg.patch<material>(top, [](material &m) { m.friction = -1; });
    expect_refused(top, "material.friction must be in [0, inf), got -1");
    reg.patch<material>(top, [](material &m) { m.friction = scalar(0.5); });
    reg.patch<material>(bottom, [&](material &m) { m.stiffness = nan; });
    expect_refused(bottom, "material.stiffness must be positive, got nan");
    reg.patch<material>(bottom, [](material &m) { m.stiffness = large_scalar; });

    reg.emplace<gravity>(bottom, vector3{nan, 0, 0});
    expect_refused(bottom, "gravity must be finite and at most");
    reg.replace<gravity>(bottom, vector3{0, scalar(-9.8), 0});

    // Mended, the stack steps on and rests where it was.
    run_for(1);
    EXPECT_NEAR(pos(bottom).y, scalar(0.5), scalar(0.01));
    EXPECT_NEAR(pos(top).y, scalar(1.5), scalar(0.01));
    EXPECT_NEAR(pos(shelf).y, scalar(0.5), scalar(1e-6));
}
