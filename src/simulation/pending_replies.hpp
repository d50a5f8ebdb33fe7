#ifndef EDYN_SRC_SIMULATION_PENDING_REPLIES_HPP
#define EDYN_SRC_SIMULATION_PENDING_REPLIES_HPP

#include "edyn/ecs/registry.hpp"
#include <cstdint>
#include <functional>
#include <vector>

namespace edyn {

// Query replies waiting for the next update() in the modes without a worker, and the id
// counter of asynchronous queries, in the registry's context.
struct pending_replies {
    std::uint32_t next_id{0};
    std::vector<std::function<void()>> replies;
};

// Hands the waiting replies to their delegates (sequential modes, from update()).
void run_pending_replies(registry &registry);

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_PENDING_REPLIES_HPP
