#ifndef EDYN_DYNAMICS_WORKER_CALLS_HPP
#define EDYN_DYNAMICS_WORKER_CALLS_HPP

#include "edyn/ecs/registry.hpp"
#include <functional>

namespace edyn {

// In execution_mode::asynchronous the main registry's context holds one of these. A function
// that reads a body's motion to change it (an impulse adds to the velocity, a new centre of
// mass shifts the position) cannot send its result to the simulation worker: the main
// registry's motion is a step or two old, and the worker would be set back to it. Such a
// function runs on the main registry with nothing sent (`muted`), so the main side sees the
// change at once, and hands itself to `forward`, which runs it again in the worker on the
// worker's entity at the start of its next step.
struct worker_calls {
    using call_type = std::function<void(registry &worker, entity worker_entity)>;
    std::function<void(entity, call_type)> forward;
    // While non-zero, changes to the main registry are not sent to the worker.
    int muted{0};
};

// Runs `local(registry, e)` and, in asynchronous mode, sends `local` to run in the worker as
// well (see worker_calls). In the other modes it only runs `local`.
template<typename Fn>
void call_here_and_in_worker(registry &registry, entity e, Fn local) {
    auto *calls = registry.ctx().find<worker_calls>();
    if (!calls) {
        local(registry, e);
        return;
    }
    ++calls->muted;
    try {
        local(registry, e);
    } catch (...) {
        --calls->muted;
        throw;
    }
    --calls->muted;
    calls->forward(e, local);
}

} // namespace edyn

#endif // EDYN_DYNAMICS_WORKER_CALLS_HPP
