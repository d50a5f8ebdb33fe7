#include "thread_pool.hpp"
#include <algorithm>

namespace edyn {

thread_pool::thread_pool(unsigned num_threads) {
    for (unsigned i = 1; i < num_threads; ++i)
        threads.emplace_back([this] { work(); });
}

thread_pool::~thread_pool() {
    {
        std::lock_guard lock(mutex);
        stopping = true;
    }
    wake.notify_all();
    for (auto &t : threads)
        t.join();
}

void thread_pool::run_ranges(job &j) {
    for (;;) {
        auto r = j.next_range.fetch_add(1);
        if (r >= j.num_ranges) return;
        j.fn(j.context, r * j.grain, std::min((r + 1) * j.grain, j.count));
    }
}

void thread_pool::work() {
    std::unique_lock lock(mutex);
    std::uint64_t joined = 0;
    for (;;) {
        wake.wait(lock, [&] { return stopping || (current != nullptr && generation != joined); });
        if (stopping) return;
        joined = generation;
        auto &j = *current;
        ++j.workers;
        lock.unlock();
        run_ranges(j);
        lock.lock();
        if (--j.workers == 0) done.notify_all();
    }
}

void thread_pool::run(task_function fn, void *context, std::size_t count, std::size_t grain) {
    job j{fn, context, count, grain, (count + grain - 1) / grain};
    if (!threads.empty()) {
        {
            std::lock_guard lock(mutex);
            current = &j;
            ++generation;
        }
        wake.notify_all();
    }
    run_ranges(j);
    if (threads.empty()) return;
    // No thread joins once `current` is cleared; wait for those that did.
    std::unique_lock lock(mutex);
    current = nullptr;
    done.wait(lock, [&] { return j.workers == 0; });
}

} // namespace edyn
