#ifndef EDYN_SIMULATION_DISCONTINUITY_HPP
#define EDYN_SIMULATION_DISCONTINUITY_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"

namespace edyn {

/// Component: how far a body's shown transform lags behind a correction of its simulated one.
/// When a networked client replaces a body's state with the server's, the jump is kept here and
/// added to present_position / present_orientation, then decayed every step
/// (set_network_client_discontinuity_decay_rate), so that the body glides to its new place
/// instead of jumping. Written by the network client; the program only reads it, if at all.
struct discontinuity {
    /// Added to the interpolated present_position, world space, in metres; default zero.
    vector3 position_offset{vector3_zero};
    /// Applied on top of the interpolated present_orientation (`offset * present`), a unit
    /// quaternion (x y z w); default the identity.
    quaternion orientation_offset{quaternion_identity};
};

} // namespace edyn

#endif // EDYN_SIMULATION_DISCONTINUITY_HPP
