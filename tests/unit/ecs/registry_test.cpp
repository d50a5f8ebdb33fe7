#include "ecs_test_support.hpp"
#include "edyn/ecs/registry.hpp"
#include <algorithm>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace edyn;
using namespace ecs_test;

namespace {

struct constructed {
    int a;
    std::string b;
    constructed(int a, std::string b)
        : a(a)
        , b(std::move(b)) {}
};

struct fails_on_zero {
    int value;
    fails_on_zero(int value)
        : value(value) {
        if (value == 0) {
            throw std::runtime_error("zero");
        }
    }
};

void count_call(int &count, registry &, entity) { ++count; }

std::string message_of(const std::function<void()> &action) {
    try {
        action();
    } catch (const std::invalid_argument &error) {
        return error.what();
    }
    return "(no std::invalid_argument thrown)";
}

} // namespace

static_assert(!std::is_copy_constructible_v<registry>);
static_assert(!std::is_copy_assignable_v<registry>);
static_assert(std::is_nothrow_move_constructible_v<registry>);
static_assert(std::is_nothrow_move_assignable_v<registry>);

TEST(registry_test, create_gives_sequential_valid_entities) {
    registry reg;
    EXPECT_EQ(reg.alive(), 0u);
    const auto a = reg.create();
    const auto b = reg.create();
    EXPECT_EQ(to_index(a), 0u);
    EXPECT_EQ(to_index(b), 1u);
    EXPECT_EQ(to_version(a), 0u);
    EXPECT_TRUE(reg.valid(a));
    EXPECT_TRUE(reg.valid(b));
    EXPECT_FALSE(reg.valid(null));
    EXPECT_FALSE(reg.valid(make_entity(2, 0)));
    EXPECT_EQ(reg.alive(), 2u);
}

TEST(registry_test, destroyed_index_is_recycled_with_a_new_version) {
    registry reg;
    const auto a = reg.create();
    const auto b = reg.create();
    reg.destroy(a);
    EXPECT_FALSE(reg.valid(a));
    EXPECT_TRUE(reg.valid(b));
    EXPECT_EQ(reg.alive(), 1u);
    EXPECT_EQ(reg.current(a), 1u);
    const auto c = reg.create();
    EXPECT_EQ(to_index(c), to_index(a));
    EXPECT_EQ(to_version(c), 1u);
    EXPECT_NE(c, a);
    EXPECT_TRUE(reg.valid(c));
    EXPECT_FALSE(reg.valid(a)) << "the stale handle stays invalid after its index is reused";
    EXPECT_THROW(reg.destroy(a), std::invalid_argument);
    EXPECT_TRUE(reg.valid(c)) << "destroying a stale handle must not touch the new entity";
}

TEST(registry_test, most_recently_freed_index_is_reused_first) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 5; ++i) {
        entities.push_back(reg.create());
    }
    reg.destroy(entities[1]);
    reg.destroy(entities[3]);
    EXPECT_EQ(to_index(reg.create()), 3u);
    EXPECT_EQ(to_index(reg.create()), 1u);
    EXPECT_EQ(to_index(reg.create()), 5u);
}

TEST(registry_test, versions_keep_counting_across_many_reuses) {
    registry reg;
    auto e = reg.create();
    for (std::uint32_t i = 1; i < 100; ++i) {
        reg.destroy(e);
        e = reg.create();
        ASSERT_EQ(to_index(e), 0u);
        ASSERT_EQ(to_version(e), i);
    }
}

TEST(registry_test, create_with_hint_past_the_end_frees_the_gap) {
    registry reg;
    const auto hint = make_entity(10, 4);
    EXPECT_EQ(reg.create(hint), hint);
    EXPECT_TRUE(reg.valid(hint));
    EXPECT_EQ(reg.alive(), 1u);
    std::vector<std::uint32_t> indices;
    for (int i = 0; i < 10; ++i) {
        indices.push_back(to_index(reg.create()));
    }
    std::sort(indices.begin(), indices.end());
    const std::vector<std::uint32_t> expected{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    EXPECT_EQ(indices, expected) << "the skipped indices were handed out";
    EXPECT_EQ(to_index(reg.create()), 11u);
}

TEST(registry_test, create_with_hint_takes_a_free_index_out_of_the_free_list) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 6; ++i) {
        entities.push_back(reg.create());
    }
    for (int i : {1, 3, 5}) {
        reg.destroy(entities[i]);
    }
    const auto hint = make_entity(3, 9);
    EXPECT_EQ(reg.create(hint), hint);
    EXPECT_EQ(reg.alive(), 4u);
    const auto x = reg.create();
    const auto y = reg.create();
    EXPECT_EQ(to_index(x), 5u);
    EXPECT_EQ(to_index(y), 1u);
    EXPECT_EQ(to_index(reg.create()), 6u);
}

TEST(registry_test, create_with_hint_of_a_used_index_creates_another) {
    registry reg;
    const auto a = reg.create();
    const auto e = reg.create(make_entity(to_index(a), 3));
    EXPECT_NE(to_index(e), to_index(a));
    EXPECT_TRUE(reg.valid(a));
    EXPECT_TRUE(reg.valid(e));
    const auto n = reg.create(null);
    EXPECT_TRUE(reg.valid(n));
    EXPECT_EQ(reg.alive(), 3u);
}

TEST(registry_test, emplace_returns_the_component_and_supports_aggregates) {
    registry reg;
    const auto e = reg.create();
    auto &p = reg.emplace<position>(e, 1.f, 2.f, 3.f);
    EXPECT_EQ(p, (position{1, 2, 3}));
    EXPECT_EQ(&p, &reg.get<position>(e));
    auto &c = reg.emplace<constructed>(e, 4, "four");
    EXPECT_EQ(c.a, 4);
    EXPECT_EQ(c.b, "four");
    auto &v = reg.emplace<velocity>(e);
    EXPECT_EQ(v, (velocity{0, 0, 0})) << "value-initialized";
    reg.emplace<tag>(e);
    EXPECT_TRUE((reg.all_of<position, constructed, velocity, tag>(e)));
}

TEST(registry_test, emplace_of_a_present_component_throws_naming_function_and_type) {
    registry reg;
    reg.create();
    const auto e = reg.create();
    reg.emplace<position>(e, 1.f, 2.f, 3.f);
    const auto message = message_of([&] { reg.emplace<position>(e, 9.f, 9.f, 9.f); });
    EXPECT_EQ(message, "registry::emplace: entity 1 already has component ecs_test::position");
    EXPECT_EQ(reg.get<position>(e), (position{1, 2, 3})) << "the first component is untouched";
    EXPECT_EQ(reg.storage<position>().size(), 1u);

    reg.emplace<tag>(e);
    const auto tag_message = message_of([&] { reg.emplace<tag>(e); });
    EXPECT_NE(tag_message.find("ecs_test::tag"), std::string::npos) << tag_message;
}

TEST(registry_test, emplace_on_an_invalid_entity_throws_and_adds_nothing) {
    registry reg;
    const auto e = reg.create();
    reg.destroy(e);
    const auto message = message_of([&] { reg.emplace<position>(e); });
    EXPECT_NE(message.find("registry::emplace"), std::string::npos) << message;
    EXPECT_NE(message.find("entity 0 is not valid"), std::string::npos) << message;
    EXPECT_NE(message.find("ecs_test::position"), std::string::npos) << message;
    EXPECT_TRUE(reg.storage<position>().empty());
    EXPECT_THROW(reg.emplace<position>(null), std::invalid_argument);
    const auto recycled = reg.create();
    reg.destroy(recycled);
    const auto versioned = message_of([&] { reg.emplace<position>(recycled); });
    EXPECT_NE(versioned.find("entity 0 (version 1) is not valid"), std::string::npos) << versioned;
    EXPECT_THROW(reg.emplace_or_replace<position>(e), std::invalid_argument);
    EXPECT_THROW(reg.get_or_emplace<position>(e), std::invalid_argument);
    EXPECT_TRUE(reg.storage<position>().empty());
}

TEST(registry_test, throwing_component_constructor_leaves_nothing_behind) {
    registry reg;
    const auto e = reg.create();
    int constructs = 0;
    reg.on_construct<fails_on_zero>().connect<&count_call>(constructs);
    EXPECT_THROW(reg.emplace<fails_on_zero>(e, 0), std::runtime_error);
    EXPECT_FALSE(reg.all_of<fails_on_zero>(e));
    EXPECT_TRUE(reg.orphan(e));
    EXPECT_EQ(constructs, 0);
    reg.emplace<fails_on_zero>(e, 3);
    EXPECT_EQ(reg.get<fails_on_zero>(e).value, 3);
    EXPECT_EQ(constructs, 1);
}

TEST(registry_test, emplace_or_replace_and_get_or_emplace) {
    registry reg;
    const auto e = reg.create();
    EXPECT_EQ(reg.emplace_or_replace<position>(e, 1.f, 1.f, 1.f), (position{1, 1, 1}));
    EXPECT_EQ(reg.emplace_or_replace<position>(e, 2.f, 2.f, 2.f), (position{2, 2, 2}));
    EXPECT_EQ(reg.storage<position>().size(), 1u);
    EXPECT_EQ(reg.get_or_emplace<velocity>(e, 3.f), (velocity{3, 0, 0}));
    EXPECT_EQ(reg.get_or_emplace<velocity>(e, 4.f), (velocity{3, 0, 0})) << "existing one returned";
    reg.emplace_or_replace<tag>(e);
    reg.emplace_or_replace<tag>(e);
    EXPECT_TRUE(reg.all_of<tag>(e));
}

TEST(registry_test, replace_and_patch_change_the_component) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e, 1.f, 2.f, 3.f);
    auto &replaced = reg.replace<position>(e, 4.f, 5.f, 6.f);
    EXPECT_EQ(replaced, (position{4, 5, 6}));
    auto &patched = reg.patch<position>(
        e, [](position &p) { p.x = 10; }, [](position &p) { p.y += 1; });
    EXPECT_EQ(patched, (position{10, 6, 6}));
    EXPECT_EQ(&patched, &reg.get<position>(e));
    reg.get<position>(e).z = 7;
    EXPECT_EQ(reg.patch<position>(e), (position{10, 6, 7}));
    reg.emplace<name>(e, "a");
    reg.replace<name>(e, "b");
    EXPECT_EQ(reg.get<name>(e).value, "b");
}

TEST(registry_test, remove_counts_and_ignores_absent_components) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.emplace<tag>(e);
    EXPECT_EQ((reg.remove<position, velocity, tag>(e)), 2u);
    EXPECT_EQ((reg.remove<position, velocity, tag>(e)), 0u);
    EXPECT_EQ(reg.remove<mass>(e), 0u) << "a type that never had a pool";
    EXPECT_TRUE(reg.orphan(e));
    reg.emplace<position>(e);
    reg.destroy(e);
    EXPECT_EQ(reg.remove<position>(e), 0u) << "stale entity has nothing to remove";
}

TEST(registry_test, remove_over_a_range) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 10; ++i) {
        entities.push_back(reg.create());
        if (i % 2 == 0) {
            reg.emplace<position>(entities.back());
        }
    }
    EXPECT_EQ(reg.remove<position>(entities.begin(), entities.end()), 5u);
    EXPECT_TRUE(reg.storage<position>().empty());
}

TEST(registry_test, erase_removes_present_components) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.emplace<velocity>(e);
    reg.erase<position, velocity>(e);
    EXPECT_FALSE((reg.any_of<position, velocity>(e)));
}

TEST(registry_test, get_and_try_get_single_and_several) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e, 1.f);
    reg.emplace<velocity>(e, 2.f);
    static_assert(std::is_same_v<decltype(reg.get<position>(e)), position &>);
    static_assert(
        std::is_same_v<decltype(reg.get<position, velocity>(e)), std::tuple<position &, velocity &>>);
    auto [p, v] = reg.get<position, velocity>(e);
    p.x = 5;
    EXPECT_EQ(reg.get<position>(e).x, 5.f);
    EXPECT_EQ(v.x, 2.f);
    EXPECT_EQ(reg.get<const position>(e).x, 5.f);

    const registry &cref = reg;
    static_assert(std::is_same_v<decltype(cref.get<position>(e)), const position &>);
    static_assert(std::is_same_v<decltype(cref.get<position, velocity>(e)),
                                 std::tuple<const position &, const velocity &>>);
    EXPECT_EQ(&cref.get<position>(e), &p);

    EXPECT_EQ(reg.try_get<position>(e), &p);
    EXPECT_EQ(reg.try_get<mass>(e), nullptr);
    auto [tp, tm] = reg.try_get<position, mass>(e);
    EXPECT_EQ(tp, &p);
    EXPECT_EQ(tm, nullptr);
    static_assert(std::is_same_v<decltype(cref.try_get<position>(e)), const position *>);
    EXPECT_EQ(cref.try_get<velocity>(e), &v);
    EXPECT_EQ(cref.try_get<name>(e), nullptr) << "const look-up creates no pool";
    reg.destroy(e);
    EXPECT_EQ(reg.try_get<position>(e), nullptr) << "stale entity";
}

TEST(registry_test, all_of_and_any_of) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.emplace<tag>(e);
    EXPECT_TRUE((reg.all_of<position, tag>(e)));
    EXPECT_FALSE((reg.all_of<position, velocity>(e)));
    EXPECT_TRUE((reg.any_of<velocity, tag>(e)));
    EXPECT_FALSE((reg.any_of<velocity, mass>(e)));
    EXPECT_TRUE(reg.all_of<>(e));
    EXPECT_FALSE(reg.any_of<>(e));
    EXPECT_FALSE(reg.all_of<position>(null));
}

TEST(registry_test, clear_of_types_removes_them_from_every_entity) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 50; ++i) {
        const auto e = reg.create();
        entities.push_back(e);
        reg.emplace<position>(e);
        reg.emplace<velocity>(e);
        reg.emplace<tag>(e);
    }
    reg.clear<position, tag>();
    EXPECT_TRUE(reg.storage<position>().empty());
    EXPECT_TRUE(reg.storage<tag>().empty());
    EXPECT_EQ(reg.storage<velocity>().size(), 50u);
    EXPECT_EQ(reg.alive(), 50u);
    reg.clear<mass>();
    reg.clear();
    EXPECT_EQ(reg.alive(), 0u);
    EXPECT_TRUE(reg.storage<velocity>().empty());
    for (auto e : entities) {
        EXPECT_FALSE(reg.valid(e));
    }
}

TEST(registry_test, storage_exposes_the_pool) {
    registry reg;
    const auto a = reg.create();
    const auto b = reg.create();
    reg.emplace<position>(a);
    reg.emplace<position>(b);
    auto &pool = reg.storage<position>();
    EXPECT_EQ(pool.size(), 2u);
    EXPECT_FALSE(pool.empty());
    EXPECT_TRUE(pool.contains(a));
    const std::vector<entity> entities(pool.begin(), pool.end());
    EXPECT_EQ(entities, (std::vector<entity>{b, a}));

    const registry &cref = reg;
    EXPECT_EQ(&cref.storage<position>(), &pool);
    EXPECT_TRUE(cref.storage<mass>().empty()) << "const access to a missing pool gives an empty one";
}

TEST(registry_test, each_visits_alive_entities_and_allows_destroying_them) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 10; ++i) {
        entities.push_back(reg.create());
    }
    reg.destroy(entities[4]);
    std::vector<entity> seen;
    reg.each([&](entity e) { seen.push_back(e); });
    EXPECT_EQ(seen.size(), 9u);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), entities[4]), 0);
    reg.each([&](entity e) {
        if (to_index(e) % 2 == 0) {
            reg.destroy(e);
        }
    });
    EXPECT_EQ(reg.alive(), 5u);
}

TEST(registry_test, orphan_and_destroy_remove_every_component) {
    registry reg;
    const auto e = reg.create();
    EXPECT_TRUE(reg.orphan(e));
    reg.emplace<position>(e);
    reg.emplace<tag>(e);
    EXPECT_FALSE(reg.orphan(e));
    reg.destroy(e);
    EXPECT_TRUE(reg.storage<position>().empty());
    EXPECT_TRUE(reg.storage<tag>().empty());
    const auto again = reg.create();
    EXPECT_TRUE(reg.orphan(again)) << "the recycled index inherits no components";
}

TEST(registry_test, destroy_range_validates_first) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 4; ++i) {
        entities.push_back(reg.create());
    }
    reg.destroy(entities[3]);
    EXPECT_THROW(reg.destroy(entities.begin(), entities.end()), std::invalid_argument);
    EXPECT_EQ(reg.alive(), 3u) << "nothing destroyed when one entity is invalid";
    entities.pop_back();
    reg.destroy(entities.begin(), entities.end());
    EXPECT_EQ(reg.alive(), 0u);
}

TEST(registry_test, insert_emplaces_copies_or_throws_adding_nothing) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 4; ++i) {
        entities.push_back(reg.create());
    }
    reg.emplace<position>(entities[2]);
    EXPECT_THROW(reg.insert(entities.begin(), entities.end(), position{1, 1, 1}), std::invalid_argument);
    EXPECT_EQ(reg.storage<position>().size(), 1u);
    reg.remove<position>(entities[2]);
    reg.insert(entities.begin(), entities.end(), position{1, 1, 1});
    for (auto e : entities) {
        EXPECT_EQ(reg.get<position>(e), (position{1, 1, 1}));
    }
}

TEST(registry_test, destroy_range_with_a_repeated_entity_destroys_nothing) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 4; ++i) {
        entities.push_back(reg.create());
    }
    entities.push_back(entities[1]);
    try {
        reg.destroy(entities.begin(), entities.end());
        ADD_FAILURE() << "expected std::invalid_argument for a repeated entity";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        EXPECT_NE(what.find("registry::destroy"), std::string::npos) << what;
        EXPECT_NE(what.find("entity 1"), std::string::npos) << what;
    }
    EXPECT_EQ(reg.alive(), 4u) << "nothing destroyed when the range repeats an entity";
    for (int i = 0; i < 4; ++i) {
        EXPECT_TRUE(reg.valid(entities[std::size_t(i)])) << "entity " << i;
    }
}

TEST(registry_test, insert_range_with_a_repeated_entity_adds_nothing) {
    registry reg;
    std::vector<entity> entities;
    for (int i = 0; i < 3; ++i) {
        entities.push_back(reg.create());
    }
    entities.push_back(entities[2]);
    try {
        reg.insert(entities.begin(), entities.end(), position{1, 1, 1});
        ADD_FAILURE() << "expected std::invalid_argument for a repeated entity";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        EXPECT_NE(what.find("registry::insert"), std::string::npos) << what;
        EXPECT_NE(what.find("entity 2"), std::string::npos) << what;
    }
    EXPECT_EQ(reg.storage<position>().size(), 0u) << "nothing inserted when the range repeats an entity";
}

TEST(registry_test, components_are_destroyed_with_the_registry) {
    const auto before = counted::live;
    {
        registry reg;
        for (int i = 0; i < 100; ++i) {
            reg.emplace<counted>(reg.create(), i);
        }
        EXPECT_EQ(counted::live - before, 100);
    }
    EXPECT_EQ(counted::live, before);
}

TEST(registry_test, move_keeps_entities_components_and_context) {
    registry a;
    const auto e = a.create();
    a.emplace<position>(e, 1.f, 2.f, 3.f);
    a.ctx().emplace<int>(42);
    registry b{std::move(a)};
    EXPECT_TRUE(b.valid(e));
    EXPECT_EQ(b.get<position>(e), (position{1, 2, 3}));
    EXPECT_EQ(b.ctx().get<int>(), 42);
    registry c;
    c.emplace<velocity>(c.create());
    c = std::move(b);
    EXPECT_TRUE(c.valid(e));
    EXPECT_EQ(c.get<position>(e), (position{1, 2, 3}));
    EXPECT_TRUE(c.storage<velocity>().empty()) << "the old contents of the target are gone";
    EXPECT_EQ(c.view<position>().size(), 1u);
}

TEST(registry_test, empty_types_are_components_without_payload) {
    registry reg;
    const auto a = reg.create();
    const auto b = reg.create();
    reg.emplace<tag>(a);
    reg.emplace<tag>(b);
    reg.emplace<other_tag>(b);
    EXPECT_TRUE(reg.all_of<tag>(a));
    EXPECT_EQ(&reg.get<tag>(a), &reg.get<tag>(b));
    EXPECT_EQ(reg.remove<tag>(a), 1u);
    EXPECT_FALSE(reg.all_of<tag>(a));
    EXPECT_EQ(reg.try_get<tag>(a), nullptr);
    EXPECT_NE(reg.try_get<tag>(b), nullptr);
    reg.patch<tag>(b);
    reg.replace<tag>(b);
}

#if defined(EDYN_ASSERTIONS) && EDYN_ASSERTIONS
TEST(registry_death_test, get_of_a_missing_component_asserts) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<velocity>(reg.create());
    EXPECT_DEATH((void)reg.get<velocity>(e), "does not have the component");
    EXPECT_DEATH((void)reg.get<mass>(e), "does not have the component");
    EXPECT_DEATH((void)std::as_const(reg).get<velocity>(e), "does not have the component");
    EXPECT_DEATH(reg.replace<velocity>(e), "does not have the component");
    EXPECT_DEATH(reg.patch<velocity>(e), "does not have the component");
    EXPECT_DEATH(reg.erase<velocity>(e), "does not have the component");
}

TEST(registry_death_test, get_on_an_invalid_entity_asserts) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.destroy(e);
    EXPECT_DEATH((void)reg.get<position>(e), "invalid entity");
    EXPECT_DEATH((void)reg.get<position>(null), "invalid entity");
    EXPECT_DEATH(reg.patch<position>(e), "invalid entity");
    EXPECT_DEATH((void)reg.orphan(e), "invalid entity");
}

TEST(registry_death_test, view_get_of_an_entity_outside_the_view_asserts) {
    registry reg;
    const auto e = reg.create();
    reg.emplace<position>(e);
    auto view = reg.view<position, velocity>();
    EXPECT_DEATH((void)view.get<position>(e), "not in the view");
}
#endif
