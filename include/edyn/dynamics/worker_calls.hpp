#ifndef EDYN_DYNAMICS_WORKER_CALLS_HPP
#define EDYN_DYNAMICS_WORKER_CALLS_HPP

#include "edyn/ecs/registry.hpp"
#include <functional>

namespace edyn {

/// Which of a body's motion a change made by the program sets, in asynchronous mode: until the
/// worker has run the change, the motion it sends back for that body leaves these parts of the
/// main registry as the program set them, and updates the others.
enum class motion_parts : unsigned {
    none = 0,      ///< Neither: the body's motion is taken from the worker as it comes.
    transform = 1, ///< `position` and `orientation`.
    velocity = 2,  ///< `linvel` and `angvel`.
    all = 3,       ///< Both.
};

/// Calls to run both on the main registry and in the simulation worker, in asynchronous mode.
/// In execution_mode::asynchronous the main registry's context holds one of these (set up by
/// attach). A function that reads a body's motion to change it (an impulse adds to the
/// velocity, a new centre of mass shifts the position) cannot send its result to the
/// simulation worker: the main registry's motion is a step or two old, and the worker would be
/// set back to it. Such a function runs on the main registry with nothing sent (`muted`), so
/// the main side sees the change at once, and hands itself to `forward`, which runs it again
/// in the worker on the worker's entity at the start of its next step. Use it through
/// call_here_and_in_worker.
struct worker_calls {
    /// A call to run in the worker, given the worker's registry and its copy of the entity.
    using call_type = std::function<void(registry &worker, entity worker_entity)>;
    /// Queues a call for the worker, for the given main-registry entity, with the parts of its
    /// motion the call sets.
    std::function<void(entity, call_type, motion_parts)> forward;
    /// While non-zero, changes to the main registry are not sent to the worker.
    int muted{0};
};

/// Runs `local(registry, e)` and, in asynchronous mode, sends `local` to run in the worker as
/// well (see worker_calls).
/// In the other modes it only runs `local`. In asynchronous mode the changes `local` makes to
/// the main registry are not replicated (the worker makes its own when it runs `local` at the
/// start of its next step); if `local` throws, the exception propagates and nothing is sent.
/// @tparam Fn A callable `void(registry &, entity)`, copied to the worker; it must cope with an
/// entity the worker no longer has as it had (check its components).
/// @param registry The main registry.
/// @param e The entity to act on, as the main registry knows it.
/// @param local The change to make.
/// @param sets The parts of the entity's motion `local` sets (an impulse sets its velocity, a
/// wake-up neither): the worker's motion for the entity, computed before the call reaches it,
/// does not overwrite those on the main side, and updates the rest.
template<typename Fn>
void call_here_and_in_worker(registry &registry, entity e, Fn local, motion_parts sets = motion_parts::all) {
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
    calls->forward(e, local, sets);
}

} // namespace edyn

#endif // EDYN_DYNAMICS_WORKER_CALLS_HPP
