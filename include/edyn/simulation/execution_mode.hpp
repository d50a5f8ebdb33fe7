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
    /// sequential_multithreaded only: the fewest bodies a step must move for its phases to be
    /// spread over the worker threads (the bodies awake in the step before, or every dynamic
    /// body in the first step). A smaller world is stepped on the calling thread alone, where
    /// handing out work and waiting for it would cost more than it saves; either way a step
    /// gives the same result to the last bit. 0 spreads every step.
    unsigned min_parallel_bodies{default_min_parallel_bodies};
    /// min_parallel_bodies' default, measured with edyn-bench on a 2-core machine (the pile,
    /// the pyramid, the chain and the rag dolls, one thread against two): below it, two threads
    /// were slower than one in every scene.
    static constexpr unsigned default_min_parallel_bodies = 2048;
};

} // namespace edyn

#endif // EDYN_SIMULATION_EXECUTION_MODE_HPP
