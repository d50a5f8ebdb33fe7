#ifndef EDYN_SERIALIZATION_MEMORY_ARCHIVE_HPP
#define EDYN_SERIALIZATION_MEMORY_ARCHIVE_HPP

// Archives that write values into a byte vector and read them back. Both are used the same way,
// `archive(a, b, c)`, so that one `serialize(Archive &, T &)` describes a type for both
// directions. Numbers are written little-endian with their own width; counts and sizes as
// variable-length integers (see write_size). A type of the program's is described by a free
// function found by argument-dependent lookup:
//
//   template<typename Archive>
//   void serialize(Archive &archive, my_component &c) { archive(c.speed, c.target); }
//
// Empty types need none. Entities are written as variable-length integers. The input archive reads bytes that
// may come from anyone: it checks every read against the end of the buffer and every count against what is
// left and against max_archive_count; the first bad read marks it failed(), and from then on it reads nothing
// and leaves the values it is given as they were. It never throws.

#include "edyn/ecs/entity.hpp"
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace edyn {

// No count or size read from bytes may exceed this, whatever the buffer's length.
inline constexpr std::size_t max_archive_count = std::size_t{1} << 20;

class memory_output_archive;
class memory_input_archive;

namespace detail {
template<typename T>
constexpr bool is_raw_value = std::is_arithmetic_v<T> || std::is_enum_v<T>;

template<typename T>
void to_little_endian(T &value) noexcept {
    if constexpr (std::endian::native == std::endian::big && sizeof(T) > 1) {
        auto *bytes = reinterpret_cast<unsigned char *>(&value);
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
            std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
}
} // namespace detail

class memory_output_archive {
public:
    static constexpr bool is_input = false;
    static constexpr bool is_output = true;

    explicit memory_output_archive(std::vector<std::uint8_t> &data) noexcept
        : m_data(&data) {}

    template<typename... Ts>
    void operator()(const Ts &...values) {
        (write(values), ...);
    }

    bool failed() const noexcept { return false; }

    void write_bytes(const void *bytes, std::size_t size) {
        auto *begin = static_cast<const std::uint8_t *>(bytes);
        m_data->insert(m_data->end(), begin, begin + size);
    }

    // Unsigned LEB128: 7 bits per byte, low first; small counts take one byte.
    void write_size(std::uint64_t value) { write_varint(value); }

    // The same encoding for integers that are not counts (quantised coordinates); read back
    // with read_varint, which is not capped by max_archive_count.
    void write_varint(std::uint64_t value) {
        while (value >= 0x80) {
            m_data->push_back(std::uint8_t(value | 0x80));
            value >>= 7;
        }
        m_data->push_back(std::uint8_t(value));
    }

private:
    template<typename T>
    void write(const T &value);

    std::vector<std::uint8_t> *m_data;
};

class memory_input_archive {
public:
    static constexpr bool is_input = true;
    static constexpr bool is_output = false;

    memory_input_archive(const std::uint8_t *data, std::size_t size) noexcept
        : m_data(data)
        , m_size(data ? size : 0) {}

    template<typename... Ts>
    void operator()(Ts &...values) {
        (read(values), ...);
    }

    bool failed() const noexcept { return m_failed; }
    // Marks the archive failed: for serialize functions that find a value out of its range.
    void fail() noexcept { m_failed = true; }
    std::size_t remaining() const noexcept { return m_size - m_position; }
    std::size_t position() const noexcept { return m_position; }

    bool read_bytes(void *bytes, std::size_t size) noexcept {
        if (m_failed || size > remaining()) {
            m_failed = true;
            return false;
        }
        if (size > 0) std::memcpy(bytes, m_data + m_position, size);
        m_position += size;
        return true;
    }

    // A count or size written by write_size. Fails, returning 0, past `max` or past
    // max_archive_count, or on an encoding longer than ten bytes.
    std::size_t read_size(std::size_t max = max_archive_count) noexcept {
        return std::size_t(read_varint(max < max_archive_count ? max : max_archive_count));
    }

    // An integer written by write_varint. Fails, returning 0, past `max`, on an encoding longer
    // than ten bytes, or on a tenth byte with bits beyond the 64th.
    std::uint64_t read_varint(std::uint64_t max) noexcept {
        std::uint64_t value = 0;
        for (unsigned shift = 0; shift < 64; shift += 7) {
            std::uint8_t byte;
            if (!read_bytes(&byte, 1)) return 0;
            // The tenth byte holds bit 63 only; more would be dropped by the shift.
            if (shift == 63 && (byte & 0x7e)) break;
            value |= std::uint64_t(byte & 0x7f) << shift;
            if (!(byte & 0x80)) {
                if (value > max) break;
                return value;
            }
        }
        m_failed = true;
        return 0;
    }

private:
    template<typename T>
    void read(T &value);

    const std::uint8_t *m_data;
    std::size_t m_size;
    std::size_t m_position{0};
    bool m_failed{false};
};

template<typename T>
void memory_output_archive::write(const T &value) {
    if constexpr (std::is_same_v<T, bool>) {
        m_data->push_back(value ? 1 : 0);
    } else if constexpr (std::is_same_v<T, entity>) {
        // Entities are small numbers (an index, a version above it, usually 0): a varint.
        write_varint(to_integral(value));
    } else if constexpr (detail::is_raw_value<T>) {
        auto copy = value;
        detail::to_little_endian(copy);
        write_bytes(&copy, sizeof(T));
    } else if constexpr (!std::is_empty_v<T>) {
        // Serialize functions take their value by reference for both directions; writing does
        // not modify it.
        serialize(*this, const_cast<T &>(value));
    }
}

template<typename T>
void memory_input_archive::read(T &value) {
    if (m_failed) return;
    if constexpr (std::is_same_v<T, bool>) {
        std::uint8_t byte;
        if (!read_bytes(&byte, 1)) return;
        if (byte > 1) {
            m_failed = true;
            return;
        }
        value = byte == 1;
    } else if constexpr (std::is_same_v<T, entity>) {
        auto integral = read_varint(~entity_traits::value_type{0});
        if (!m_failed) value = entity{entity_traits::value_type(integral)};
    } else if constexpr (detail::is_raw_value<T>) {
        T copy;
        if (!read_bytes(&copy, sizeof(T))) return;
        detail::to_little_endian(copy);
        value = copy;
    } else if constexpr (!std::is_empty_v<T>) {
        serialize(*this, value);
    }
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_MEMORY_ARCHIVE_HPP
