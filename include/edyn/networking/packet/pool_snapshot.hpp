#ifndef EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP
#define EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP

#include "edyn/serialization/std_types.hpp"
#include <cstdint>
#include <vector>

namespace edyn::packet {

/// The values of one networked component type in a packet.
///
/// The packet layer keeps them as bytes: they are decoded, and checked, only by a registry that
/// knows the type, so decoding a packet never depends on registry state.
struct pool_snapshot {
    /// The type's position in the list both ends registered
    /// (networking/networked_components.hpp).
    std::uint16_t component_index{};
    /// Per entity, its position in the packet's entity list and the value, encoded by that type's
    /// serializer.
    std::vector<std::uint8_t> data;
};

/// Writes or reads a pool_snapshot: the component index and the bytes, not decoded.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param pool The pool to write from or read into.
template<typename Archive>
void serialize(Archive &archive, pool_snapshot &pool) {
    archive(pool.component_index, pool.data);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_POOL_SNAPSHOT_HPP
