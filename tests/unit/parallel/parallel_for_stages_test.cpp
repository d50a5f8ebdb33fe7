#include "support/one_range_at_a_time.hpp"
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <edyn/parallel/parallel_for_stages.hpp>
#include <gtest/gtest.h>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace edyn;

namespace {

// Stages of 0 to 40 blocks; each block records, when it runs, how many blocks of earlier stages
// had finished, and adds itself to the finished count when done.
struct staged_run {
    std::vector<std::uint32_t> stage_begin;
    std::vector<std::atomic<int>> runs;
    std::vector<int> finished_before;
    std::atomic<std::uint32_t> finished{0};

    explicit staged_run(std::vector<std::uint32_t> sizes)
        : runs(total(sizes))
        , finished_before(total(sizes), -1) {
        stage_begin.push_back(0);
        for (auto n : sizes)
            stage_begin.push_back(stage_begin.back() + n);
    }
    static std::size_t total(const std::vector<std::uint32_t> &sizes) {
        std::size_t n = 0;
        for (auto s : sizes)
            n += s;
        return n;
    }

    void run(task_scheduler *scheduler, stage_sync &sync) {
        parallel_for_stages(scheduler, sync, stage_begin, [&](std::size_t stage, std::uint32_t block) {
            EXPECT_GE(block, stage_begin[stage]);
            EXPECT_LT(block, stage_begin[stage + 1]);
            finished_before[block] = int(finished.load());
            runs[block].fetch_add(1);
            finished.fetch_add(1);
        });
    }

    // Every block ran once, after every block of the earlier stages.
    void check() const {
        for (std::size_t k = 0; k + 1 < stage_begin.size(); ++k) {
            for (auto b = stage_begin[k]; b < stage_begin[k + 1]; ++b) {
                EXPECT_EQ(runs[b].load(), 1) << "block " << b;
                EXPECT_GE(finished_before[b], int(stage_begin[k])) << "block " << b << " of stage " << k;
            }
        }
    }
};

} // namespace

TEST(parallel_for_stages, runs_each_block_once_after_the_earlier_stages_on_any_thread_count) {
    std::vector<std::uint32_t> sizes{3, 40, 0, 1, 17, 2, 0, 25, 1, 1, 9};
    stage_sync sync;
    staged_run alone(sizes);
    alone.run(nullptr, sync);
    alone.check();
    // On the calling thread the blocks run in order.
    for (std::size_t b = 0; b < alone.finished_before.size(); ++b)
        EXPECT_EQ(alone.finished_before[b], int(b));

    for (unsigned threads : {1u, 2u, 4u, 8u}) {
        task_scheduler scheduler(threads);
        for (int repeat = 0; repeat < 20; ++repeat) {
            staged_run run(sizes);
            run.run(&scheduler, sync);
            run.check();
        }
    }
}

// One stage_sync serves calls of any layout, one after another: it grows for more blocks and
// stages, and a block taken in one call is free again in the next.
TEST(parallel_for_stages, one_sync_serves_calls_of_growing_and_shrinking_layouts) {
    task_scheduler scheduler(4);
    stage_sync sync;
    for (auto sizes : std::vector<std::vector<std::uint32_t>>{
             {2, 3}, {40, 1, 0, 30, 7, 12, 5}, {1, 1}, {64, 64, 64, 64}, {3}, {0, 9, 0, 2}}) {
        for (int repeat = 0; repeat < 3; ++repeat) {
            staged_run run(sizes);
            run.run(&scheduler, sync);
            run.check();
        }
    }
}

// The threads wait within the task for the earlier stages: a scheduler that runs the task's
// ranges one at a time, in reverse, must still see every block run, in stage order.
TEST(parallel_for_stages, does_not_stall_on_a_scheduler_that_runs_one_range_at_a_time) {
    test::one_range_at_a_time program;
    task_scheduler scheduler(program.hooks());
    stage_sync sync;
    staged_run run({5, 1, 12, 3});
    run.run(&scheduler, sync);
    run.check();
}

TEST(parallel_for_stages, rethrows_the_first_exception_after_every_block_ran) {
    std::vector<std::uint32_t> stage_begin{0, 10, 30};
    for (unsigned threads : {1u, 4u}) {
        task_scheduler scheduler(threads);
        std::atomic<int> ran{0};
        stage_sync sync;
        EXPECT_THROW(parallel_for_stages(&scheduler, sync, stage_begin,
                                         [&](std::size_t, std::uint32_t block) {
                                             ran.fetch_add(1);
                                             if (block == 3) throw std::runtime_error("block 3");
                                         }),
                     std::runtime_error);
        EXPECT_EQ(ran.load(), 30) << "the blocks after the throwing one still ran, " << threads << " threads";
    }
}

TEST(parallel_for_stages, no_stages_or_empty_stages_run_nothing) {
    task_scheduler scheduler(2);
    int calls = 0;
    stage_sync sync;
    parallel_for_stages(&scheduler, sync, std::vector<std::uint32_t>{},
                        [&](std::size_t, std::uint32_t) { ++calls; });
    parallel_for_stages(&scheduler, sync, std::vector<std::uint32_t>{0},
                        [&](std::size_t, std::uint32_t) { ++calls; });
    parallel_for_stages(&scheduler, sync, std::vector<std::uint32_t>{0, 0, 0},
                        [&](std::size_t, std::uint32_t) { ++calls; });
    EXPECT_EQ(calls, 0);
}

// Consecutive stages of one block each (a chain's joints, one colour each) run as one, in order,
// on whichever thread takes the first; when no stage has two blocks, the call is never handed to
// the scheduler at all.
TEST(parallel_for_stages, runs_stages_of_one_block_in_a_row_on_one_thread) {
    std::vector<std::uint32_t> stage_begin{0, 1, 2, 2, 3, 10, 11, 12, 13, 20};
    task_scheduler scheduler(4);
    stage_sync sync;
    for (int repeat = 0; repeat < 20; ++repeat) {
        std::vector<std::thread::id> ran_on(stage_begin.back());
        std::vector<int> order;
        std::mutex order_mutex;
        parallel_for_stages(&scheduler, sync, stage_begin, [&](std::size_t, std::uint32_t block) {
            ran_on[block] = std::this_thread::get_id();
            std::lock_guard lock(order_mutex);
            order.push_back(int(block));
        });
        ASSERT_EQ(order.size(), std::size_t(20));
        // Blocks 0 to 2 (stages 0, 1 and 3) on one thread, in order; so are 10 to 12.
        EXPECT_EQ(ran_on[1], ran_on[0]);
        EXPECT_EQ(ran_on[2], ran_on[0]);
        EXPECT_EQ(ran_on[11], ran_on[10]);
        EXPECT_EQ(ran_on[12], ran_on[10]);
        auto place = [&](int block) { return std::find(order.begin(), order.end(), block) - order.begin(); };
        EXPECT_LT(place(0), place(1));
        EXPECT_LT(place(1), place(2));
        EXPECT_LT(place(10), place(11));
        EXPECT_LT(place(11), place(12));
        for (int b = 3; b < 10; ++b) {
            EXPECT_GT(place(b), place(2)) << "block " << b;
            EXPECT_LT(place(b), place(10)) << "block " << b;
        }
        for (int b = 13; b < 20; ++b)
            EXPECT_GT(place(b), place(12)) << "block " << b;
    }

    test::one_range_at_a_time program;
    task_scheduler counted(program.hooks());
    std::vector<std::uint32_t> single_blocks{0, 1, 2, 2, 3, 4};
    std::vector<int> order;
    parallel_for_stages(&counted, sync, single_blocks,
                        [&](std::size_t, std::uint32_t block) { order.push_back(int(block)); });
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(program.tasks, 0u) << "a call with no stage of two blocks stays on the calling thread";
    parallel_for_stages(&counted, sync, stage_begin, [](std::size_t, std::uint32_t) {});
    EXPECT_EQ(program.tasks, 1u);
}
