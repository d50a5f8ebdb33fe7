// Action lists in every execution mode: each action is seen by exactly one step, however many
// steps an update runs, and the lists are emptied after it; in asynchronous mode the actions
// reach the worker, with the entities they hold translated.
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace edyn;

struct push {
    int id{0};
    entity target{null};
};

} // namespace

template<>
struct edyn::entity_members<push> {
    template<typename Fn>
    static void each(push &p, Fn &&fn) {
        fn(p.target);
    }
};

namespace {

// What the steps saw: per step, the ids of the actions in every list, and whether each action's
// target was a rigid body of the registry the step ran on. Written by the step's thread (the
// worker in asynchronous mode), read by the test after wait_for_simulation.
struct seen_log {
    std::mutex mutex;
    std::vector<std::vector<int>> steps;
    bool targets_valid{true};
};
seen_log seen;

void record_pushes(registry &registry) {
    auto ids = std::vector<int>{};
    auto valid = true;
    for (auto [e, list] : registry.view<action_list<push>>().each()) {
        for (auto &p : list.actions) {
            ids.push_back(p.id);
            valid = valid && registry.valid(p.target) && registry.all_of<rigidbody_tag>(p.target);
        }
    }
    std::lock_guard lock(seen.mutex);
    seen.steps.push_back(ids);
    seen.targets_valid = seen.targets_valid && valid;
}

std::vector<int> all_seen() {
    std::lock_guard lock(seen.mutex);
    auto all = std::vector<int>{};
    for (auto &ids : seen.steps)
        all.insert(all.end(), ids.begin(), ids.end());
    return all;
}

std::size_t steps_seen() {
    std::lock_guard lock(seen.mutex);
    return seen.steps.size();
}

entity make_body(registry &registry, const vector3 &at) {
    auto def = rigidbody_def{};
    def.shape = sphere_shape{0.5};
    def.position = at;
    def.gravity = vector3_zero;
    return make_rigidbody(registry, def);
}

struct action_modes : ::testing::TestWithParam<execution_mode> {
    registry reg;
    entity body{null}, other{null};
    double time{0};

    void SetUp() override {
        {
            std::lock_guard lock(seen.mutex);
            seen.steps.clear();
            seen.targets_valid = true;
        }
        attach(reg, init_config{GetParam()});
        register_external_components<>(reg, std::tuple<push>{});
        set_pre_step_callback(reg, &record_pushes);
        body = make_body(reg, {0, 0, 0});
        other = make_body(reg, {3, 0, 0});
        update(reg, time);
        wait_for_simulation(reg);
    }
    void TearDown() override { detach(reg); }

    // One update over `steps` fixed steps.
    void run(int steps) {
        time += steps * double(get_fixed_dt(reg));
        update(reg, time);
        wait_for_simulation(reg);
    }
    void add(int id) { reg.get_or_emplace<action_list<push>>(body).actions.push_back({id, other}); }
};

TEST_P(action_modes, each_action_is_seen_by_one_step_when_an_update_runs_several) {
    add(1);
    add(2);
    run(3);
    EXPECT_EQ(all_seen(), (std::vector<int>{1, 2}));
    {
        std::lock_guard lock(seen.mutex);
        ASSERT_EQ(seen.steps.size(), 3u);
        EXPECT_EQ(seen.steps[0], (std::vector<int>{1, 2})) << "the first step sees them";
        EXPECT_TRUE(seen.steps[1].empty());
        EXPECT_TRUE(seen.steps[2].empty());
        EXPECT_TRUE(seen.targets_valid) << "the action's entity names the stepping registry's body";
    }
    EXPECT_TRUE(reg.get<action_list<push>>(body).actions.empty());

    // Added between updates, over several updates: still once each, in order.
    for (int i = 3; i < 10; ++i) {
        add(i);
        run(i % 3 + 1);
    }
    run(2);
    auto expected = std::vector<int>{};
    for (int i = 1; i < 10; ++i)
        expected.push_back(i);
    EXPECT_EQ(all_seen(), expected);
}

TEST_P(action_modes, an_update_that_runs_no_step_keeps_the_actions_for_the_next_one) {
    add(7);
    // Less than a step: nothing runs, in the sequential modes the list waits.
    time += 0.25 * double(get_fixed_dt(reg));
    update(reg, time);
    wait_for_simulation(reg);
    auto before = steps_seen();
    run(1);
    EXPECT_GT(steps_seen(), before);
    EXPECT_EQ(all_seen(), (std::vector<int>{7}));
}

TEST_P(action_modes, step_simulation_consumes_them_too) {
    add(4);
    step_simulation(reg);
    step_simulation(reg);
    wait_for_simulation(reg);
    EXPECT_EQ(all_seen(), (std::vector<int>{4}));
    EXPECT_EQ(steps_seen(), 2u);
}

INSTANTIATE_TEST_SUITE_P(modes, action_modes,
                         ::testing::Values(execution_mode::sequential,
                                           execution_mode::sequential_multithreaded,
                                           execution_mode::asynchronous),
                         [](const auto &info) {
                             switch (info.param) {
                             case execution_mode::sequential:
                                 return std::string("sequential");
                             case execution_mode::sequential_multithreaded:
                                 return std::string("multithreaded");
                             default:
                                 return std::string("asynchronous");
                             }
                         });

TEST(action_lists, unregistered_types_are_left_alone_and_registration_needs_attach) {
    registry reg;
    EXPECT_THROW(register_external_components<>(reg, std::tuple<push>{}), std::invalid_argument);
    attach(reg, init_config{execution_mode::sequential});
    auto body = make_body(reg, {0, 0, 0});
    reg.emplace<action_list<push>>(body).actions.push_back({1, null});
    step_simulation(reg);
    // A type that was not registered is the program's own business: the step leaves it.
    EXPECT_EQ(reg.get<action_list<push>>(body).actions.size(), 1u);
    // Registering it twice is the same as once.
    register_external_components<>(reg, std::tuple<push>{});
    register_external_components<>(reg, std::tuple<push>{});
    step_simulation(reg);
    EXPECT_TRUE(reg.get<action_list<push>>(body).actions.empty());
    detach(reg);
}

} // namespace
