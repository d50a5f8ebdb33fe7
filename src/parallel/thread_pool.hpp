#ifndef EDYN_SRC_PARALLEL_THREAD_POOL_HPP
#define EDYN_SRC_PARALLEL_THREAD_POOL_HPP

#include "edyn/parallel/task_scheduler.hpp"
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace edyn {

// The default scheduler's threads in ThreadSanitizer builds. oneTBB hands tasks between threads
// inside its own library, which such a build does not instrument, so TSan would report its
// internal hand-offs as races and could not check edyn's; this pool, written with standard
// primitives only, lets it check every access edyn's tasks make. It cuts work into ranges of
// exactly `grain` items, like the oneTBB path.
class thread_pool {
public:
    // `num_threads` threads run tasks, the caller's included (at least 1).
    explicit thread_pool(unsigned num_threads);
    ~thread_pool();
    thread_pool(const thread_pool &) = delete;
    thread_pool &operator=(const thread_pool &) = delete;

    unsigned concurrency() const noexcept { return unsigned(threads.size()) + 1; }

    // Runs fn over [0, count) and returns when every range has run. fn must not throw.
    void run(task_function fn, void *context, std::size_t count, std::size_t grain);

private:
    struct job {
        task_function fn;
        void *context;
        std::size_t count, grain, num_ranges;
        std::atomic<std::size_t> next_range{0};
        unsigned workers{0}; // threads other than the caller inside run_ranges, under `mutex`
    };

    static void run_ranges(job &j);
    void work();

    std::vector<std::thread> threads;
    std::mutex mutex;
    std::condition_variable wake, done;
    job *current{nullptr};       // the job threads may join, under `mutex`
    std::uint64_t generation{0}; // counts jobs, so that a thread joins each one once
    bool stopping{false};
};

} // namespace edyn

#endif // EDYN_SRC_PARALLEL_THREAD_POOL_HPP
