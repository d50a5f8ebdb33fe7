#ifndef EDYN_TESTS_SUPPORT_ONE_RANGE_AT_A_TIME_HPP
#define EDYN_TESTS_SUPPORT_ONE_RANGE_AT_A_TIME_HPP

#include <algorithm>
#include <cstddef>
#include <edyn/parallel/task_scheduler.hpp>
#include <vector>

namespace edyn::test {

// A program's scheduler that claims four threads but runs nothing at once: its wait hook runs a
// task's ranges one after another on the calling thread, the last range first. Work that waits
// within a task for other ranges of it must neither stall on it nor change a bit.
struct one_range_at_a_time {
    struct task {
        task_function fn;
        void *context;
        std::size_t count, grain;
    };
    std::vector<task> pending; // a stack: a task may start another before it is waited for
    unsigned tasks{0};

    one_range_at_a_time() { pending.reserve(8); }

    task_hooks hooks() { return {&enqueue, &wait, this, 4}; }

    static void *enqueue(task_function fn, void *context, std::size_t count, std::size_t grain, void *user) {
        auto &self = *static_cast<one_range_at_a_time *>(user);
        self.pending.push_back({fn, context, count, grain});
        ++self.tasks;
        return &self.pending.back();
    }
    static void wait(void *handle, void *user) {
        auto &self = *static_cast<one_range_at_a_time *>(user);
        auto t = *static_cast<task *>(handle);
        self.pending.pop_back();
        for (auto r = (t.count + t.grain - 1) / t.grain; r-- > 0;)
            t.fn(t.context, r * t.grain, std::min((r + 1) * t.grain, t.count));
    }
};

} // namespace edyn::test

#endif // EDYN_TESTS_SUPPORT_ONE_RANGE_AT_A_TIME_HPP
