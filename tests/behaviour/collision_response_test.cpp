// Kinematic bodies pushing dynamic ones, and collision filtering.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using edyn::test::fall;
using edyn::test::world_fixture;

namespace {

struct kinematic_push : world_fixture {
    entity kin{null}, box{null};

    // A kinematic box 1.5 m to the left of a dynamic box, both on the ground, 50 cm apart.
    void make_scene() {
        scenes::make_ground(reg, scalar(0.5), 0);
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_kinematic;
        def.shape = box_shape{test::unit_half};
        // Slightly above the ground: kinematic and static bodies do not interact anyway.
        def.position = {scalar(-1.5), scalar(0.51), 0};
        kin = make_rigidbody(reg, def);
        box = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, scalar(0.5), 0}));
    }

    // Gap between the kinematic box's right face and the dynamic box's left face (negative when
    // they overlap).
    scalar gap() const { return pos(box).x - pos(kin).x - 1; }
};

} // namespace

TEST_F(kinematic_push, a_kinematic_box_moving_at_its_linvel_pushes_a_dynamic_box) {
    make_scene();
    const scalar speed = 1;
    reg.replace<linvel>(kin, vector3{speed, 0, 0});
    scalar min_gap = large_scalar;
    for (int i = 0; i < 180; ++i) {
        edyn::test::step(reg);
        min_gap = std::min(min_gap, gap());
    }
    // The kinematic body follows its velocity exactly, whatever it hits.
    EXPECT_NEAR(pos(kin).x, scalar(-1.5) + 3 * speed, scalar(1e-3)) << "kinematic body at " << pos(kin).x;
    EXPECT_EQ(vel(kin), (vector3{speed, 0, 0}));
    // Pushed for the last 2.5 s: it moves with the pusher, in contact.
    EXPECT_NEAR(vel(box).x, speed, scalar(0.02)) << "pushed box speed " << vel(box).x;
    EXPECT_NEAR(gap(), 0, scalar(0.03)) << "the boxes separated or overlap";
    EXPECT_GT(min_gap, scalar(-0.03)) << "the kinematic box went " << -min_gap << " m into the dynamic one";
    EXPECT_NEAR(pos(box).y, scalar(0.5), scalar(0.01));
}

TEST_F(kinematic_push, a_kinematic_box_placed_by_the_program_every_step_pushes_a_dynamic_box) {
    make_scene();
    const scalar speed = 1;
    auto dt = get_fixed_dt(reg);
    scalar min_gap = large_scalar;
    for (int i = 1; i <= 180; ++i) {
        // As a program animating it would: the next pose and the velocity that leads there.
        reg.replace<position>(kin, vector3{scalar(-1.5) + speed * dt * scalar(i - 1), scalar(0.51), 0});
        reg.replace<linvel>(kin, vector3{speed, 0, 0});
        edyn::test::step(reg);
        min_gap = std::min(min_gap, gap());
    }
    EXPECT_NEAR(pos(kin).x, scalar(-1.5) + 3 * speed, scalar(1e-3));
    EXPECT_NEAR(vel(box).x, speed, scalar(0.02)) << "pushed box speed " << vel(box).x;
    EXPECT_NEAR(gap(), 0, scalar(0.03));
    EXPECT_GT(min_gap, scalar(-0.03)) << "the kinematic box went " << -min_gap << " m into the dynamic one";
}

TEST_F(kinematic_push, a_box_resting_on_a_rising_kinematic_platform_is_carried_up) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = box_shape{vector3{2, scalar(0.5), 2}};
    def.linvel = {0, scalar(0.5), 0};
    auto platform = make_rigidbody(reg, def);
    auto box = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, 1, 0}));
    run_for(2);
    EXPECT_NEAR(pos(platform).y, 1, scalar(1e-3));
    EXPECT_NEAR(pos(box).y, 2, scalar(0.02)) << "box at " << pos(box).y << ", expected on the platform at 2";
    EXPECT_NEAR(vel(box).y, scalar(0.5), scalar(0.02));
}

// Collision filtering: a ball dropped from 1 m onto the ground lands at y = r unless filtered,
// when it falls freely through it.
namespace {

struct filtering : world_fixture {
    entity ground{null};
    static constexpr scalar r = scalar(0.25);

    void SetUp() override {
        world_fixture::SetUp();
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.shape = plane_shape{vector3_y, 0};
        def.collision_group = 1;
        ground = make_rigidbody(reg, def);
    }

    entity drop_ball(scalar x, std::uint64_t group = collision_filter::all_groups,
                     std::uint64_t mask = collision_filter::all_groups) {
        auto def = edyn::test::sphere_def(r, {x, 1 + r, 0});
        def.collision_group = group;
        def.collision_mask = mask;
        return make_rigidbody(reg, def);
    }

    bool fell_through(entity ball) const {
        // After 1 s of free fall from 1 m above the ground.
        return std::abs(pos(ball).y - (1 + r - fall(reg, 1))) < scalar(1e-3);
    }
    bool landed(entity ball) const { return std::abs(pos(ball).y - r) < scalar(0.01); }

    std::size_t manifold_count(entity body) {
        std::size_t n = 0;
        for (auto e : reg.view<contact_manifold>()) {
            auto &m = reg.get<contact_manifold>(e);
            n += m.body[0] == body || m.body[1] == body;
        }
        return n;
    }
};

struct ghost {};

bool no_ghosts(const registry &reg, entity a, entity b) {
    if (reg.all_of<ghost>(a) || reg.all_of<ghost>(b)) return false;
    return should_collide_default(reg, a, b);
}

} // namespace

TEST_F(filtering, groups_and_masks_let_bodies_pass_through_each_other) {
    // Out of the ground's group by its mask.
    auto masked = drop_ball(0, collision_filter::all_groups, ~std::uint64_t(1));
    // In no group at all: (group & ground.mask) == 0.
    auto groupless = drop_ball(2, 0);
    // The manual's example: group 2, mask ~1 against a body in group 1.
    auto manual = drop_ball(4, std::uint64_t(1) << 1, ~std::uint64_t(1));
    auto control = drop_ball(6);
    run_for(1);
    EXPECT_TRUE(fell_through(masked)) << "masked ball at " << pos(masked).y;
    EXPECT_TRUE(fell_through(groupless)) << "group-less ball at " << pos(groupless).y;
    EXPECT_TRUE(fell_through(manual)) << "ball at " << pos(manual).y;
    EXPECT_TRUE(landed(control)) << "unfiltered ball at " << pos(control).y;
    EXPECT_EQ(manifold_count(masked) + manifold_count(groupless) + manifold_count(manual), 0u);
}

TEST_F(filtering, two_dynamic_bodies_in_excluded_groups_pass_through_each_other) {
    // A ball falls onto a box resting on the ground; their groups exclude each other.
    auto box_def = edyn::test::box_def(test::unit_half, {0, scalar(0.5), 0});
    box_def.collision_group = std::uint64_t(1) << 2;
    box_def.collision_mask = ~(std::uint64_t(1) << 3);
    auto box = make_rigidbody(reg, box_def);
    auto ball = drop_ball(0, std::uint64_t(1) << 3, ~(std::uint64_t(1) << 2));
    run_for(2);
    EXPECT_TRUE(landed(ball)) << "ball at " << pos(ball).y << ", expected on the ground inside the box";
    EXPECT_NEAR(pos(box).y, scalar(0.5), scalar(0.01));
    EXPECT_NEAR(pos(box).x, 0, scalar(1e-3)) << "the ball pushed the box";
}

TEST_F(filtering, exclude_collision_lets_a_pair_pass_through) {
    auto excluded = drop_ball(0);
    auto control = drop_ball(2);
    exclude_collision(reg, excluded, ground);
    run_for(1);
    EXPECT_TRUE(fell_through(excluded)) << "excluded ball at " << pos(excluded).y;
    EXPECT_TRUE(landed(control)) << "control ball at " << pos(control).y;
}

TEST_F(filtering, a_custom_should_collide_replaces_the_default) {
    auto ghost_ball = drop_ball(0);
    reg.emplace<ghost>(ghost_ball);
    auto control = drop_ball(2);
    // The filter runs where the step runs: in the asynchronous mode the ghost tag must be sent
    // to the worker's registry.
    register_external_components<ghost>(reg);
    set_should_collide(reg, &no_ghosts);
    run_for(1);
    EXPECT_TRUE(fell_through(ghost_ball)) << "ghost ball at " << pos(ghost_ball).y;
    EXPECT_TRUE(landed(control)) << "control ball at " << pos(control).y;
}

TEST_F(filtering, changing_the_filter_of_a_resting_body_at_run_time_drops_it_through) {
    auto ball = drop_ball(0);
    // Long enough to land and fall asleep.
    run_for(2);
    ASSERT_TRUE(landed(ball)) << "ball at " << pos(ball).y;
    ASSERT_EQ(manifold_count(ball), 1u);

    reg.replace<collision_filter>(ball, collision_filter{collision_filter::all_groups, ~std::uint64_t(1)});
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    EXPECT_EQ(manifold_count(ball), 0u) << "the manifold with the ground survived the new filter";
    run_for(1);
    EXPECT_NEAR(pos(ball).y, r - fall(reg, 1), scalar(1e-3))
        << "ball at " << pos(ball).y << ", expected free fall";
}

TEST_F(filtering, a_new_should_collide_applies_to_resting_pairs_and_the_default_comes_back) {
    auto ball = drop_ball(0);
    auto control = drop_ball(2);
    run_for(2);
    ASSERT_TRUE(landed(ball)) << "ball at " << pos(ball).y;
    ASSERT_EQ(manifold_count(ball), 1u);

    reg.emplace<ghost>(ball);
    register_external_components<ghost>(reg);
    set_should_collide(reg, &no_ghosts);
    // The ball sleeps: losing its contact with the ground wakes it.
    ASSERT_TRUE(reg.all_of<sleeping_tag>(ball));
    run_for(scalar(0.25));
    EXPECT_EQ(manifold_count(ball), 0u) << "the resting pair kept its contact under the new function";
    auto sunk = pos(ball).y;
    EXPECT_LT(sunk, r - scalar(0.2)) << "ball at " << sunk << ", expected it to fall";
    EXPECT_TRUE(landed(control)) << "control ball at " << pos(control).y;

    // Back to the default while the ball is still in the ground's box: the pair is found again
    // and the ground pushes the ball back out.
    reset_should_collide(reg);
    run_for(2);
    EXPECT_EQ(manifold_count(ball), 1u);
    EXPECT_GT(pos(ball).y, sunk + scalar(0.2)) << "ball at " << pos(ball).y << ", from " << sunk;
}

// Two boxes excluded from each other rest on the ground overlapping by 40 cm and fall asleep.
// Taking the exclusion away, by removing the component or by emptying it, must let them collide:
// they push apart.
TEST_F(filtering, boxes_asleep_inside_each_other_push_apart_once_their_exclusion_goes) {
    auto overlapping_pair = [&](scalar z) {
        auto a = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, scalar(0.5), z}));
        auto b = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {scalar(0.6), scalar(0.5), z}));
        exclude_collision(reg, a, b);
        return std::pair{a, b};
    };
    auto removed = overlapping_pair(-3);
    auto emptied = overlapping_pair(3);
    run_for(2);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(removed.first));
    ASSERT_TRUE(reg.all_of<sleeping_tag>(emptied.first));

    for (auto e : {removed.first, removed.second})
        reg.remove<collision_exclusion>(e);
    for (auto e : {emptied.first, emptied.second})
        reg.patch<collision_exclusion>(e, [](collision_exclusion &ex) { ex = {}; });
    run_for(1);
    for (auto [a, b] : {removed, emptied}) {
        EXPECT_GT(pos(b).x - pos(a).x, scalar(0.99)) << "the boxes still overlap";
        EXPECT_EQ(manifold_count(a), 2u) << "the box touches the ground and the other box";
    }
}

TEST_F(filtering, excluding_a_resting_pair_at_run_time_drops_it_through) {
    auto ball = drop_ball(0);
    run_for(2);
    ASSERT_TRUE(landed(ball)) << "ball at " << pos(ball).y;
    exclude_collision(reg, ball, ground);
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    EXPECT_EQ(manifold_count(ball), 0u);
    run_for(1);
    EXPECT_NEAR(pos(ball).y, r - fall(reg, 1), scalar(1e-3))
        << "ball at " << pos(ball).y << ", expected free fall";
}

TEST_F(filtering, filtering_the_ground_out_from_under_resting_bodies_drops_them_through) {
    auto ball = drop_ball(0);
    run_for(2);
    ASSERT_TRUE(landed(ball)) << "ball at " << pos(ball).y;
    // A ground whose mask accepts no group collides with nothing.
    reg.replace<collision_filter>(ground, collision_filter{1, 0});
    // In the asynchronous mode the worker applies it: its results are back after this.
    wait_for_simulation(reg);
    EXPECT_EQ(manifold_count(ball), 0u);
    run_for(1);
    EXPECT_NEAR(pos(ball).y, r - fall(reg, 1), scalar(1e-3))
        << "ball at " << pos(ball).y << ", expected free fall";
}
