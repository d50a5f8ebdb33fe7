#include "edyn/collision/should_collide.hpp"
#include "edyn/ecs/registry.hpp"
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace {

using edyn::collision_exclusion;
using edyn::collision_filter;
using edyn::entity;

struct no_collision_tag {};

bool tag_aware_should_collide(const edyn::registry &registry, entity a, entity b) {
    if (registry.all_of<no_collision_tag>(a) || registry.all_of<no_collision_tag>(b)) return false;
    return edyn::should_collide_default(registry, a, b);
}

bool never_collide(const edyn::registry &, entity, entity) { return false; }

TEST(collision_filter_test, defaults_collide_with_everything) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    EXPECT_TRUE(edyn::should_collide_default(registry, a, b));

    collision_filter filter;
    EXPECT_EQ(filter.group, ~0ull);
    EXPECT_EQ(filter.mask, ~0ull);
    registry.emplace<collision_filter>(a, filter);
    EXPECT_TRUE(edyn::should_collide_default(registry, a, b));
}

TEST(collision_filter_test, manual_groups_and_masks) {
    edyn::registry registry;
    auto first = registry.create();
    auto second = registry.create();
    auto other = registry.create();
    // As the manual's example: the first body is in group 1 and ignores group 2, the second is
    // in group 2 and ignores group 1.
    registry.emplace<collision_filter>(first, collision_filter{1ull, ~(1ull << 1)});
    registry.emplace<collision_filter>(second, collision_filter{1ull << 1, ~1ull});

    EXPECT_FALSE(edyn::should_collide_default(registry, first, second));
    EXPECT_FALSE(edyn::should_collide_default(registry, second, first));
    EXPECT_TRUE(edyn::should_collide_default(registry, first, other));
    EXPECT_TRUE(edyn::should_collide_default(registry, second, other));
}

TEST(collision_filter_test, one_sided_mask_is_enough_to_reject) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    // "if one rigid body has a collision group of 1 and another has a collision mask of ~1
    // then they will not collide": b's group is everything, so only a's side matches.
    registry.emplace<collision_filter>(a, collision_filter{1ull, ~0ull});
    registry.emplace<collision_filter>(b, collision_filter{~0ull, ~1ull});
    EXPECT_FALSE(edyn::should_collide_default(registry, a, b));
    EXPECT_FALSE(edyn::should_collide_default(registry, b, a));

    // Sharing a second group bit with b's mask makes them collide again.
    registry.replace<collision_filter>(a, collision_filter{1ull | (1ull << 5), ~0ull});
    EXPECT_TRUE(edyn::should_collide_default(registry, a, b));

    // A mask of zero collides with nothing.
    registry.replace<collision_filter>(a, collision_filter{~0ull, 0ull});
    EXPECT_FALSE(edyn::should_collide_default(registry, a, b));
}

TEST(collision_filter_test, exclusion_is_mutual_and_idempotent) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    auto c = registry.create();

    edyn::exclude_collision(registry, a, b);
    EXPECT_FALSE(edyn::should_collide_default(registry, a, b));
    EXPECT_FALSE(edyn::should_collide_default(registry, b, a));
    EXPECT_TRUE(edyn::should_collide_default(registry, a, c));
    EXPECT_TRUE(edyn::should_collide_default(registry, b, c));

    edyn::exclude_collision(registry, b, a);
    edyn::exclude_collision(registry, a, b);
    EXPECT_EQ(registry.get<collision_exclusion>(a).num_entities, 1u);
    EXPECT_EQ(registry.get<collision_exclusion>(b).num_entities, 1u);
    EXPECT_EQ(registry.get<collision_exclusion>(a).entities[0], b);

    edyn::exclude_collision(registry, a, c);
    EXPECT_EQ(registry.get<collision_exclusion>(a).num_entities, 2u);
    EXPECT_FALSE(edyn::should_collide_default(registry, c, a));
    EXPECT_TRUE(edyn::should_collide_default(registry, b, c));
}

TEST(collision_filter_test, exclusion_on_one_side_is_enough) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    collision_exclusion excl;
    excl.entities[excl.num_entities++] = b;
    registry.emplace<collision_exclusion>(a, excl);
    EXPECT_FALSE(edyn::should_collide_default(registry, a, b));
    EXPECT_FALSE(edyn::should_collide_default(registry, b, a));
}

TEST(collision_filter_test, exclude_collision_validates) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    auto dead = registry.create();
    registry.destroy(dead);

    EXPECT_THROW(edyn::exclude_collision(registry, a, dead), std::invalid_argument);
    EXPECT_THROW(edyn::exclude_collision(registry, edyn::null, a), std::invalid_argument);
    EXPECT_THROW(edyn::exclude_collision(registry, a, a), std::invalid_argument);
    EXPECT_FALSE(registry.all_of<collision_exclusion>(a));
    EXPECT_TRUE(edyn::should_collide_default(registry, a, b));
}

TEST(collision_filter_test, exclusion_list_is_bounded) {
    edyn::registry registry;
    auto a = registry.create();
    std::vector<entity> others;
    for (std::size_t i = 0; i < collision_exclusion::max_exclusions; ++i) {
        others.push_back(registry.create());
        edyn::exclude_collision(registry, a, others.back());
    }
    EXPECT_EQ(registry.get<collision_exclusion>(a).num_entities, collision_exclusion::max_exclusions);

    // Re-adding an existing pair to a full list is fine.
    EXPECT_NO_THROW(edyn::exclude_collision(registry, others[3], a));

    auto one_more = registry.create();
    try {
        edyn::exclude_collision(registry, one_more, a);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &error) {
        EXPECT_NE(std::string(error.what()).find("exclude_collision"), std::string::npos) << error.what();
    }
    // Nothing was half done: the new entity got no exclusion either.
    EXPECT_FALSE(registry.all_of<collision_exclusion>(one_more));
    EXPECT_TRUE(edyn::should_collide_default(registry, a, one_more));
}

// A gun that excludes each bullet it fires, the bullets destroyed as they land: the list drops
// the destroyed ones, so the gun can go on firing past max_exclusions bullets.
TEST(collision_filter_test, destroyed_entities_leave_the_exclusion_list_when_it_next_changes) {
    edyn::registry registry;
    auto gun = registry.create();
    auto holster = registry.create();
    edyn::exclude_collision(registry, gun, holster);
    std::vector<entity> flying;
    for (std::size_t shot = 0; shot < 5 * collision_exclusion::max_exclusions; ++shot) {
        auto bullet = registry.create();
        ASSERT_NO_THROW(edyn::exclude_collision(registry, gun, bullet)) << "shot " << shot;
        flying.push_back(bullet);
        // Three bullets in flight at most.
        if (flying.size() > 3) {
            registry.destroy(flying.front());
            flying.erase(flying.begin());
        }
    }
    auto &list = registry.get<collision_exclusion>(gun);
    EXPECT_LE(list.num_entities, std::size_t{5}) << "the holster, three bullets and the last one destroyed";
    EXPECT_TRUE(list.contains(holster));
    for (auto bullet : flying) {
        EXPECT_TRUE(list.contains(bullet));
        EXPECT_FALSE(edyn::should_collide_default(registry, gun, bullet));
    }
    std::size_t destroyed = 0;
    for (std::size_t i = 0; i < list.num_entities; ++i)
        destroyed += registry.valid(list.entities[i]) ? 0 : 1;
    EXPECT_EQ(destroyed, 1u) << "only the bullet destroyed after the last change";
}

TEST(collision_filter_test, exclusion_fires_component_signals) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    auto c = registry.create();
    struct listener {
        int constructed{0};
        int updated{0};
        void on_construct(edyn::registry &, entity) { ++constructed; }
        void on_update(edyn::registry &, entity) { ++updated; }
    } counts;
    registry.on_construct<collision_exclusion>().connect<&listener::on_construct>(counts);
    registry.on_update<collision_exclusion>().connect<&listener::on_update>(counts);

    edyn::exclude_collision(registry, a, b);
    EXPECT_EQ(counts.constructed, 2);
    edyn::exclude_collision(registry, a, c);
    EXPECT_EQ(counts.constructed, 3);
    EXPECT_EQ(counts.updated, 1);
    // Nothing changes, nothing fires.
    edyn::exclude_collision(registry, c, a);
    EXPECT_EQ(counts.constructed, 3);
    EXPECT_EQ(counts.updated, 1);
}

TEST(collision_filter_test, custom_should_collide) {
    edyn::registry registry;
    auto a = registry.create();
    auto b = registry.create();
    EXPECT_EQ(edyn::get_should_collide(registry), &edyn::should_collide_default);

    edyn::set_should_collide(registry, &tag_aware_should_collide);
    EXPECT_EQ(edyn::get_should_collide(registry), &tag_aware_should_collide);
    auto fn = edyn::get_should_collide(registry);
    EXPECT_TRUE(fn(registry, a, b));
    registry.emplace<no_collision_tag>(b);
    EXPECT_FALSE(fn(registry, a, b));
    registry.remove<no_collision_tag>(b);
    // The custom function builds on the default one.
    edyn::exclude_collision(registry, a, b);
    EXPECT_FALSE(fn(registry, a, b));

    edyn::set_should_collide(registry, &never_collide);
    EXPECT_EQ(edyn::get_should_collide(registry), &never_collide);
    EXPECT_THROW(edyn::set_should_collide(registry, nullptr), std::invalid_argument);
    EXPECT_EQ(edyn::get_should_collide(registry), &never_collide);

    // Another registry keeps the default.
    edyn::registry other;
    EXPECT_EQ(edyn::get_should_collide(other), &edyn::should_collide_default);
}

} // namespace
