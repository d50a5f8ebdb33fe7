#ifndef EDYN_SIMULATION_DISCONTINUITY_HPP
#define EDYN_SIMULATION_DISCONTINUITY_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"

namespace edyn {

// How far a body's shown transform lags behind a correction of its simulated one: when a
// networked client replaces a body's state with the server's, the jump is kept here and added to
// present_position / present_orientation, then decayed every step
// (set_network_client_discontinuity_decay_rate), so that the body glides to its new place
// instead of jumping.
struct discontinuity {
    vector3 position_offset{vector3_zero};
    quaternion orientation_offset{quaternion_identity};
};

} // namespace edyn

#endif // EDYN_SIMULATION_DISCONTINUITY_HPP
