#include <algorithm>
#include <atomic>
#include <cstring>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>
#include <vector>

// init_config::min_parallel_bodies: in sequential_multithreaded mode a step hands its phases to
// the scheduler only when it moves at least that many bodies; a smaller world is stepped on the
// calling thread. Either way the motion is the same to the last bit.

namespace edyn {
namespace {

// A program's scheduler that counts the tasks edyn hands it and runs each at once, range by
// range, on the calling thread (task_hooks allows enqueue to run the whole task).
struct counting_step_scheduler {
    std::atomic<int> tasks{0}, waits{0};

    static void *enqueue(task_function fn, void *context, std::size_t count, std::size_t grain, void *user) {
        auto &self = *static_cast<counting_step_scheduler *>(user);
        ++self.tasks;
        grain = grain == 0 ? 1 : grain;
        for (std::size_t begin = 0; begin < count; begin += grain)
            fn(context, begin, std::min(begin + grain, count));
        return user;
    }
    static void wait(void *, void *user) { ++static_cast<counting_step_scheduler *>(user)->waits; }

    init_config config(unsigned min_parallel_bodies) {
        init_config c{execution_mode::sequential_multithreaded};
        c.scheduler = task_hooks{&enqueue, &wait, this, 2};
        c.min_parallel_bodies = min_parallel_bodies;
        return c;
    }
};

constexpr unsigned threshold_pile_bodies = 200;

// The bodies' positions and orientations, as bytes, after `steps` steps of a pile of
// threshold_pile_bodies dropped on the ground.
std::vector<unsigned char> threshold_pile_transforms(const init_config &config, int steps) {
    registry reg;
    attach(reg, config);
    scenes::make_ground(reg);
    auto bodies = scenes::make_pile(reg, threshold_pile_bodies, 8, 2, scenes::pile_shapes::with_polyhedra);
    for (int i = 0; i < steps; ++i)
        step_simulation(reg);
    std::vector<unsigned char> bytes;
    for (auto e : bodies) {
        auto &p = reg.get<position>(e);
        auto &q = reg.get<orientation>(e);
        auto at = bytes.size();
        bytes.resize(at + sizeof(p) + sizeof(q));
        std::memcpy(bytes.data() + at, &p, sizeof(p));
        std::memcpy(bytes.data() + at + sizeof(p), &q, sizeof(q));
    }
    detach(reg);
    return bytes;
}

TEST(parallel_threshold, a_world_smaller_than_the_threshold_never_reaches_the_scheduler) {
    counting_step_scheduler below, at;
    constexpr int steps = 60;
    auto serial = threshold_pile_transforms(below.config(threshold_pile_bodies + 1), steps);
    EXPECT_EQ(below.tasks.load(), 0) << "a world of " << threshold_pile_bodies
                                     << " bodies handed tasks to the scheduler with a threshold of "
                                     << threshold_pile_bodies + 1;

    // At the threshold, from the first step on (which counts the dynamic bodies, none having
    // moved yet), the phases go to the scheduler, and every task is waited for.
    auto parallel = threshold_pile_transforms(at.config(threshold_pile_bodies), steps);
    EXPECT_GT(at.tasks.load(), steps) << "the step's phases did not reach the scheduler";
    EXPECT_EQ(at.waits.load(), at.tasks.load());

    // The same motion to the last bit, and the same as the sequential mode's.
    EXPECT_TRUE(serial == parallel) << "the threshold changed the result";
    EXPECT_TRUE(serial == threshold_pile_transforms(init_config{execution_mode::sequential}, steps));
}

TEST(parallel_threshold, the_default_keeps_a_small_world_on_the_calling_thread) {
    EXPECT_EQ(init_config{}.min_parallel_bodies, init_config::default_min_parallel_bodies);
    EXPECT_GT(init_config::default_min_parallel_bodies, threshold_pile_bodies);
    counting_step_scheduler program;
    auto config = program.config(0);
    config.min_parallel_bodies = init_config{}.min_parallel_bodies;
    threshold_pile_transforms(config, 10);
    EXPECT_EQ(program.tasks.load(), 0);
}

TEST(parallel_threshold, bodies_asleep_do_not_count) {
    // A thousand balls resting on the ground, threshold 1,000: the phases run on the scheduler
    // while the balls are awake; once they all sleep, the world moves no body and stays on this
    // thread (though its loops over the bodies and the manifolds, asleep or not, are long enough
    // to be spread).
    counting_step_scheduler program;
    registry reg;
    attach(reg, program.config(1000));
    scenes::make_ground(reg);
    std::vector<entity> balls;
    for (int i = 0; i < 1000; ++i) {
        rigidbody_def def;
        def.shape = sphere_shape{0.25};
        def.position = {scalar(i % 40) * scalar(0.6), scalar(0.25), scalar(i / 40) * scalar(0.6)};
        def.mass = 1;
        balls.push_back(make_rigidbody(reg, def));
    }
    auto all_asleep = [&] {
        for (auto e : balls)
            if (!reg.all_of<sleeping_tag>(e)) return false;
        return true;
    };
    step_simulation(reg);
    EXPECT_GT(program.tasks.load(), 0) << "a thousand awake balls did not reach the scheduler";
    for (int i = 0; i < 600 && !all_asleep(); ++i)
        step_simulation(reg);
    ASSERT_TRUE(all_asleep()) << "the balls did not fall asleep in 10 s";
    step_simulation(reg); // the step that finds no body awake since the last
    auto before = program.tasks.load();
    for (int i = 0; i < 30; ++i)
        step_simulation(reg);
    EXPECT_EQ(program.tasks.load(), before) << "a sleeping world handed tasks to the scheduler";
    // Woken, they count again.
    for (auto e : balls)
        wake_up_entity(reg, e);
    step_simulation(reg);
    step_simulation(reg);
    EXPECT_GT(program.tasks.load(), before) << "woken, the balls did not reach the scheduler";
    detach(reg);
}

} // namespace
} // namespace edyn
