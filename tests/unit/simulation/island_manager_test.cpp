#include <array>
#include <cmath>
#include <edyn/edyn.hpp>
#include <edyn/simulation/island_manager.hpp>
#include <gtest/gtest.h>

using namespace edyn;

namespace {

// The island manager on a bare registry: bodies are entities with dynamic_tag and velocities,
// links are plain entities, and each call of update_sleeping stands for a step of `dt`.
struct island_manager_test : ::testing::Test {
    registry reg;
    island_manager islands;
    settings config;
    scalar dt{scalar(1) / scalar(60)};

    entity body(scalar speed = 0) {
        auto e = reg.create();
        reg.emplace<dynamic_tag>(e);
        reg.emplace<linvel>(e, vector3{speed, 0, 0});
        reg.emplace<angvel>(e, vector3_zero);
        islands.add_node(reg, e);
        return e;
    }

    entity link(entity a, entity b) {
        auto edge = reg.create();
        islands.link_edge(reg, edge, a, b);
        return edge;
    }

    // a - b - c with the link b - c gone, a and b moving at `speed`, c never allowed to sleep
    // (rigidbody_def::sleeping_disabled). Returns a and c.
    std::array<entity, 2> chain_without_its_last_link(scalar speed) {
        auto a = body(speed), b = body(speed), c = body();
        reg.emplace<sleeping_disabled_tag>(c);
        link(a, b);
        islands.unlink_edge(reg, link(b, c));
        return {a, c};
    }

    entity island_of(entity e) const { return reg.get<island_resident>(e).island_entity; }
    bool asleep(entity e) const { return reg.all_of<sleeping_tag>(e); }
    // Steps a body's timer needs before it is ready to sleep.
    int steps_to_sleep() const { return static_cast<int>(std::ceil(config.time_to_sleep / dt)); }
};

// a - b - c, then the link b - c goes while c keeps moving: a and b must sleep, without waiting
// for c.
TEST_F(island_manager_test, a_lost_link_splits_the_island_once_one_body_is_ready_to_sleep) {
    auto a = body(), b = body(), c = body(1);
    link(a, b);
    auto bc = link(b, c);
    ASSERT_EQ(island_of(a), island_of(c));
    islands.unlink_edge(reg, bc);
    ASSERT_EQ(island_of(a), island_of(c)) << "splitting is deferred";

    int steps = 0;
    while (island_of(a) == island_of(c) && steps < 10 * steps_to_sleep()) {
        islands.update_sleeping(reg, config, dt);
        ++steps;
    }
    EXPECT_NE(island_of(a), island_of(c));
    EXPECT_EQ(island_of(a), island_of(b));
    // Split the step the bodies a and b became ready, not before.
    EXPECT_GE(steps, steps_to_sleep());
    EXPECT_LE(steps, steps_to_sleep() + 1);
    islands.update_sleeping(reg, config, dt);
    EXPECT_TRUE(asleep(a));
    EXPECT_TRUE(asleep(b));
    EXPECT_FALSE(asleep(c));
}

// An island that loses a link every step but stays whole (a heap that keeps moving) is split at
// most once per time_to_sleep, not every step: each split walks the whole island.
TEST_F(island_manager_test, an_island_found_whole_is_split_again_only_after_time_to_sleep) {
    auto a = body(), b = body(), c = body(1);
    link(a, b);
    link(b, c);
    const int total = 10 * steps_to_sleep();
    int splits = 0;
    for (int step = 0; step < total; ++step) {
        islands.unlink_edge(reg, link(a, c));
        islands.update_sleeping(reg, config, dt);
        ASSERT_EQ(island_of(a), island_of(c)) << "the island stays whole";
        // The call adds dt to the clock before it splits: zero means this call split.
        if (reg.get<island>(island_of(a)).since_split == 0) ++splits;
    }
    EXPECT_FALSE(asleep(a)) << "c keeps its island awake";
    // At most one split per time_to_sleep, but splits do happen while bodies are ready.
    EXPECT_GE(splits, 1);
    EXPECT_LE(splits, total / steps_to_sleep() + 1);
}

// A body that is never allowed to sleep is never ready to either: it cannot make its
// island split, but bodies whose link to it has gone still sleep once another body splits it.
TEST_F(island_manager_test, a_body_never_allowed_to_sleep_is_never_ready) {
    auto [resting, insomniac] = chain_without_its_last_link(0);
    auto [moving, insomniac_too] = chain_without_its_last_link(1);
    for (int step = 0; step < 3 * steps_to_sleep(); ++step)
        islands.update_sleeping(reg, config, dt);
    EXPECT_TRUE(asleep(resting));
    EXPECT_FALSE(asleep(insomniac));
    EXPECT_NE(island_of(resting), island_of(insomniac));
    // No body of the other island is ready: it is not split.
    EXPECT_EQ(island_of(moving), island_of(insomniac_too));
    EXPECT_FALSE(asleep(insomniac_too));
}

} // namespace
