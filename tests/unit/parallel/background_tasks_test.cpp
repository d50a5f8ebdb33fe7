// background_tasks: tasks run once each, in the background, on edyn's own thread or through a
// program's task_hooks, whose handles all come back to `wait`; the destructor waits for them.
#include <atomic>
#include <edyn/parallel/background_tasks.hpp>
#include <gtest/gtest.h>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace edyn;

// A program's scheduler that runs each task on a thread of its own, joined by `wait`.
struct thread_per_task {
    std::atomic<int> enqueued{0}, waited{0};

    static void *enqueue(task_function fn, void *context, std::size_t count, std::size_t, void *user) {
        ++static_cast<thread_per_task *>(user)->enqueued;
        return new std::thread([=] { fn(context, 0, count); });
    }
    static void wait(void *handle, void *user) {
        auto *thread = static_cast<std::thread *>(handle);
        thread->join();
        delete thread;
        ++static_cast<thread_per_task *>(user)->waited;
    }
    task_hooks hooks() { return {&enqueue, &wait, this, 2}; }
};

TEST(background_tasks, edyn_s_thread_runs_every_task_once_in_order_off_the_caller) {
    std::vector<int> order;
    std::mutex mutex;
    auto caller = std::this_thread::get_id();
    std::atomic<int> on_caller{0};
    {
        background_tasks tasks;
        EXPECT_FALSE(tasks.uses_program_scheduler());
        for (int i = 0; i < 50; ++i) {
            tasks.post([&, i] {
                if (std::this_thread::get_id() == caller) ++on_caller;
                std::lock_guard lock(mutex);
                order.push_back(i);
            });
        }
    } // Waits for all.
    ASSERT_EQ(order.size(), 50u);
    for (int i = 0; i < 50; ++i)
        EXPECT_EQ(order[std::size_t(i)], i);
    EXPECT_EQ(on_caller.load(), 0);
}

TEST(background_tasks, a_task_posted_while_another_runs_runs_too) {
    std::atomic<bool> release{false};
    std::atomic<int> ran{0};
    background_tasks tasks;
    tasks.post([&] {
        while (!release.load())
            std::this_thread::yield();
        ++ran;
    });
    tasks.post([&] { ++ran; });
    EXPECT_EQ(ran.load(), 0) << "the second task overtook the first";
    release = true;
    // And after the thread went idle.
    while (ran.load() < 2)
        std::this_thread::yield();
    tasks.post([&] { ++ran; });
    while (ran.load() < 3)
        std::this_thread::yield();
    EXPECT_EQ(ran.load(), 3);
}

TEST(background_tasks, a_program_scheduler_runs_the_tasks_and_gets_every_handle_back) {
    thread_per_task scheduler;
    std::atomic<int> ran{0};
    {
        background_tasks tasks(scheduler.hooks());
        EXPECT_TRUE(tasks.uses_program_scheduler());
        for (int i = 0; i < 10; ++i)
            tasks.post([&] { ++ran; });
        EXPECT_EQ(scheduler.enqueued.load(), 10);
        while (ran.load() < 10)
            std::this_thread::yield();
        tasks.release_finished();
        // Every task has run: every handle went back, and nothing is left for the destructor.
        EXPECT_EQ(scheduler.waited.load(), 10);
        tasks.post([&] { ++ran; });
    }
    EXPECT_EQ(ran.load(), 11);
    EXPECT_EQ(scheduler.enqueued.load(), 11);
    EXPECT_EQ(scheduler.waited.load(), 11) << "the destructor must wait for the last task";
}

TEST(background_tasks, incomplete_hooks_are_refused_naming_the_field) {
    thread_per_task scheduler;
    auto hooks = scheduler.hooks();
    hooks.enqueue = nullptr;
    try {
        background_tasks tasks(hooks);
        FAIL() << "no exception for a null enqueue";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("task_hooks::enqueue"), std::string::npos) << e.what();
    }
    hooks = scheduler.hooks();
    hooks.wait = nullptr;
    try {
        background_tasks tasks(hooks);
        FAIL() << "no exception for a null wait";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("task_hooks::wait"), std::string::npos) << e.what();
    }
}

} // namespace
