#ifndef EDYN_PARALLEL_PARALLEL_FOR_HPP
#define EDYN_PARALLEL_PARALLEL_FOR_HPP

#include "edyn/parallel/task_scheduler.hpp"
#include <atomic>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

namespace edyn {

namespace detail {

// What the scheduler's threads share while running one parallel_for: the caller's function and
// the first exception any range threw (the others are dropped), rethrown in the caller's thread.
template<typename Index, typename Fn>
struct parallel_for_context {
    Index first;
    Fn *fn;
    std::atomic<bool> failed{false};
    std::exception_ptr error{};

    parallel_for_context(Index first, Fn *fn)
        : first(first)
        , fn(fn) {}

    static void run(void *context, std::size_t begin, std::size_t end) {
        auto &self = *static_cast<parallel_for_context *>(context);
        if (self.failed.load(std::memory_order_relaxed)) return;
        try {
            for (auto i = begin; i < end; ++i)
                (*self.fn)(static_cast<Index>(self.first + static_cast<Index>(i)));
        } catch (...) {
            if (!self.failed.exchange(true)) self.error = std::current_exception();
        }
    }
};

// Both overloads of parallel_for refuse the same arguments, with or without a scheduler.
template<typename Index>
void validate_parallel_for(Index first, Index last, std::size_t grain) {
    if (grain == 0) throw std::invalid_argument("parallel_for: grain must be at least 1, not 0");
    if (last < first) {
        throw std::invalid_argument("parallel_for: first (" + std::to_string(first) + ") is after last (" +
                                    std::to_string(last) + ")");
    }
}

} // namespace detail

/// Calls fn(i) for every i in [first, last), spread over the scheduler's threads in ranges of
/// at least `grain` indices; returns when every call has returned.
///
/// Work no larger than one range, or a scheduler of concurrency 1, runs in the calling thread,
/// without the scheduler. Calls may run in any order and at once: fn must write only what index
/// i owns, and the caller merges in a fixed order so that results do not depend on the thread
/// count. If any call throws, the remaining ranges are skipped and the first exception is
/// rethrown here.
/// @param scheduler The scheduler whose threads run the calls.
/// @param first First index.
/// @param last One past the last index.
/// @param grain Smallest number of indices per range, at least 1.
/// @param fn Callable taking an `Index`.
/// @throws std::invalid_argument If first > last or grain is 0.
template<typename Index, typename Fn>
void parallel_for(task_scheduler &scheduler, Index first, Index last, std::size_t grain, Fn &&fn) {
    detail::validate_parallel_for(first, last, grain);
    auto count = static_cast<std::size_t>(last - first);
    if (count <= grain || scheduler.concurrency() == 1) {
        for (auto i = first; i < last; ++i)
            fn(i);
        return;
    }
    using context_type = detail::parallel_for_context<Index, std::remove_reference_t<Fn>>;
    context_type context{first, &fn};
    scheduler.run(&context_type::run, &context, count, grain);
    if (context.error) std::rethrow_exception(context.error);
}

/// `parallel_for` with an optional scheduler: without one (null), every call runs in the
/// calling thread, in index order.
/// @param scheduler The scheduler, or null.
/// @param first First index.
/// @param last One past the last index.
/// @param grain Smallest number of indices per range, at least 1.
/// @param fn Callable taking an `Index`.
/// @throws std::invalid_argument If first > last or grain is 0, with a scheduler or without.
template<typename Index, typename Fn>
void parallel_for(task_scheduler *scheduler, Index first, Index last, std::size_t grain, Fn &&fn) {
    if (scheduler) {
        parallel_for(*scheduler, first, last, grain, std::forward<Fn>(fn));
    } else {
        detail::validate_parallel_for(first, last, grain);
        for (auto i = first; i < last; ++i)
            fn(i);
    }
}

} // namespace edyn

#endif // EDYN_PARALLEL_PARALLEL_FOR_HPP
