// Rag doll construction: proportions, the parts and joints made, and rejected definitions.
#include <edyn/edyn.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace edyn;

namespace {

// The standing chain from the floor to the crown.
scalar standing_height(const ragdoll_def &d) {
    return d.foot_size.z + d.leg_lower_size.x + d.leg_upper_size.x + d.torso_lower_size.x +
           d.torso_upper_size.x + d.neck_size.x + d.head_size.x;
}

scalar total_mass(const ragdoll_def &d) {
    auto side = d.shoulder_mass + d.arm_upper_mass + d.arm_lower_mass + d.arm_twist_mass + d.hand_mass +
                d.leg_upper_mass + d.leg_lower_mass + d.foot_mass;
    return d.head_mass + d.neck_mass + d.torso_upper_mass + d.torso_lower_mass + 2 * side;
}

vector3 world_pivot(const registry &reg, entity body, const vector3 &pivot) {
    return get_rigidbody_origin(reg, body) + rotate(reg.get<orientation>(body), pivot);
}

struct attached_registry : ::testing::Test {
    registry reg;
    void SetUp() override { attach(reg); }
    void TearDown() override { detach(reg); }
};

using ragdoll = attached_registry;

} // namespace

TEST(ragdoll_def, segments_add_up_to_the_height_and_masses_to_the_weight) {
    for (scalar height : {scalar(1.5), scalar(1.8), scalar(2.1)}) {
        ragdoll_simple_def simple;
        simple.height = height;
        simple.weight = 70;
        auto def = make_ragdoll_def_from_simple(simple);
        EXPECT_NEAR(standing_height(def), height, height * scalar(0.01)) << "height " << height;
        EXPECT_NEAR(total_mass(def), 70, scalar(70e-4)) << "height " << height;
    }
}

TEST(ragdoll_def, proportions_follow_the_anthropometric_tables) {
    ragdoll_simple_def simple;
    simple.height = 2;
    simple.weight = 100;
    auto def = make_ragdoll_def_from_simple(simple);
    // Winter's segment lengths (fractions of height) and Dempster's mass fractions.
    EXPECT_NEAR(def.arm_upper_size.x, scalar(0.372), 1e-4);
    EXPECT_NEAR(def.leg_upper_size.x, scalar(0.490), 1e-4);
    EXPECT_NEAR(def.leg_lower_size.x, scalar(0.492), 1e-4);
    EXPECT_NEAR(def.foot_size.x, scalar(0.304), 1e-4);
    EXPECT_NEAR(def.leg_upper_mass, 10, 1e-4);
    EXPECT_NEAR(def.hand_mass, scalar(0.6), 1e-4);
    // The forearm of the tables is the lower arm and its twist together.
    EXPECT_NEAR(def.arm_lower_mass + def.arm_twist_mass, scalar(1.6), 1e-4);
    // The thigh is the heaviest limb part, the hand the lightest shaped one.
    EXPECT_GT(def.leg_upper_mass, def.leg_lower_mass);
    EXPECT_GT(def.arm_lower_mass, def.hand_mass);
}

TEST(ragdoll_def, placement_and_material_are_carried_over) {
    ragdoll_simple_def simple;
    simple.position = {1, 2, 3};
    simple.orientation = quaternion_axis_angle(vector3_y, 1);
    simple.friction = scalar(0.9);
    simple.restitution = scalar(0.3);
    simple.collision_group = 2;
    simple.collision_mask = 5;
    simple.sleeping_disabled = true;
    auto def = make_ragdoll_def_from_simple(simple);
    EXPECT_EQ(def.position, simple.position);
    EXPECT_EQ(def.orientation, simple.orientation);
    EXPECT_EQ(def.friction, simple.friction);
    EXPECT_EQ(def.restitution, simple.restitution);
    EXPECT_EQ(def.collision_group, 2u);
    EXPECT_EQ(def.collision_mask, 5u);
    EXPECT_TRUE(def.sleeping_disabled);
}

TEST_F(ragdoll, makes_every_body_and_joint) {
    auto e = make_ragdoll(reg, ragdoll_simple_def{});
    std::set<entity> bodies, constraints;
    for (auto body : e.bodies()) {
        ASSERT_TRUE(reg.valid(body));
        EXPECT_TRUE(reg.all_of<rigidbody_tag>(body));
        EXPECT_TRUE(reg.all_of<dynamic_tag>(body));
        bodies.insert(body);
    }
    EXPECT_EQ(bodies.size(), ragdoll_entities::num_bodies);
    for (auto c : e.constraints()) {
        ASSERT_TRUE(reg.valid(c));
        constraints.insert(c);
    }
    EXPECT_EQ(constraints.size(), ragdoll_entities::num_constraints);
    EXPECT_EQ(reg.storage<hinge_constraint>().size(), 6u);
    EXPECT_EQ(reg.storage<cvjoint_constraint>().size(), 13u);
    EXPECT_EQ(reg.storage<cone_constraint>().size(), 13u);
    EXPECT_EQ(reg.storage<rigidbody_tag>().size(), 20u);
}

TEST_F(ragdoll, shoulders_and_arm_twists_are_amorphous_and_joined_as_described) {
    auto e = make_ragdoll(reg, ragdoll_simple_def{});
    for (auto body : {e.shoulder_left, e.shoulder_right, e.arm_twist_left, e.arm_twist_right}) {
        EXPECT_FALSE(reg.all_of<shape_index>(body));
        EXPECT_GT(reg.get<mass>(body), 0);
    }
    for (auto body : {e.head, e.torso_upper, e.hand_left, e.foot_right, e.leg_upper_left})
        EXPECT_TRUE(reg.all_of<shape_index>(body));
    auto joined = [&](auto type, entity c, entity a, entity b) {
        auto &con = reg.get<decltype(type)>(c);
        return con.body[0] == a && con.body[1] == b;
    };
    EXPECT_TRUE(joined(cvjoint_constraint{}, e.clavicle_cvjoint_left, e.torso_upper, e.shoulder_left));
    EXPECT_TRUE(joined(cvjoint_constraint{}, e.shoulder_cvjoint_left, e.shoulder_left, e.arm_upper_left));
    EXPECT_TRUE(joined(hinge_constraint{}, e.arm_twist_hinge_right, e.arm_lower_right, e.arm_twist_right));
    EXPECT_TRUE(joined(cvjoint_constraint{}, e.wrist_cvjoint_right, e.arm_twist_right, e.hand_right));
    EXPECT_TRUE(joined(hinge_constraint{}, e.knee_hinge_left, e.leg_upper_left, e.leg_lower_left));
    EXPECT_TRUE(joined(cone_constraint{}, e.ankle_cone_right, e.leg_lower_right, e.foot_right));
}

TEST_F(ragdoll, every_part_gets_the_material_filter_and_sleep_setting) {
    ragdoll_simple_def simple;
    simple.friction = scalar(0.9);
    simple.restitution = scalar(0.25);
    simple.collision_group = 4;
    simple.collision_mask = ~std::uint64_t(4);
    simple.sleeping_disabled = true;
    auto e = make_ragdoll(reg, simple);
    for (auto body : e.bodies()) {
        EXPECT_TRUE(reg.all_of<sleeping_disabled_tag>(body));
        // Amorphous parts take no part in collisions.
        if (!reg.all_of<shape_index>(body)) continue;
        EXPECT_EQ(reg.get<material>(body).friction, simple.friction);
        EXPECT_EQ(reg.get<material>(body).restitution, simple.restitution);
        EXPECT_EQ(reg.get<collision_filter>(body).group, 4u);
        EXPECT_EQ(reg.get<collision_filter>(body).mask, ~std::uint64_t(4));
    }
}

TEST_F(ragdoll, stands_at_its_position_with_its_joints_closed) {
    ragdoll_simple_def simple;
    simple.height = scalar(1.7);
    simple.position = {2, 0, -1};
    simple.orientation = quaternion_axis_angle(normalize(vector3{1, 2, 3}), 1);
    auto e = make_ragdoll(reg, simple);
    // The crown is `height` above the position along the rag doll's up.
    auto up = rotate(simple.orientation, vector3_y);
    auto crown = world_pivot(
        reg, e.head,
        {0, reg.get<capsule_shape>(e.head).half_length + reg.get<capsule_shape>(e.head).radius, 0});
    EXPECT_NEAR(dot(crown - simple.position, up), simple.height, scalar(1e-4));
    // Every joint's pivots start together.
    auto check = [&](auto type, entity c) {
        auto &con = reg.get<decltype(type)>(c);
        auto gap = distance(world_pivot(reg, con.body[0], con.pivot[0]),
                            world_pivot(reg, con.body[1], con.pivot[1]));
        EXPECT_LT(gap, scalar(1e-5)) << "joint pivots " << gap << " m apart";
    };
    reg.view<hinge_constraint>().each([&](entity c, hinge_constraint &) { check(hinge_constraint{}, c); });
    reg.view<cvjoint_constraint>().each(
        [&](entity c, cvjoint_constraint &) { check(cvjoint_constraint{}, c); });
}

TEST_F(ragdoll, at_rest_without_gravity_nothing_pushes_its_parts) {
    // Parts that overlap, joints outside their limits or pivots apart would move the rag doll in
    // its first steps.
    set_gravity(reg, vector3_zero);
    auto e = make_ragdoll(reg, ragdoll_simple_def{});
    std::vector<vector3> start;
    for (auto body : e.bodies())
        start.push_back(reg.get<position>(body));
    for (int i = 0; i < 10; ++i)
        step_simulation(reg);
    scalar moved = 0, spinning = 0;
    for (std::size_t i = 0; i < e.bodies().size(); ++i) {
        moved = std::max(moved, distance(vector3(reg.get<position>(e.bodies()[i])), start[i]));
        spinning = std::max(spinning, length(reg.get<angvel>(e.bodies()[i])));
    }
    EXPECT_LT(moved, scalar(1e-4)) << "a part moved by " << moved << " m";
    EXPECT_LT(spinning, scalar(1e-2)) << "fastest spin " << spinning << " rad/s";
}

TEST_F(ragdoll, manual_example_runs_as_written) {
    auto &registry = reg;
    auto rag_def = edyn::ragdoll_simple_def{};
    rag_def.height = 1.8;
    rag_def.weight = 82;
    rag_def.position = {2, 3, -1};
    rag_def.orientation = edyn::quaternion_axis_angle({0, 0, 1}, edyn::to_radians(26));
    rag_def.friction = 0.6;
    rag_def.restitution = 0.2;
    auto entities = edyn::make_ragdoll(registry, rag_def);
    EXPECT_TRUE(registry.valid(entities.arm_twist_left));
    // The full definition is there to be edited before making the rag doll.
    auto full = edyn::make_ragdoll_def_from_simple(rag_def);
    full.arm_upper_size.x *= scalar(1.1);
    full.position.x += 3;
    auto longer = edyn::make_ragdoll(registry, full);
    EXPECT_NEAR(reg.get<capsule_shape>(longer.arm_upper_left).half_length,
                reg.get<capsule_shape>(entities.arm_upper_left).half_length + full.arm_upper_size.x / 22,
                scalar(1e-4));
    edyn::step_simulation(registry);
}

namespace {

// The registry's entities and rigid bodies, to tell whether a call left anything behind.
std::pair<std::size_t, std::size_t> census(const registry &reg) {
    return {reg.alive(), reg.storage<rigidbody_tag>().size()};
}

void expect_rejected(registry &reg, const ragdoll_simple_def &def, const std::string &field,
                     const std::string &value) {
    auto before = census(reg);
    try {
        make_ragdoll(reg, def);
        ADD_FAILURE() << "make_ragdoll accepted " << field << " = " << value;
    } catch (const std::invalid_argument &error) {
        EXPECT_THAT(error.what(), ::testing::HasSubstr("make_ragdoll"));
        EXPECT_THAT(error.what(), ::testing::HasSubstr(field));
        EXPECT_THAT(error.what(), ::testing::HasSubstr(value));
    }
    EXPECT_EQ(census(reg), before) << field;
    EXPECT_THROW(make_ragdoll_def_from_simple(def), std::invalid_argument) << field;
}

} // namespace

TEST_F(ragdoll, rejects_bad_simple_definitions_creating_nothing) {
    make_ragdoll(reg, ragdoll_simple_def{});
    const auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto with = [](auto change) {
        ragdoll_simple_def def;
        change(def);
        return def;
    };
    expect_rejected(reg, with([](auto &d) { d.height = -1; }), "height", "-1");
    expect_rejected(reg, with([](auto &d) { d.height = 0; }), "height", "0");
    expect_rejected(reg, with([&](auto &d) { d.height = nan; }), "height", "nan");
    expect_rejected(reg, with([](auto &d) { d.weight = 0; }), "weight", "0");
    expect_rejected(reg, with([](auto &d) { d.weight = -80; }), "weight", "-80");
    expect_rejected(reg, with([](auto &d) { d.orientation = {0, 0, 0, 2}; }), "orientation", "2");
    expect_rejected(reg, with([&](auto &d) { d.position.y = nan; }), "position", "nan");
    expect_rejected(reg, with([](auto &d) { d.friction = -1; }), "friction", "-1");
    expect_rejected(reg, with([](auto &d) { d.restitution = scalar(1.5); }), "restitution", "1.5");
}

TEST_F(ragdoll, rejects_bad_full_definitions_creating_nothing) {
    auto good = make_ragdoll_def_from_simple({});
    auto before = census(reg);
    auto bad_size = good;
    bad_size.hand_size.y = 0;
    EXPECT_THAT([&] { make_ragdoll(reg, bad_size); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("hand_size")));
    auto bad_mass = good;
    bad_mass.arm_twist_mass = -1;
    EXPECT_THAT([&] { make_ragdoll(reg, bad_mass); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("arm_twist_mass")));
    // Zero sizes and masses until filled.
    EXPECT_THROW(make_ragdoll(reg, ragdoll_def{}), std::invalid_argument);
    EXPECT_EQ(census(reg), before);
}
