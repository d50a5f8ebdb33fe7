// The chain and bridge scenes: joints that hold under load.
#include "joints_support.hpp"
#include <edyn/dynamics/integration.hpp>
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using edyn::test::world_fixture;

using joint_scenes = world_fixture;

namespace {

// Largest separation of a hinge's pivots, in metres.
scalar hinge_error(const registry &reg, entity e) {
    auto &h = reg.get<hinge_constraint>(e);
    return distance(edyn::test::world_pivot(reg, h.body[0], h.pivot[0]),
                    edyn::test::world_pivot(reg, h.body[1], h.pivot[1]));
}

// Largest separation of a chain's ball joint pivots, in metres.
scalar chain_error(const registry &reg, const scenes::chain_scene &chain) {
    scalar worst = 0;
    for (auto e : chain.joints) {
        auto &c = reg.get<point_constraint>(e);
        worst = std::max(worst, distance(edyn::test::world_pivot(reg, c.body[0], c.pivot[0]),
                                         edyn::test::world_pivot(reg, c.body[1], c.pivot[1])));
    }
    return worst;
}

} // namespace

TEST_F(joint_scenes, bridge_holds_a_box_dropped_onto_it) {
    scenes::make_ground(reg);
    const unsigned planks = 16;
    const scalar plank_length = scalar(0.5), height = 3;
    auto bridge = scenes::make_bridge(reg, planks, plank_length, height);
    auto span = pos(bridge.posts[1]).x - pos(bridge.posts[0]).x - scalar(0.5);
    // A 20 kg box dropped from 1 m onto the middle of the deck of 32 kg of planks.
    auto box = make_rigidbody(
        reg, edyn::test::box_def({scalar(0.3), scalar(0.3), scalar(0.3)}, {span / 2, height + 1, 0}, 20));
    scalar worst = 0;
    for (int i = 0; i < 60 * 4; ++i) {
        edyn::test::step(reg);
        for (auto e : bridge.hinges)
            worst = std::max(worst, hinge_error(reg, e));
    }
    EXPECT_LT(worst, scalar(0.01)) << "largest hinge pivot error " << worst << " m";
    // The box stays on the deck, in the middle, well above the ground.
    EXPECT_GT(pos(box).y, height - 1) << "box at y = " << pos(box).y;
    EXPECT_NEAR(pos(box).x, span / 2, scalar(0.5));
    EXPECT_NEAR(pos(box).z, 0, scalar(0.2));
}

TEST_F(joint_scenes, bridge_with_a_box_on_it_comes_to_rest) {
    // The demo's bridge: a 20 kg box dropped onto the deck. The deck is nearly taut under it,
    // more than the solver holds exactly, and the position projection closes the hinges every
    // sub-step; the velocity it used to leave in the planks kept the box bouncing, still at
    // 0.1 m/s after 35 s. The hinges' damping alone takes the swaying out now: slowly (the box
    // sleeps after about 27 s), but for good.
    scenes::make_ground(reg);
    const scalar height = 3;
    auto bridge = scenes::make_bridge(reg, 16, scalar(0.5), height);
    auto span = pos(bridge.posts[1]).x - pos(bridge.posts[0]).x - scalar(0.5);
    auto box = make_rigidbody(
        reg, edyn::test::box_def({scalar(0.3), scalar(0.3), scalar(0.3)}, {span / 2, height + 1, 0}, 20));
    const int seconds = 35;
    int asleep_at = -1;
    scalar fastest_late = 0; // planks' top speed over the last 5 s
    for (int i = 1; i <= 60 * seconds; ++i) {
        edyn::test::step(reg);
        if (asleep_at < 0 && reg.all_of<sleeping_tag>(box)) asleep_at = i;
        if (i > 60 * (seconds - 5)) {
            for (auto plank : bridge.planks)
                fastest_late = std::max(fastest_late, length(vector3(reg.get<linvel>(plank))));
        }
    }
    EXPECT_GT(asleep_at, 0) << "the box on the bridge is still awake after " << seconds << " s";
    EXPECT_LT(fastest_late, scalar(0.05)) << "planks still move at " << fastest_late << " m/s";
    EXPECT_GT(pos(box).y, height - 1) << "box at y = " << pos(box).y;
}

namespace {

// The demo's bridge with its far post moved 30% of the span away: hinges that cannot all hold.
scenes::bridge_scene make_stretched_bridge(registry &reg) {
    scenes::make_ground(reg);
    auto bridge = scenes::make_bridge(reg, 16, scalar(0.5), 3);
    auto far = vector3(reg.get<position>(bridge.posts[1]));
    auto span = far.x - vector3(reg.get<position>(bridge.posts[0])).x;
    reg.replace<position>(bridge.posts[1], far + vector3{span * scalar(0.3), 0, 0});
    return bridge;
}

} // namespace

TEST_F(joint_scenes, a_bridge_whose_posts_are_pulled_apart_hangs_still) {
    // The hinges are too far apart to close, so the group is left to the soft correction, which
    // shares the stretch between them: the deck sways for a few seconds and sleeps (after 7 s).
    // Projected, the hinges were closed every sub-step and the planks were thrown about at the
    // speed limit, faster every sub-step.
    auto bridge = make_stretched_bridge(reg);
    scalar fastest_late = 0; // over the last second
    bool finite = true;
    for (int i = 1; i <= 60 * 10; ++i) {
        edyn::test::step(reg);
        for (auto plank : bridge.planks) {
            if (i > 60 * 9) fastest_late = std::max(fastest_late, length(vector3(reg.get<linvel>(plank))));
            finite = finite && isfinite(pos(plank));
        }
    }
    EXPECT_TRUE(finite);
    EXPECT_LT(fastest_late, scalar(0.01)) << "planks still move at " << fastest_late << " m/s";
    for (auto plank : bridge.planks)
        EXPECT_TRUE(reg.all_of<sleeping_tag>(plank));
    // The deck hangs straight between the posts, at their tops.
    for (auto plank : bridge.planks)
        EXPECT_NEAR(pos(plank).y, 3, scalar(0.2));
}

TEST_F(joint_scenes, a_bridge_projected_whatever_its_gaps_stays_within_the_speed_limits) {
    // With every joint projected, however wide open (max_projected_gap infinite), the same
    // bridge is thrown about: before the speed limits its planks reached 50,000 m/s, and random
    // scenes of the same kind overflowed to NaN. No plank leaves a step faster than the limits,
    // and all stay finite.
    reg.ctx().get<edyn::settings>().joint.max_projected_gap = std::numeric_limits<scalar>::infinity();
    auto bridge = make_stretched_bridge(reg);
    auto &settings = get_settings(reg);
    auto max_angular = max_angular_speed(settings.fixed_dt / scalar(settings.num_substeps));
    scalar fastest = 0, fastest_turn = 0;
    bool finite = true;
    for (int i = 0; i < 60 * 10; ++i) {
        edyn::test::step(reg);
        for (auto plank : bridge.planks) {
            fastest = std::max(fastest, length(vector3(reg.get<linvel>(plank))));
            fastest_turn = std::max(fastest_turn, length(vector3(reg.get<angvel>(plank))));
            finite = finite && isfinite(pos(plank)) && isfinite(reg.get<orientation>(plank));
        }
    }
    EXPECT_TRUE(finite);
    EXPECT_LE(fastest, get_max_linear_speed(reg) * scalar(1.0001))
        << "a plank moved at " << fastest << " m/s";
    EXPECT_LE(fastest_turn, max_angular * scalar(1.0001)) << "a plank turned at " << fastest_turn << " rad/s";
}

TEST_F(joint_scenes, chain_hangs_straight_down_with_its_links_joined) {
    const unsigned links = 12;
    const scalar link_length = scalar(0.5);
    const vector3 top{0, 10, 0};
    auto chain = scenes::make_chain(reg, links, link_length, top);
    scalar worst = 0;
    for (int i = 0; i < 60 * 10; ++i) {
        edyn::test::step(reg);
        worst = std::max(worst, chain_error(reg, chain));
    }
    EXPECT_LT(worst, scalar(0.01)) << "largest pivot separation " << worst << " m";
    // Released horizontally it swung down: its free end is below the anchor by most of its
    // 6 m length (it is still swinging, less than 45 degrees out).
    auto end = edyn::test::world_pivot(reg, chain.links.back(), {link_length / 2, 0, 0});
    EXPECT_LT(end.y, top.y - link_length * links * scalar(0.7)) << "free end at y = " << end.y;
}

TEST_F(joint_scenes, a_hundred_link_chain_swinging_down_keeps_its_joints_closed) {
    // edyn-bench's chain: 100 links of 0.5 m released horizontally. Its free end whips round
    // at the bottom of the swing, and links fold into one another. Projected one joint at a
    // time, its joints opened by up to 10.4 mm; as one path solved at once, by micrometres.
    auto chain = scenes::make_chain(reg, 100, scalar(0.5), vector3_zero);
    scalar worst = 0;
    for (int i = 0; i < 60 * 10; ++i) {
        edyn::test::step(reg);
        worst = std::max(worst, chain_error(reg, chain));
    }
    EXPECT_LT(worst, scalar(0.001)) << "largest pivot separation " << worst << " m";
}
