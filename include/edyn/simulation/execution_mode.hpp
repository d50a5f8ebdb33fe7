#ifndef EDYN_SIMULATION_EXECUTION_MODE_HPP
#define EDYN_SIMULATION_EXECUTION_MODE_HPP

#include <cstdint>

namespace edyn {

enum class execution_mode : std::uint8_t {
    // Everything runs inside update(), in the calling thread.
    sequential,
    // As sequential, with parts of the step spread over worker threads.
    sequential_multithreaded,
    // A worker thread owns the simulation; update() exchanges state with it.
    asynchronous
};

struct init_config {
    // The manual makes asynchronous the default; until that mode and the multithreaded one are
    // available, sequential is, and asking for another throws std::invalid_argument.
    edyn::execution_mode execution_mode{edyn::execution_mode::sequential};
};

} // namespace edyn

#endif // EDYN_SIMULATION_EXECUTION_MODE_HPP
