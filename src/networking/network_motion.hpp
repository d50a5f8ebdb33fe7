#ifndef EDYN_SRC_NETWORKING_NETWORK_MOTION_HPP
#define EDYN_SRC_NETWORKING_NETWORK_MOTION_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/serialization/quantize.hpp"

namespace edyn {

// A body's transform (of its centre of mass) and velocities, as snapshots carry them: positions
// in steps of position_quantum, velocities of velocity_quantum, the orientation in 48 bits
// (serialization/quantize.hpp).
struct network_motion {
    vector3 position{vector3_zero};
    quaternion orientation{quaternion_identity};
    vector3 linvel{vector3_zero};
    vector3 angvel{vector3_zero};
};

template<typename Archive>
void serialize(Archive &archive, network_motion &m) {
    serialize_quantized(archive, m.position, position_quantum);
    serialize_quantized(archive, m.orientation);
    serialize_quantized(archive, m.linvel, velocity_quantum);
    serialize_quantized(archive, m.angvel, velocity_quantum);
}

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_NETWORK_MOTION_HPP
