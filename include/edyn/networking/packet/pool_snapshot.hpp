#ifndef EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP
#define EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP

#include "edyn/serialization/std_types.hpp"
#include <cstdint>
#include <vector>

namespace edyn::packet {

// The values of one networked component type in a packet. `component_index` is the type's
// position in the list both ends registered (networking/networked_components.hpp); `data` holds,
// per entity, its position in the packet's entity list and the value, encoded by that type's
// serializer. The packet layer keeps it as bytes: it is decoded, and checked, only by a
// registry that knows the type, so decoding a packet never depends on registry state.
struct pool_snapshot {
    std::uint16_t component_index{};
    std::vector<std::uint8_t> data;
};

template<typename Archive>
void serialize(Archive &archive, pool_snapshot &pool) {
    archive(pool.component_index, pool.data);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP
