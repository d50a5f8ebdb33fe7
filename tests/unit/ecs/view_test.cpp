#include "ecs_test_support.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/ecs/view.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace edyn;
using namespace ecs_test;

namespace {

// Ten entities: every one has a position (x = index); even ones a velocity; multiples of three
// a tag.
struct view_fixture : ::testing::Test {
    registry reg;
    std::vector<entity> entities;

    void SetUp() override {
        for (int i = 0; i < 10; ++i) {
            const auto e = reg.create();
            entities.push_back(e);
            reg.emplace<position>(e, float(i));
            if (i % 2 == 0) {
                reg.emplace<velocity>(e, float(i * 10));
            }
            if (i % 3 == 0) {
                reg.emplace<tag>(e);
            }
        }
    }

    template<typename View>
    static std::vector<std::uint32_t> indices(const View &view) {
        std::vector<std::uint32_t> result;
        for (auto e : view) {
            result.push_back(to_index(e));
        }
        return result;
    }
};

using view_test = view_fixture;

} // namespace

TEST_F(view_test, single_component_view_iterates_newest_first) {
    auto view = reg.view<position>();
    EXPECT_EQ(view.size(), 10u);
    EXPECT_EQ(view.size_hint(), 10u);
    EXPECT_FALSE(view.empty());
    EXPECT_EQ(indices(view), (std::vector<std::uint32_t>{9, 8, 7, 6, 5, 4, 3, 2, 1, 0}));
    EXPECT_EQ(view.front(), entities[9]);
    EXPECT_EQ(view.back(), entities[0]);
}

TEST_F(view_test, multi_component_view_filters_by_every_pool) {
    auto view = reg.view<position, velocity>();
    EXPECT_EQ(indices(view), (std::vector<std::uint32_t>{8, 6, 4, 2, 0}));
    EXPECT_EQ(view.size_hint(), 5u) << "the smallest pool leads";
    auto three = reg.view<position, velocity, tag>();
    EXPECT_EQ(indices(three), (std::vector<std::uint32_t>{6, 0}));
    EXPECT_EQ(three.size_hint(), 4u);
    EXPECT_EQ(three.front(), entities[6]);
    EXPECT_EQ(three.back(), entities[0]);
}

TEST_F(view_test, exclusion_removes_entities_with_the_excluded_components) {
    auto view = reg.view<position>(exclude<velocity>);
    EXPECT_EQ(indices(view), (std::vector<std::uint32_t>{9, 7, 5, 3, 1}));
    auto two = reg.view<position>(exclude<velocity, tag>);
    EXPECT_EQ(indices(two), (std::vector<std::uint32_t>{7, 5, 1}));
    auto never = reg.view<position>(exclude<mass>);
    EXPECT_EQ(indices(never).size(), 10u) << "a pool nobody emplaced excludes nothing";
    EXPECT_TRUE(two.contains(entities[7]));
    EXPECT_FALSE(two.contains(entities[9]));
    EXPECT_FALSE(two.contains(entities[2]));
}

TEST_F(view_test, each_passes_entity_and_components_or_only_components) {
    float sum = 0;
    std::vector<entity> seen;
    reg.view<position, velocity>().each([&](entity e, position &p, velocity &v) {
        seen.push_back(e);
        sum += p.x + v.x;
    });
    EXPECT_EQ(seen, (std::vector<entity>{entities[8], entities[6], entities[4], entities[2], entities[0]}));
    EXPECT_EQ(sum, 20.f + 200.f);

    reg.view<position, velocity>().each([](position &p, velocity &v) { p.y = v.x; });
    EXPECT_EQ(reg.get<position>(entities[4]).y, 40.f);
    EXPECT_EQ(reg.get<position>(entities[3]).y, 0.f);

    int generic = 0;
    reg.view<velocity>().each([&](auto &v) { generic += int(v.x); });
    EXPECT_EQ(generic, 200);
}

TEST_F(view_test, each_leaves_empty_types_out_of_the_arguments) {
    std::vector<entity> seen;
    reg.view<tag, position>().each([&](entity e, position &p) {
        seen.push_back(e);
        EXPECT_EQ(p.x, float(to_index(e)));
    });
    EXPECT_EQ(seen.size(), 4u);
    int count = 0;
    reg.view<tag>().each([&](entity) { ++count; });
    reg.view<tag>().each([&]() { ++count; });
    EXPECT_EQ(count, 8);
}

TEST_F(view_test, each_works_whichever_pool_leads) {
    // Make velocity the largest pool so position leads, then compare with the other order.
    std::set<std::uint32_t> first, second;
    reg.view<tag, velocity>().each([&](entity e, velocity &) { first.insert(to_index(e)); });
    for (int i = 0; i < 20; ++i) {
        reg.emplace<velocity>(reg.create());
    }
    reg.view<velocity, tag>().each([&](entity e, velocity &) { second.insert(to_index(e)); });
    EXPECT_EQ(first, second);
    EXPECT_EQ(first, (std::set<std::uint32_t>{0, 6}));
}

TEST_F(view_test, get_on_the_view) {
    auto view = reg.view<position, velocity>();
    const auto e = entities[4];
    EXPECT_TRUE(view.contains(e));
    EXPECT_FALSE(view.contains(entities[3]));
    static_assert(std::is_same_v<decltype(view.get<position>(e)), position &>);
    static_assert(
        std::is_same_v<decltype(view.get<velocity, position>(e)), std::tuple<velocity &, position &>>);
    EXPECT_EQ(&view.get<position>(e), &reg.get<position>(e));
    auto [v, p] = view.get<velocity, position>(e);
    EXPECT_EQ(v.x, 40.f);
    EXPECT_EQ(p.x, 4.f);
    auto [all_p, all_v] = view.get(e);
    EXPECT_EQ(&all_p, &p);
    EXPECT_EQ(&all_v, &v);
    EXPECT_EQ(&view.storage<velocity>(), &reg.storage<velocity>());
}

TEST_F(view_test, range_for_over_each_gives_entity_and_components) {
    int count = 0;
    for (auto [e, p, v] : reg.view<position, velocity>().each()) {
        static_assert(std::is_same_v<decltype(p), position &>);
        EXPECT_EQ(p.x, float(to_index(e)));
        v.y = 1;
        ++count;
    }
    EXPECT_EQ(count, 5);
    EXPECT_EQ(reg.get<velocity>(entities[2]).y, 1.f);
    for (auto [e, p] : reg.view<tag, position>().each()) {
        EXPECT_EQ(to_index(e) % 3, 0u);
        EXPECT_EQ(p.x, float(to_index(e)));
    }
}

TEST_F(view_test, const_registry_gives_read_only_views) {
    const registry &cref = reg;
    auto view = cref.view<position, velocity>();
    static_assert(
        std::is_same_v<decltype(view), basic_view<get_t<const position, const velocity>, exclude_t<>>>);
    static_assert(std::is_same_v<decltype(view.get<position>(entities[0])), const position &>);
    float sum = 0;
    view.each([&](const position &p, const velocity &) { sum += p.x; });
    EXPECT_EQ(sum, 20.f);
    auto missing = cref.view<mass>();
    EXPECT_TRUE(missing.empty()) << "a view of a pool the const registry lacks is empty";
    EXPECT_TRUE(missing.front() == null);
    auto excluded = cref.view<position>(exclude<mass, velocity>);
    EXPECT_EQ(indices(excluded).size(), 5u);

    auto mixed = reg.view<const position, velocity>();
    static_assert(std::is_same_v<decltype(mixed.get<position>(entities[0])), const position &>);
    static_assert(std::is_same_v<decltype(mixed.get<velocity>(entities[0])), velocity &>);
}

TEST_F(view_test, view_type_can_be_spelled) {
    view<get_t<position>, exclude_t<tag>> spelled = reg.view<position>(exclude<tag>);
    EXPECT_EQ(indices(spelled).size(), 6u);
}

TEST_F(view_test, view_sees_changes_made_after_it_was_created) {
    auto view = reg.view<position, velocity>();
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.emplace<velocity>(e);
    EXPECT_TRUE(view.contains(e));
    EXPECT_EQ(view.front(), e);
}

TEST_F(view_test, destroying_the_visited_entity_during_each_is_safe) {
    std::vector<entity> seen;
    reg.view<position>().each([&](entity e, position &) {
        seen.push_back(e);
        reg.destroy(e);
    });
    EXPECT_EQ(seen.size(), 10u);
    EXPECT_EQ(reg.alive(), 0u);
    EXPECT_TRUE(reg.storage<position>().empty());
}

TEST_F(view_test, destroying_the_visited_entity_in_a_range_for_is_safe) {
    std::set<entity> seen;
    for (auto e : reg.view<position, velocity>()) {
        seen.insert(e);
        reg.destroy(e);
    }
    EXPECT_EQ(seen.size(), 5u);
    EXPECT_EQ(reg.alive(), 5u);
    EXPECT_TRUE(reg.storage<velocity>().empty());
    for (auto e : reg.view<position>()) {
        EXPECT_EQ(to_index(e) % 2, 1u);
    }
}

TEST_F(view_test, removing_the_current_component_during_each_is_safe) {
    int visited = 0;
    reg.view<position, velocity>().each([&](entity e, position &, velocity &) {
        ++visited;
        reg.remove<velocity>(e);
    });
    EXPECT_EQ(visited, 5);
    EXPECT_TRUE(reg.storage<velocity>().empty());

    visited = 0;
    reg.view<position>().each([&](entity e, position &p) {
        ++visited;
        EXPECT_EQ(p.x, float(to_index(e))) << "each visited entity still gets its own component";
        reg.remove<position>(e);
    });
    EXPECT_EQ(visited, 10);
    EXPECT_TRUE(reg.storage<position>().empty());
}

TEST_F(view_test, emplacing_into_other_pools_while_iterating_is_safe) {
    int visited = 0;
    reg.view<position>().each([&](entity e, position &p) {
        ++visited;
        // Grows the mass pool well past its first page and its entity array many times.
        reg.emplace<mass>(e, p.x);
        for (int i = 0; i < 200; ++i) {
            reg.emplace<mass>(reg.create(), 0.f);
        }
        p.z = 1;
    });
    EXPECT_EQ(visited, 10);
    for (auto e : entities) {
        EXPECT_EQ(reg.get<mass>(e).value, float(to_index(e)));
        EXPECT_EQ(reg.get<position>(e).z, 1.f);
    }
}

TEST_F(view_test, emplacing_into_the_leading_pool_while_iterating_is_safe) {
    int visited = 0;
    reg.view<velocity>().each([&](entity, velocity &v) {
        ++visited;
        for (int i = 0; i < 100; ++i) {
            reg.emplace<velocity>(reg.create());
        }
        v.z = 2; // still the visited entity's component: pages never move
    });
    EXPECT_EQ(visited, 5) << "entities added behind the iterator are not visited";
    for (int i = 0; i < 10; i += 2) {
        EXPECT_EQ(reg.get<velocity>(entities[i]).z, 2.f);
    }
}

TEST_F(view_test, clearing_the_leading_pool_while_iterating_stops_the_iteration) {
    int visited = 0;
    for (auto e : reg.view<velocity>()) {
        (void)e;
        ++visited;
        reg.clear<velocity>();
    }
    EXPECT_EQ(visited, 1);
}

TEST(view_empty_test, empty_registry_views) {
    registry reg;
    auto view = reg.view<position, velocity>(exclude<tag>);
    EXPECT_TRUE(view.empty());
    EXPECT_EQ(view.begin(), view.end());
    EXPECT_TRUE(view.front() == null);
    EXPECT_TRUE(view.back() == null);
    int calls = 0;
    view.each([&](position &, velocity &) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST_F(view_test, handle_is_the_leading_pool_whose_candidates_back_to_front_give_the_order) {
    auto view = reg.view<position, velocity>(exclude<tag>);
    auto &lead = view.handle();
    EXPECT_EQ(&lead, static_cast<const sparse_set *>(&reg.storage<velocity>())) << "the smallest pool leads";
    EXPECT_EQ(lead.size(), view.size_hint());
    // Checking each candidate apart (as threads may), then listing those that belong from the back
    // of the packed array to the front, gives the view's own order.
    std::vector<bool> belongs(lead.size());
    for (std::size_t i = 0; i < lead.size(); ++i)
        belongs[i] = view.contains(lead.data()[i]);
    std::vector<std::uint32_t> listed;
    for (auto i = lead.size(); i-- > 0;) {
        if (belongs[i]) listed.push_back(to_index(lead.data()[i]));
    }
    EXPECT_EQ(listed, (std::vector<std::uint32_t>{8, 4, 2}));
    EXPECT_EQ(listed, indices(view));
}
