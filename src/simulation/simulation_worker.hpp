#ifndef EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP
#define EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP

#include "async_protocol.hpp"
#include "edyn/ecs/registry.hpp"
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace edyn {

// The worker's side: its registry (attached in sequential mode), the map from main entities to
// its own, and the message being filled. Only the worker thread touches it once it runs.
struct worker_context {
    registry reg;
    entity_map to_worker;      // main entity -> worker entity
    std::vector<entity> slept; // worker entities that fell asleep in this message
    worker_message message;
    std::vector<worker_message> ready; // finished messages, not yet handed over
    std::uint64_t ops_applied{0};

    worker_context();
    worker_context(const worker_context &) = delete;
    worker_context &operator=(const worker_context &) = delete;

    // The worker entity for main entity `main`, made (and tagged with remote_entity) if there
    // is none yet.
    entity local(entity main);
    // The worker entity for `main`, or null.
    entity find(entity main) const noexcept;
    // The main entity a worker entity stands for, or null.
    entity main_of(entity worker) const noexcept;

    // Runs the steps due at the caller's `time`, one message each, and records where the
    // present lies between the last two.
    void advance(double time);
    // Runs one step now, paused or not.
    void step_once();
    // Hands the message being filled over, if it holds anything.
    void finish_message();

private:
    void step();
    void snapshot();
};

// The thread of execution_mode::asynchronous. The main thread sends batches of operations and
// takes messages back; neither ever waits for the other, except in wait().
class simulation_worker {
public:
    simulation_worker();
    // Stops the thread (dropping operations not yet applied) and joins it.
    ~simulation_worker();
    simulation_worker(const simulation_worker &) = delete;
    simulation_worker &operator=(const simulation_worker &) = delete;

    // Queues `ops` (emptying it) as one batch; returns the batch's number.
    std::uint64_t send(std::vector<worker_op> &ops);
    // The messages finished so far, oldest first.
    std::vector<worker_message> receive();
    // Blocks until batch `batch` has been applied and its messages are ready.
    void wait(std::uint64_t batch);

private:
    void run();

    std::mutex mutex;
    std::condition_variable work_arrived;
    std::condition_variable batch_done;
    std::vector<worker_op> inbox;
    std::vector<worker_message> outbox;
    std::uint64_t batches_sent{0};
    std::uint64_t batches_done{0};
    bool stopping{false};
    worker_context context;
    std::thread thread;
};

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP
