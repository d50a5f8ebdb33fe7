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

/// No count or size read from bytes may exceed this (2^20), whatever the buffer's length.
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

/// An archive that appends values to a byte vector.
///
/// Numbers are written little-endian with their own width, `bool` as one byte, entities and
/// counts as variable-length integers; other types through their `serialize` function, and empty
/// types not at all. It never fails. Both archives are used the same way, `archive(a, b, c)`, so
/// that one free function, found by argument-dependent lookup, describes a type for both
/// directions:
/// @code
/// template<typename Archive>
/// void serialize(Archive &archive, my_component &c) { archive(c.speed, c.target); }
/// @endcode
class memory_output_archive {
public:
    static constexpr bool is_input = false; ///< For `if constexpr` in serialize functions: false.
    static constexpr bool is_output = true; ///< For `if constexpr` in serialize functions: true.

    /// Makes an archive that writes to the end of `data`.
    /// @param data The vector the bytes are appended to; it must outlive the archive. Its
    /// contents are kept.
    explicit memory_output_archive(std::vector<std::uint8_t> &data) noexcept
        : m_data(&data) {}

    /// Writes the values, in order.
    /// @param values Numbers, enumerations, entities, or values of types with a `serialize`
    /// function.
    template<typename... Ts>
    void operator()(const Ts &...values) {
        (write(values), ...);
    }

    /// Whether writing failed: never, but serialize functions may ask either archive.
    /// @return Always false.
    bool failed() const noexcept { return false; }

    /// Appends raw bytes, as they are.
    /// @param bytes The first byte.
    /// @param size The number of bytes.
    void write_bytes(const void *bytes, std::size_t size) {
        auto *begin = static_cast<const std::uint8_t *>(bytes);
        m_data->insert(m_data->end(), begin, begin + size);
    }

    /// Writes a count or size as unsigned LEB128: 7 bits per byte, low first; small counts take
    /// one byte. Read it back with memory_input_archive::read_size.
    /// @param value The count.
    void write_size(std::uint64_t value) { write_varint(value); }

    /// Writes an integer that is not a count (a quantised coordinate) with the same encoding as
    /// write_size; read it back with memory_input_archive::read_varint, which is not capped by
    /// max_archive_count.
    /// @param value The integer.
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

/// An archive that reads values back from bytes written by memory_output_archive.
///
/// The bytes may come from anyone: every read is checked against the end of the buffer and every
/// count against what is left and against max_archive_count. The first bad read marks the
/// archive failed(); from then on it reads nothing and leaves the values it is given as they
/// were. It never throws. Check failed() after reading, and drop the value when it is set.
class memory_input_archive {
public:
    static constexpr bool is_input = true;   ///< For `if constexpr` in serialize functions: true.
    static constexpr bool is_output = false; ///< For `if constexpr` in serialize functions: false.

    /// Makes an archive that reads from a buffer, from its start.
    /// @param data The first byte; the buffer must outlive the archive. A null pointer reads as
    /// an empty buffer.
    /// @param size The number of bytes in the buffer.
    memory_input_archive(const std::uint8_t *data, std::size_t size) noexcept
        : m_data(data)
        , m_size(data ? size : 0) {}

    /// Reads the values, in order; after a failure, the values are left as they were.
    /// @param values Numbers, enumerations, entities, or values of types with a `serialize`
    /// function.
    template<typename... Ts>
    void operator()(Ts &...values) {
        (read(values), ...);
    }

    /// Whether a read has failed: the bytes ran out, a count was too large, or a value was out of
    /// its range.
    /// @return True once any read has failed.
    bool failed() const noexcept { return m_failed; }
    /// Marks the archive failed: for serialize functions that find a value out of its range.
    void fail() noexcept { m_failed = true; }
    /// The bytes not read yet.
    /// @return The number of bytes left.
    std::size_t remaining() const noexcept { return m_size - m_position; }
    /// How far reading has come.
    /// @return The number of bytes read so far.
    std::size_t position() const noexcept { return m_position; }

    /// Copies raw bytes out of the buffer.
    /// @param bytes Where to copy them; left as it was on failure.
    /// @param size The number of bytes.
    /// @return False, and the archive failed, when fewer than `size` bytes are left or the
    /// archive had failed already.
    bool read_bytes(void *bytes, std::size_t size) noexcept {
        if (m_failed || size > remaining()) {
            m_failed = true;
            return false;
        }
        if (size > 0) std::memcpy(bytes, m_data + m_position, size);
        m_position += size;
        return true;
    }

    /// Reads a count or size written by memory_output_archive::write_size.
    /// @param max The largest count accepted; capped at max_archive_count.
    /// @return The count; 0, and the archive failed, past `max` or max_archive_count, on an
    /// encoding longer than ten bytes, or when the bytes run out.
    std::size_t read_size(std::size_t max = max_archive_count) noexcept {
        return std::size_t(read_varint(max < max_archive_count ? max : max_archive_count));
    }

    /// Reads an integer written by memory_output_archive::write_varint.
    /// @param max The largest value accepted.
    /// @return The value; 0, and the archive failed, past `max`, on an encoding longer than ten
    /// bytes, on a tenth byte with bits beyond the 64th, or when the bytes run out.
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
