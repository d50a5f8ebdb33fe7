#include "src/parallel/thread_pool.hpp"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <edyn/parallel/parallel_for.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace edyn;

namespace {

// Counts how many times each index was visited.
std::vector<int> visits(task_scheduler &scheduler, std::size_t count, std::size_t grain) {
    std::vector<std::atomic<int>> counters(count);
    parallel_for(scheduler, std::size_t(0), count, grain, [&](std::size_t i) { counters[i].fetch_add(1); });
    std::vector<int> result;
    for (auto &c : counters)
        result.push_back(c.load());
    return result;
}

} // namespace

TEST(parallel_for, visits_every_index_exactly_once_whatever_the_threads_and_grain) {
    for (unsigned threads : {1u, 2u, 4u}) {
        task_scheduler scheduler(threads);
        for (std::size_t count : {0u, 1u, 7u, 64u, 1000u, 10007u}) {
            for (std::size_t grain : {1u, 16u, 5000u}) {
                auto v = visits(scheduler, count, grain);
                EXPECT_EQ(std::count(v.begin(), v.end(), 1), std::ptrdiff_t(count))
                    << threads << " threads, " << count << " items, grain " << grain;
            }
        }
    }
}

TEST(parallel_for, runs_over_any_index_interval) {
    task_scheduler scheduler(2);
    std::vector<std::atomic<int>> seen(100);
    parallel_for(scheduler, -50, 50, 4, [&](int i) { seen[std::size_t(i + 50)].fetch_add(1); });
    for (std::size_t i = 0; i < seen.size(); ++i)
        EXPECT_EQ(seen[i].load(), 1) << "index " << int(i) - 50;
}

TEST(parallel_for, ranges_run_at_the_same_time_on_several_threads) {
    // Each of the two halves waits for the other to start: this finishes only if two threads run
    // them at once (a time-out turns a sequential run into a failure instead of a hang).
    task_scheduler scheduler(2);
    ASSERT_EQ(scheduler.concurrency(), 2u);
    std::atomic<int> started{0};
    std::atomic<bool> met{true};
    parallel_for(scheduler, 0, 2, 1, [&](int) {
        started.fetch_add(1);
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (started.load() < 2) {
            if (std::chrono::steady_clock::now() > deadline) {
                met = false;
                return;
            }
            std::this_thread::yield();
        }
    });
    EXPECT_TRUE(met.load()) << "the two ranges never ran at the same time";
}

TEST(parallel_for, small_work_runs_in_the_calling_thread) {
    task_scheduler scheduler(4);
    auto caller = std::this_thread::get_id();
    std::atomic<int> elsewhere{0};
    parallel_for(scheduler, 0, 64, 64, [&](int) {
        if (std::this_thread::get_id() != caller) elsewhere.fetch_add(1);
    });
    EXPECT_EQ(elsewhere.load(), 0);
}

TEST(parallel_for, results_merged_in_index_order_do_not_depend_on_the_thread_count) {
    // The pattern the step uses: each index writes its own slot, the caller merges in order.
    auto run = [](unsigned threads) {
        task_scheduler scheduler(threads);
        std::vector<float> slots(5000);
        parallel_for(scheduler, std::size_t(0), slots.size(), 8,
                     [&](std::size_t i) { slots[i] = 1.0f / float(i + 1) * (i % 3 == 0 ? -1.0f : 1.0f); });
        float sum = 0;
        for (auto s : slots)
            sum += s;
        return sum;
    };
    auto one = run(1);
    EXPECT_EQ(one, run(2));
    EXPECT_EQ(one, run(4));
}

TEST(parallel_for, the_first_exception_is_rethrown_in_the_caller_and_the_scheduler_stays_usable) {
    task_scheduler scheduler(2);
    EXPECT_THROW(parallel_for(scheduler, 0, 1000, 10,
                              [](int i) {
                                  if (i == 537) throw std::runtime_error("item 537");
                              }),
                 std::runtime_error);
    auto v = visits(scheduler, 1000, 10);
    EXPECT_EQ(std::count(v.begin(), v.end(), 1), 1000);
}

TEST(parallel_for, rejects_a_zero_grain_and_a_reversed_interval) {
    task_scheduler scheduler(1);
    auto nothing = [](int) {};
    EXPECT_THROW(parallel_for(scheduler, 0, 10, 0, nothing), std::invalid_argument);
    try {
        parallel_for(scheduler, 10, 3, 1, nothing);
        ADD_FAILURE() << "no exception for first > last";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("parallel_for"), std::string::npos) << e.what();
    }
}

TEST(parallel_for, without_a_scheduler_rejects_a_zero_grain_and_a_reversed_interval) {
    auto *none = static_cast<task_scheduler *>(nullptr);
    int calls = 0;
    auto count = [&](int) { ++calls; };
    EXPECT_THROW(parallel_for(none, 0, 10, 0, count), std::invalid_argument);
    try {
        parallel_for(none, 10, 3, 1, count);
        ADD_FAILURE() << "no exception for first > last without a scheduler";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("parallel_for"), std::string::npos) << e.what();
    }
    EXPECT_EQ(calls, 0);
}

TEST(task_scheduler, rejects_a_thread_count_oneTBB_cannot_take) {
    auto too_many = unsigned(std::numeric_limits<int>::max()) + 1u;
    try {
        task_scheduler scheduler(too_many);
        ADD_FAILURE() << "no exception for " << too_many << " threads, concurrency "
                      << scheduler.concurrency();
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        EXPECT_NE(what.find("task_scheduler"), std::string::npos) << what;
        EXPECT_NE(what.find(std::to_string(too_many)), std::string::npos) << what;
    }
    EXPECT_THROW(task_scheduler{std::numeric_limits<unsigned>::max()}, std::invalid_argument);
}

namespace {

// A program's scheduler: enqueue only records the task, wait runs it in ranges of `grain`
// (as a job system that defers work to when it is waited on would).
struct deferred_scheduler {
    task_function fn{nullptr};
    void *context{nullptr};
    std::size_t count{0}, grain{0};
    int enqueued{0}, waited{0}, ranges{0};
    int handle_token{0};
    bool handle_matched{false};

    static void *enqueue(task_function fn, void *context, std::size_t count, std::size_t grain, void *user) {
        auto &self = *static_cast<deferred_scheduler *>(user);
        self.fn = fn;
        self.context = context;
        self.count = count;
        self.grain = grain;
        ++self.enqueued;
        return &self.handle_token;
    }
    static void wait(void *handle, void *user) {
        auto &self = *static_cast<deferred_scheduler *>(user);
        ++self.waited;
        self.handle_matched = handle == &self.handle_token;
        for (std::size_t begin = 0; begin < self.count; begin += self.grain) {
            self.fn(self.context, begin, std::min(begin + self.grain, self.count));
            ++self.ranges;
        }
    }
};

} // namespace

TEST(task_scheduler, hands_the_work_to_the_programs_hooks) {
    deferred_scheduler program;
    task_hooks hooks;
    hooks.enqueue = &deferred_scheduler::enqueue;
    hooks.wait = &deferred_scheduler::wait;
    hooks.user = &program;
    hooks.concurrency = 8;
    task_scheduler scheduler(hooks);
    EXPECT_EQ(scheduler.concurrency(), 8u);

    auto v = visits(scheduler, 100, 10);
    EXPECT_EQ(std::count(v.begin(), v.end(), 1), 100);
    EXPECT_EQ(program.enqueued, 1);
    EXPECT_EQ(program.waited, 1);
    EXPECT_TRUE(program.handle_matched) << "wait did not get the handle enqueue returned";
    EXPECT_EQ(program.ranges, 10);
}

TEST(task_scheduler, rejects_incomplete_hooks) {
    task_hooks hooks;
    EXPECT_THROW(task_scheduler{hooks}, std::invalid_argument);
    hooks.enqueue = &deferred_scheduler::enqueue;
    EXPECT_THROW(task_scheduler{hooks}, std::invalid_argument);
    hooks.wait = &deferred_scheduler::wait;
    hooks.concurrency = 0;
    EXPECT_THROW(task_scheduler{hooks}, std::invalid_argument);
}

TEST(task_scheduler, zero_threads_means_one_per_hardware_thread) {
    task_scheduler scheduler(0);
    auto hardware = std::thread::hardware_concurrency();
    if (hardware > 0) {
        EXPECT_EQ(scheduler.concurrency(), hardware);
    }
    EXPECT_GE(scheduler.concurrency(), 1u);
}

// The standard-library pool the default scheduler uses in ThreadSanitizer builds, checked in
// every build.
TEST(thread_pool, runs_every_range_once_with_the_caller_taking_part) {
    for (unsigned threads : {1u, 2u, 3u}) {
        thread_pool pool(threads);
        EXPECT_EQ(pool.concurrency(), threads);
        for (int round = 0; round < 50; ++round) {
            std::vector<std::atomic<int>> seen(1001);
            auto fn = [](void *context, std::size_t begin, std::size_t end) {
                auto &s = *static_cast<std::vector<std::atomic<int>> *>(context);
                EXPECT_LE(end - begin, 10u);
                for (auto i = begin; i < end; ++i)
                    s[i].fetch_add(1);
            };
            pool.run(fn, &seen, seen.size(), 10);
            for (std::size_t i = 0; i < seen.size(); ++i)
                ASSERT_EQ(seen[i].load(), 1) << threads << " threads, round " << round << ", index " << i;
        }
    }
}

TEST(parallel_for, without_a_scheduler_runs_in_order_in_the_calling_thread) {
    std::vector<int> order;
    parallel_for(static_cast<task_scheduler *>(nullptr), 0, 1000, 10, [&](int i) { order.push_back(i); });
    std::vector<int> expected(1000);
    std::iota(expected.begin(), expected.end(), 0);
    EXPECT_EQ(order, expected);
}
