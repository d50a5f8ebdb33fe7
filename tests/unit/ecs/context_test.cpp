#include "ecs_test_support.hpp"
#include "edyn/ecs/context.hpp"
#include "edyn/ecs/registry.hpp"
#include <gtest/gtest.h>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace edyn;

namespace {

struct settings {
    int iterations{10};
    float gravity{-9.8f};
};

struct non_movable {
    int value;
    explicit non_movable(int value)
        : value(value) {}
    non_movable(const non_movable &) = delete;
    non_movable &operator=(const non_movable &) = delete;
};

std::vector<std::string> *destroyed = nullptr;

template<int N>
struct logs_destruction {
    ~logs_destruction() { destroyed->push_back(std::to_string(N)); }
};

} // namespace

TEST(context_test, emplace_get_find_contains_erase) {
    registry reg;
    auto &ctx = reg.ctx();
    EXPECT_TRUE(ctx.empty());
    EXPECT_FALSE(ctx.contains<settings>());
    EXPECT_EQ(ctx.find<settings>(), nullptr);
    auto &s = ctx.emplace<settings>(20, 1.5f);
    EXPECT_EQ(s.iterations, 20);
    EXPECT_EQ(s.gravity, 1.5f);
    EXPECT_TRUE(ctx.contains<settings>());
    EXPECT_EQ(&ctx.get<settings>(), &s);
    EXPECT_EQ(ctx.find<settings>(), &s);
    EXPECT_EQ(ctx.size(), 1u);
    EXPECT_TRUE(ctx.erase<settings>());
    EXPECT_FALSE(ctx.erase<settings>());
    EXPECT_FALSE(ctx.contains<settings>());
}

TEST(context_test, emplace_of_a_present_value_returns_it_unchanged) {
    context ctx;
    auto &first = ctx.emplace<settings>(1);
    auto &second = ctx.emplace<settings>(2);
    EXPECT_EQ(&first, &second);
    EXPECT_EQ(second.iterations, 1) << "arguments of the second emplace are ignored, as in EnTT";
}

TEST(context_test, emplace_or_replace_and_insert_or_assign) {
    context ctx;
    auto &value = ctx.emplace_or_replace<settings>(1);
    auto &again = ctx.emplace_or_replace<settings>(2);
    EXPECT_EQ(&value, &again);
    EXPECT_EQ(value.iterations, 2);
    ctx.insert_or_assign(settings{3, 0});
    EXPECT_EQ(ctx.get<settings>().iterations, 3);
    ctx.insert_or_assign(std::string("text"));
    EXPECT_EQ(ctx.get<std::string>(), "text");
}

TEST(context_test, const_access) {
    registry reg;
    reg.ctx().emplace<int>(5);
    const registry &cref = reg;
    static_assert(std::is_same_v<decltype(cref.ctx().get<int>()), const int &>);
    static_assert(std::is_same_v<decltype(cref.ctx().find<int>()), const int *>);
    EXPECT_EQ(cref.ctx().get<int>(), 5);
    EXPECT_TRUE(cref.ctx().contains<int>());
    EXPECT_EQ(cref.ctx().find<double>(), nullptr);
}

TEST(context_test, values_never_move) {
    context ctx;
    auto &kept = ctx.emplace<non_movable>(7);
    ctx.emplace<int>(1);
    ctx.emplace<double>(2.0);
    ctx.emplace<settings>();
    ctx.erase<int>();
    EXPECT_EQ(&ctx.get<non_movable>(), &kept);
    EXPECT_EQ(kept.value, 7);
    EXPECT_EQ(ctx.get<double>(), 2.0);
    EXPECT_EQ(ctx.get<settings>().iterations, 10);
}

TEST(context_test, values_are_destroyed_newest_first) {
    std::vector<std::string> log;
    destroyed = &log;
    {
        context ctx;
        ctx.emplace<logs_destruction<1>>();
        ctx.emplace<logs_destruction<2>>();
        ctx.emplace<logs_destruction<3>>();
        ctx.erase<logs_destruction<2>>();
        EXPECT_EQ(log, (std::vector<std::string>{"2"}));
    }
    EXPECT_EQ(log, (std::vector<std::string>{"2", "3", "1"}));
    destroyed = nullptr;
}

TEST(context_test, move_transfers_values) {
    context a;
    a.emplace<int>(3);
    context b{std::move(a)};
    EXPECT_EQ(b.get<int>(), 3);
    context c;
    c.emplace<double>(1.0);
    c = std::move(b);
    EXPECT_EQ(c.get<int>(), 3);
    EXPECT_FALSE(c.contains<double>());
}

#if defined(EDYN_ASSERTIONS) && EDYN_ASSERTIONS
TEST(context_death_test, get_of_a_missing_value_asserts) {
    context ctx;
    EXPECT_DEATH((void)ctx.get<settings>(), "no context variable");
}
#endif
