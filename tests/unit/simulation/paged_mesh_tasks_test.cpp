// Page loads of a paged mesh go through the world's task interface: a program's scheduler
// (init_config::scheduler) sees and runs them, and the bodies land on the pages it loaded;
// without one they run off the stepping thread.
#include <atomic>
#include <chrono>
#include <cmath>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <thread>
#include <vector>

using namespace edyn;

namespace {

// Whether the current thread is running a task of the program's scheduler below.
thread_local bool in_program_task = false;

// A program's scheduler: every task on a thread of its own, joined by `wait`. Counts the tasks
// of one item (edyn's background work: the step's parallel loops here have more) and every
// handle given back.
struct program_scheduler {
    std::atomic<int> single_item_tasks{0}, handles_back{0}, tasks{0};

    static void *enqueue(task_function fn, void *context, std::size_t count, std::size_t, void *user) {
        auto &self = *static_cast<program_scheduler *>(user);
        ++self.tasks;
        if (count == 1) ++self.single_item_tasks;
        return new std::thread([=] {
            in_program_task = true;
            fn(context, 0, count);
        });
    }
    static void wait(void *handle, void *user) {
        auto *thread = static_cast<std::thread *>(handle);
        thread->join();
        delete thread;
        ++static_cast<program_scheduler *>(user)->handles_back;
    }
};

// Pages from memory; counts the loads and those run inside a task of the program's scheduler.
struct counting_loader final : triangle_mesh_page_loader {
    std::unique_ptr<triangle_mesh_page_loader> pages;
    std::shared_ptr<std::atomic<int>> loads = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> loads_in_program_tasks = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> loads_on_stepping_thread = std::make_shared<std::atomic<int>>(0);
    std::thread::id stepping_thread = std::this_thread::get_id();

    explicit counting_loader(const std::vector<triangle_mesh_page> &source)
        : pages(make_memory_page_loader(source)) {}

    std::shared_ptr<triangle_mesh> load(std::size_t page) override {
        ++*loads;
        if (in_program_task) ++*loads_in_program_tasks;
        if (std::this_thread::get_id() == stepping_thread) ++*loads_on_stepping_thread;
        return pages->load(page);
    }
};

struct terrain {
    entity body;
    std::shared_ptr<paged_triangle_mesh> mesh;
    std::shared_ptr<std::atomic<int>> loads, loads_in_program_tasks, loads_on_stepping_thread;
};

// A 60 m x 60 m hilly paged terrain of 7,200 triangles in pages of 100.
terrain make_terrain(registry &reg) {
    auto grid =
        scenes::make_grid_mesh(60, 1, [](scalar x, scalar z) { return scenes::terrain_height(x, z, 2); });
    auto v = grid->get_vertices();
    auto i = grid->get_indices();
    auto source = create_paged_triangle_mesh({v.begin(), v.end()}, {i.begin(), i.end()}, 100);
    std::vector<AABB> aabbs;
    std::vector<std::size_t> counts;
    for (std::size_t p = 0; p < source->num_pages(); ++p) {
        aabbs.push_back(source->get_page_aabb(p));
        counts.push_back(source->num_page_triangles(p));
    }
    auto loader = std::make_unique<counting_loader>(*source->get_loader().memory_pages());
    terrain t{null, nullptr, loader->loads, loader->loads_in_program_tasks, loader->loads_on_stepping_thread};
    t.mesh = std::make_shared<paged_triangle_mesh>(aabbs, counts, std::move(loader));
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = paged_mesh_shape{t.mesh};
    t.body = make_rigidbody(reg, def);
    return t;
}

// Balls dropped from 3 m over the terrain, some of them thrown sideways so that they reach pages
// they were not over at first.
std::vector<entity> drop_balls(registry &reg) {
    std::vector<entity> balls;
    for (int k = 0; k < 6; ++k) {
        auto x = scalar(-20 + 8 * k), z = scalar(-15 + 5 * k);
        rigidbody_def def;
        def.shape = sphere_shape{scalar(0.4)};
        def.mass = 1;
        def.position = {x, scenes::terrain_height(x, z, 2) + 3, z};
        def.linvel = {scalar(k == 5 ? -6 : k % 2 ? 6 : 0), 0, 0};
        def.sleeping_disabled = true;
        balls.push_back(make_rigidbody(reg, def));
    }
    return balls;
}

void expect_resting_on_terrain(registry &reg, const std::vector<entity> &balls) {
    for (auto e : balls) {
        auto p = reg.get<position>(e);
        ASSERT_LT(std::abs(p.x), 30) << "left the terrain";
        auto ground = scenes::terrain_height(p.x, p.z, 2);
        EXPECT_GT(p.y, ground + scalar(0.3)) << "fell through at x = " << p.x << ", z = " << p.z;
        EXPECT_LT(p.y, ground + 1) << "not on the ground at x = " << p.x << ", z = " << p.z;
    }
}

// Attaches `reg` with `config`, drops the balls on the terrain and steps 2 s; checks that they
// rest on it and that only some of the pages were loaded. Between steps the stepping thread
// sleeps a little, as a game's frame would: on a busy machine a background load could otherwise
// be overtaken every time by the step that needs its page, which then loads it itself.
terrain balls_landed_on_terrain(registry &reg, const init_config &config) {
    attach(reg, config);
    auto t = make_terrain(reg);
    auto balls = drop_balls(reg);
    for (int i = 0; i < 120; ++i) {
        step_simulation(reg);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    expect_resting_on_terrain(reg, balls);
    EXPECT_GT(t.mesh->num_loaded_pages(), 0u);
    EXPECT_LT(t.mesh->num_loaded_pages(), t.mesh->num_pages());
    return t;
}

} // namespace

TEST(paged_mesh_tasks_test, a_program_scheduler_sees_and_runs_the_page_loads) {
    program_scheduler scheduler;
    init_config config{execution_mode::sequential_multithreaded};
    config.scheduler = task_hooks{&program_scheduler::enqueue, &program_scheduler::wait, &scheduler, 2};
    config.min_parallel_bodies = 0; // the step's loops on the program's threads too
    registry reg;
    auto t = balls_landed_on_terrain(reg, config);
    // Every load the step did not have to do at once ran as a task of the program's scheduler,
    // which was handed one task of one item per page asked for in advance.
    EXPECT_GT(t.loads_in_program_tasks->load(), 0) << "no page was loaded by the program's scheduler";
    EXPECT_EQ(t.loads_in_program_tasks->load() + t.loads_on_stepping_thread->load(), t.loads->load());
    EXPECT_GE(scheduler.single_item_tasks.load(), t.loads_in_program_tasks->load());
    detach(reg);
    // Every task's handle came back to the program's `wait`.
    EXPECT_EQ(scheduler.handles_back.load(), scheduler.tasks.load());
}

TEST(paged_mesh_tasks_test, without_a_program_scheduler_pages_load_off_the_stepping_thread) {
    for (auto mode : {execution_mode::sequential, execution_mode::sequential_multithreaded}) {
        init_config config{mode};
        config.num_worker_threads = 2;
        config.min_parallel_bodies = 0;
        registry reg;
        auto t = balls_landed_on_terrain(reg, config);
        // Pages asked for in advance loaded in the background (those needed at once, if any, on
        // the stepping thread).
        EXPECT_GT(t.loads->load() - t.loads_on_stepping_thread->load(), 0) << "mode " << int(mode);
        EXPECT_EQ(t.loads_in_program_tasks->load(), 0);
        detach(reg);
    }
}
