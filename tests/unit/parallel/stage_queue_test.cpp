#include "support/one_range_at_a_time.hpp"
#include <atomic>
#include <cstdint>
#include <edyn/parallel/stage_queue.hpp>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

using namespace edyn;

namespace {

// Each block of each stage records, when it runs, how many blocks had finished before it.
struct recorded_blocks {
    std::vector<std::uint32_t> first_block; // per stage, in the record
    std::vector<std::atomic<int>> runs;
    std::vector<int> finished_before;
    std::atomic<int> finished{0};

    explicit recorded_blocks(const std::vector<std::uint32_t> &sizes)
        : runs(total(sizes))
        , finished_before(total(sizes), -1) {
        std::uint32_t n = 0;
        for (auto size : sizes) {
            first_block.push_back(n);
            n += size;
        }
    }
    static std::size_t total(const std::vector<std::uint32_t> &sizes) {
        std::size_t n = 0;
        for (auto s : sizes)
            n += s;
        return n;
    }

    void queue(stage_queue &queue, const std::vector<std::uint32_t> &sizes) {
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            auto size = sizes[k];
            auto first = first_block[k];
            queue.add(size, [this, first, size](std::uint32_t block) {
                EXPECT_LT(block, size);
                finished_before[first + block] = finished.load();
                runs[first + block].fetch_add(1);
                finished.fetch_add(1);
            });
        }
    }

    // Every block ran once, after every block of the stages queued before its own.
    void check() const {
        for (std::size_t k = 0; k < first_block.size(); ++k) {
            auto end = k + 1 < first_block.size() ? first_block[k + 1] : std::uint32_t(runs.size());
            for (auto b = first_block[k]; b < end; ++b) {
                EXPECT_EQ(runs[b].load(), 1) << "block " << b;
                EXPECT_GE(finished_before[b], int(first_block[k])) << "block " << b << " of stage " << k;
            }
        }
    }
};

} // namespace

TEST(stage_queue, runs_the_stages_in_the_order_queued_each_block_once_on_any_thread_count) {
    std::vector<std::uint32_t> sizes{3, 40, 0, 1, 17, 2, 25, 1, 1, 9};
    stage_queue queue;
    recorded_blocks alone(sizes);
    alone.queue(queue, sizes);
    queue.run(nullptr);
    alone.check();
    // On the calling thread the blocks run in order.
    for (std::size_t b = 0; b < alone.finished_before.size(); ++b)
        EXPECT_EQ(alone.finished_before[b], int(b));

    for (unsigned threads : {1u, 2u, 4u}) {
        task_scheduler scheduler(threads);
        for (int repeat = 0; repeat < 20; ++repeat) {
            recorded_blocks record(sizes);
            record.queue(queue, sizes);
            queue.run(&scheduler);
            record.check();
            EXPECT_TRUE(queue.empty());
        }
    }
}

// The point of the queue: however many stages, one run is one task for the scheduler.
TEST(stage_queue, hands_all_its_stages_to_the_scheduler_as_one_task) {
    test::one_range_at_a_time program;
    task_scheduler scheduler(program.hooks());
    std::vector<std::uint32_t> sizes{5, 1, 12, 3, 7, 7, 2};
    recorded_blocks record(sizes);
    stage_queue queue;
    record.queue(queue, sizes);
    EXPECT_FALSE(queue.empty());
    queue.run(&scheduler);
    record.check();
    EXPECT_EQ(program.tasks, 1u);
    EXPECT_TRUE(queue.empty());
    // An empty queue hands nothing over.
    queue.run(&scheduler);
    EXPECT_EQ(program.tasks, 1u);
}

TEST(stage_queue, add_for_calls_every_index_of_the_range_once_in_blocks_of_the_grain) {
    task_scheduler scheduler(4);
    stage_queue queue;
    std::vector<std::atomic<int>> calls(100);
    auto *counts = calls.data();
    queue.add_for(7u, 100u, 8u, [counts](std::uint32_t i) { counts[i].fetch_add(1); });
    queue.add_for(5u, 5u, 8u, [counts](std::uint32_t i) { counts[i].fetch_add(10); });
    queue.add_for(9u, 3u, 8u, [counts](std::uint32_t i) { counts[i].fetch_add(10); });
    queue.run(&scheduler);
    for (std::uint32_t i = 0; i < 100; ++i)
        EXPECT_EQ(calls[i].load(), i >= 7 ? 1 : 0) << "index " << i;

    EXPECT_THROW(queue.add_for(0u, 10u, 0u, [](std::uint32_t) {}), std::invalid_argument);
    EXPECT_TRUE(queue.empty());
}

// A stage's function is copied when it is queued: what it captured by value is what it sees.
TEST(stage_queue, keeps_a_copy_of_each_stage_function) {
    stage_queue queue;
    std::vector<int> seen;
    auto *out = &seen;
    for (int value = 0; value < 50; ++value)
        queue.add(1, [out, value](std::uint32_t) { out->push_back(value); });
    queue.run(nullptr);
    ASSERT_EQ(seen.size(), 50u);
    for (int value = 0; value < 50; ++value)
        EXPECT_EQ(seen[std::size_t(value)], value);
}

TEST(stage_queue, rethrows_the_first_exception_and_is_empty_after) {
    for (unsigned threads : {1u, 4u}) {
        task_scheduler scheduler(threads);
        stage_queue queue;
        std::atomic<int> ran{0};
        auto *count = &ran;
        queue.add(10, [count](std::uint32_t block) {
            count->fetch_add(1);
            if (block == 3) throw std::runtime_error("block 3");
        });
        queue.add(20, [count](std::uint32_t) { count->fetch_add(1); });
        EXPECT_THROW(queue.run(&scheduler), std::runtime_error);
        EXPECT_EQ(ran.load(), 30) << "the other blocks still ran, " << threads << " threads";
        EXPECT_TRUE(queue.empty());
    }
}

TEST(stage_queue, clear_drops_the_queued_stages_unrun) {
    stage_queue queue;
    int calls = 0;
    auto *count = &calls;
    queue.add(3, [count](std::uint32_t) { ++*count; });
    queue.add(0, [count](std::uint32_t) { ++*count; });
    queue.clear();
    EXPECT_TRUE(queue.empty());
    queue.run(nullptr);
    EXPECT_EQ(calls, 0);
}
