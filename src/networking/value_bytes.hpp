#ifndef EDYN_SRC_NETWORKING_VALUE_BYTES_HPP
#define EDYN_SRC_NETWORKING_VALUE_BYTES_HPP

#include "edyn/serialization/memory_archive.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

// The bytes a value is sent as, to compare values of types without operator== (shapes,
// constraints): two values with the same bytes arrive as the same value.
template<typename T>
std::vector<std::uint8_t> value_bytes(const T &value) {
    auto bytes = std::vector<std::uint8_t>{};
    auto archive = memory_output_archive(bytes);
    archive(value);
    return bytes;
}

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_VALUE_BYTES_HPP
