#include "ecs_test_support.hpp"
#include "edyn/ecs/sparse_set.hpp"
#include "edyn/ecs/storage.hpp"
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

using namespace edyn;
using namespace ecs_test;

namespace {

std::vector<entity> iterate(const sparse_set &set) { return {set.begin(), set.end()}; }

struct throws_on_negative {
    int value;
    explicit throws_on_negative(int value)
        : value(value) {
        if (value < 0) {
            throw std::runtime_error("negative");
        }
    }
};

// Not assignable: removal must fall back to destroy and move-construct.
struct not_assignable {
    const int value;
};

} // namespace

TEST(storage_test, emplace_contains_get_and_index) {
    storage<position> pool;
    EXPECT_TRUE(pool.empty());
    const auto a = make_entity(3, 0);
    const auto b = make_entity(5000, 2);
    auto &pa = pool.emplace(a, 1.f, 2.f, 3.f);
    pool.emplace(b, position{4, 5, 6});
    EXPECT_EQ(pool.size(), 2u);
    EXPECT_TRUE(pool.contains(a));
    EXPECT_TRUE(pool.contains(b));
    EXPECT_FALSE(pool.contains(make_entity(4, 0)));
    EXPECT_FALSE(pool.contains(make_entity(1 << 19, 0))) << "index on a page never allocated";
    EXPECT_FALSE(pool.contains(null));
    EXPECT_EQ(&pa, &pool.get(a));
    EXPECT_EQ(pool.get(a), (position{1, 2, 3}));
    EXPECT_EQ(pool.get(b), (position{4, 5, 6}));
    EXPECT_EQ(pool.index(a), 0u);
    EXPECT_EQ(pool.index(b), 1u);
    EXPECT_EQ(pool.data()[1], b);
    EXPECT_EQ(pool.at(0), a);
    EXPECT_TRUE(pool.at(2) == null);
    EXPECT_EQ(pool.try_get(a), &pa);
    EXPECT_EQ(pool.try_get(make_entity(4, 0)), nullptr);
}

TEST(storage_test, stale_version_is_not_contained) {
    storage<position> pool;
    const auto e = make_entity(7, 1);
    pool.emplace(e);
    EXPECT_TRUE(pool.contains(e));
    EXPECT_FALSE(pool.contains(make_entity(7, 0)));
    EXPECT_FALSE(pool.contains(make_entity(7, 2)));
    EXPECT_FALSE(pool.remove(make_entity(7, 2)));
    EXPECT_EQ(pool.size(), 1u);
}

TEST(storage_test, removal_moves_the_last_component_into_the_hole) {
    storage<position> pool;
    std::vector<entity> entities;
    for (std::uint32_t i = 0; i < 5; ++i) {
        entities.push_back(make_entity(i, 0));
        pool.emplace(entities.back(), float(i), 0.f, 0.f);
    }
    EXPECT_TRUE(pool.remove(entities[1]));
    EXPECT_FALSE(pool.remove(entities[1])) << "second removal is a no-op";
    EXPECT_EQ(pool.size(), 4u);
    EXPECT_EQ(pool.data()[1], entities[4]) << "last entity moved into position 1";
    EXPECT_EQ(pool.value_at(1).x, 4.f);
    EXPECT_EQ(pool.index(entities[4]), 1u);
    EXPECT_EQ(pool.get(entities[4]).x, 4.f);
    pool.erase(entities[4]);
    EXPECT_FALSE(pool.contains(entities[4]));
    EXPECT_EQ(pool.get(entities[3]).x, 3.f);
    EXPECT_EQ(pool.get(entities[0]).x, 0.f);
    EXPECT_EQ(pool.get(entities[2]).x, 2.f);
}

TEST(storage_test, iteration_is_newest_first) {
    storage<position> pool;
    const std::vector<entity> entities{make_entity(9, 0), make_entity(2, 0), make_entity(40, 3)};
    for (auto e : entities) {
        pool.emplace(e);
    }
    const std::vector<entity> expected{entities[2], entities[1], entities[0]};
    EXPECT_EQ(iterate(pool), expected);
}

TEST(storage_test, removing_the_visited_entity_while_iterating_visits_all_others) {
    storage<position> pool;
    for (std::uint32_t i = 0; i < 100; ++i) {
        pool.emplace(make_entity(i, 0), float(i));
    }
    int visited = 0;
    for (auto e : pool) {
        ++visited;
        if (to_index(e) % 3 == 0) {
            pool.remove(e);
        }
    }
    EXPECT_EQ(visited, 100);
    EXPECT_EQ(pool.size(), 66u);
    for (auto e : pool) {
        EXPECT_NE(to_index(e) % 3, 0u) << "entity " << to_index(e);
        EXPECT_EQ(pool.get(e).x, float(to_index(e)));
    }
}

TEST(storage_test, references_survive_insertions) {
    storage<position> pool;
    const auto first = make_entity(0, 0);
    auto *address = &pool.emplace(first, 1.f, 2.f, 3.f);
    for (std::uint32_t i = 1; i < 20000; ++i) {
        pool.emplace(make_entity(i, 0));
    }
    EXPECT_EQ(address, &pool.get(first));
    EXPECT_EQ(*address, (position{1, 2, 3}));
}

TEST(storage_test, empty_types_store_no_payload) {
    storage<tag> pool;
    const auto a = make_entity(1, 0);
    const auto b = make_entity(2, 0);
    auto &ta = pool.emplace(a);
    auto &tb = pool.emplace(b, tag{});
    EXPECT_EQ(&ta, &tb) << "every tag is the one shared instance";
    EXPECT_EQ(pool.size(), 2u);
    EXPECT_TRUE(pool.remove(a));
    EXPECT_FALSE(pool.contains(a));
    EXPECT_TRUE(pool.contains(b));
    EXPECT_EQ(pool.try_get(a), nullptr);
    EXPECT_NE(pool.try_get(b), nullptr);
}

TEST(storage_test, destroys_every_component) {
    const auto before = counted::live;
    {
        storage<counted> pool;
        for (std::uint32_t i = 0; i < 3000; ++i) {
            pool.emplace(make_entity(i, 0), int(i));
        }
        EXPECT_EQ(counted::live - before, 3000);
        pool.remove(make_entity(10, 0));
        pool.erase(make_entity(2999, 0));
        EXPECT_EQ(counted::live - before, 2998);
        pool.clear();
        EXPECT_EQ(counted::live - before, 0);
        EXPECT_TRUE(pool.empty());
        EXPECT_FALSE(pool.contains(make_entity(5, 0)));
        pool.emplace(make_entity(5, 0), 5);
        pool.emplace(make_entity(6, 0), 6);
        EXPECT_EQ(pool.get(make_entity(6, 0)).value, 6);
    }
    EXPECT_EQ(counted::live, before) << "the destructor destroys what is left";
}

TEST(storage_test, throwing_constructor_leaves_the_pool_unchanged) {
    storage<throws_on_negative> pool;
    pool.emplace(make_entity(1, 0), 1);
    EXPECT_THROW(pool.emplace(make_entity(2, 0), -1), std::runtime_error);
    EXPECT_EQ(pool.size(), 1u);
    EXPECT_FALSE(pool.contains(make_entity(2, 0)));
    pool.emplace(make_entity(2, 0), 2);
    EXPECT_EQ(pool.get(make_entity(2, 0)).value, 2);
    EXPECT_EQ(pool.get(make_entity(1, 0)).value, 1);
}

TEST(storage_test, non_assignable_components_can_be_removed) {
    storage<not_assignable> pool;
    for (std::uint32_t i = 0; i < 4; ++i) {
        pool.emplace(make_entity(i, 0), int(i * 10));
    }
    pool.remove(make_entity(0, 0));
    EXPECT_EQ(pool.get(make_entity(3, 0)).value, 30);
    EXPECT_EQ(pool.value_at(0).value, 30);
}

TEST(storage_test, non_trivial_payload_moves_on_removal) {
    storage<name> pool;
    pool.emplace(make_entity(0, 0), std::string(100, 'a'));
    pool.emplace(make_entity(1, 0), std::string(100, 'b'));
    pool.remove(make_entity(0, 0));
    EXPECT_EQ(pool.get(make_entity(1, 0)).value, std::string(100, 'b'));
}

TEST(storage_test, reserve_keeps_contents) {
    storage<position> pool;
    pool.emplace(make_entity(1, 0), 1.f);
    pool.reserve(5000);
    EXPECT_GE(pool.capacity(), 5000u);
    EXPECT_EQ(pool.get(make_entity(1, 0)).x, 1.f);
}

TEST(storage_test, iterator_is_random_access) {
    storage<position> pool;
    for (std::uint32_t i = 0; i < 10; ++i) {
        pool.emplace(make_entity(i, 0));
    }
    auto it = pool.begin();
    EXPECT_EQ(pool.end() - it, 10);
    EXPECT_EQ(*(it + 3), make_entity(6, 0));
    EXPECT_EQ(it[9], make_entity(0, 0));
    EXPECT_EQ((it + 3).index(), 6u);
    EXPECT_TRUE(it < pool.end());
    it += 10;
    EXPECT_TRUE(it == pool.end());
    --it;
    EXPECT_EQ(*it, make_entity(0, 0));
}
