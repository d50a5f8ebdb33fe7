// background_job: one run at a time on a thread of its own, its writes visible once finished.
#include <atomic>
#include <chrono>
#include <edyn/parallel/background_job.hpp>
#include <gtest/gtest.h>
#include <stdexcept>
#include <thread>

namespace {

using namespace edyn;

TEST(background_job, a_run_writes_what_the_caller_reads_once_finished) {
    background_job job;
    EXPECT_FALSE(job.finished());
    EXPECT_FALSE(job.busy());
    auto result = 0;
    auto caller = std::this_thread::get_id();
    auto runner = caller;
    job.start([&] {
        runner = std::this_thread::get_id();
        for (int i = 1; i <= 100; ++i)
            result += i;
    });
    job.wait();
    EXPECT_TRUE(job.finished());
    EXPECT_FALSE(job.busy());
    EXPECT_EQ(result, 5050);
    EXPECT_NE(runner, caller) << "the run did not happen on the job's thread";
}

TEST(background_job, the_caller_goes_on_while_it_runs) {
    background_job job;
    std::atomic<bool> release{false};
    job.start([&] {
        while (!release.load())
            std::this_thread::yield();
    });
    EXPECT_TRUE(job.busy());
    EXPECT_FALSE(job.finished());
    EXPECT_THROW(job.start([] {}), std::logic_error) << "a second run started while one was in progress";
    release = true;
    job.wait();
    EXPECT_TRUE(job.finished());
}

TEST(background_job, runs_again_and_again_on_the_same_thread) {
    background_job job;
    auto first = std::thread::id{};
    auto count = 0;
    for (int i = 0; i < 50; ++i) {
        job.start([&] {
            if (first == std::thread::id{}) first = std::this_thread::get_id();
            EXPECT_EQ(std::this_thread::get_id(), first);
            ++count;
        });
        EXPECT_FALSE(job.finished() && count != i + 1);
        job.wait();
    }
    EXPECT_EQ(count, 50);
}

TEST(background_job, destroying_it_waits_for_the_run) {
    auto done = false;
    {
        background_job job;
        job.start([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            done = true;
        });
    }
    EXPECT_TRUE(done);
}

} // namespace
