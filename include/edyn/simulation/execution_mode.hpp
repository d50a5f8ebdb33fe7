#ifndef EDYN_SIMULATION_EXECUTION_MODE_HPP
#define EDYN_SIMULATION_EXECUTION_MODE_HPP

#include "edyn/parallel/task_scheduler.hpp"
#include <cstdint>
#include <optional>

namespace edyn {

/// Where and on which threads the simulation runs; chosen in init_config when a registry is
/// attached, and fixed from then on.
enum class execution_mode : std::uint8_t {
    /// Everything runs inside update(), in the calling thread.
    sequential,
    /// As sequential, with parts of the step spread over worker threads.
    sequential_multithreaded,
    /// A worker thread owns the simulation in a registry of its own; update() sends it the changes
    /// made to the main registry and applies the results it has finished, never waiting for it.
    asynchronous
};

/// Options of attach (directly, or as the default set by init).
struct init_config {
    /// How the simulation runs; asynchronous by default: a simulation worker thread steps the
    /// world while the calling thread goes on (see update() in world.hpp).
    edyn::execution_mode execution_mode{edyn::execution_mode::asynchronous};
    /// sequential_multithreaded only: threads that run the step's parallel phases, the calling
    /// thread included; 0 (the default) means one per hardware thread, and more than
    /// max_worker_threads is refused. Threads are made once, in attach.
    unsigned num_worker_threads{0};
    /// The most num_worker_threads accepts: 256.
    static constexpr unsigned max_worker_threads = 256;
    /// sequential_multithreaded only: the program's own scheduler, instead of edyn's oneTBB
    /// arena (num_worker_threads is then ignored), for the step's parallel phases and for the
    /// background work (page loads of paged meshes, one task of one item each: see
    /// background_tasks). Empty by default. Its `enqueue` and `wait` hooks must be set and its
    /// `concurrency` must not be 0.
    std::optional<task_hooks> scheduler{};
};

} // namespace edyn

#endif // EDYN_SIMULATION_EXECUTION_MODE_HPP
