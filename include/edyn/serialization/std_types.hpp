#ifndef EDYN_SERIALIZATION_STD_TYPES_HPP
#define EDYN_SERIALIZATION_STD_TYPES_HPP

// Serialization of the standard containers and vocabulary types, for any archive of
// memory_archive.hpp. Counts are written with write_size; when reading, a count is capped by
// the bytes left (every element takes at least one byte, empty types excepted) so that a short
// packet claiming a billion elements fails before allocating anything.

#include "edyn/serialization/memory_archive.hpp"
#include <array>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

namespace edyn {

namespace detail {
// A count of T read from the archive, checked against the bytes left after the count itself.
template<typename T>
std::size_t read_count(memory_input_archive &archive) noexcept {
    auto count = archive.read_size();
    if (!std::is_empty_v<T> && count > archive.remaining()) {
        archive.fail();
        return 0;
    }
    return count;
}
} // namespace detail

/// Writes or reads a vector: its size, then each element (a vector of bytes as one block).
/// Reading replaces the contents; a size larger than the bytes left fails the archive before
/// anything is allocated.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param values The vector to write from or read into.
template<typename Archive, typename T, typename Allocator>
void serialize(Archive &archive, std::vector<T, Allocator> &values) {
    if constexpr (Archive::is_output) {
        archive.write_size(values.size());
        if constexpr (std::is_same_v<T, std::uint8_t>) {
            archive.write_bytes(values.data(), values.size());
        } else {
            for (auto &v : values)
                archive(v);
        }
    } else {
        auto size = detail::read_count<T>(archive);
        if (archive.failed()) return;
        if constexpr (std::is_same_v<T, std::uint8_t>) {
            values.resize(size);
            archive.read_bytes(values.data(), size);
        } else {
            values.clear();
            values.reserve(size);
            for (std::size_t i = 0; i < size && !archive.failed(); ++i)
                archive(values.emplace_back());
        }
    }
}

/// Writes or reads a string: its length, then its bytes. A length larger than the bytes left
/// fails the archive.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The string to write from or read into.
template<typename Archive>
void serialize(Archive &archive, std::string &value) {
    if constexpr (Archive::is_output) {
        archive.write_size(value.size());
        archive.write_bytes(value.data(), value.size());
    } else {
        auto size = detail::read_count<char>(archive);
        if (archive.failed()) return;
        value.resize(size);
        archive.read_bytes(value.data(), size);
    }
}

/// Writes or reads a fixed-size array: each element, without a count.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param values The array to write from or read into.
template<typename Archive, typename T, std::size_t N>
void serialize(Archive &archive, std::array<T, N> &values) {
    for (auto &v : values)
        archive(v);
}

/// Writes or reads a pair: first, then second.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The pair to write from or read into.
template<typename Archive, typename A, typename B>
void serialize(Archive &archive, std::pair<A, B> &value) {
    archive(value.first, value.second);
}

/// Writes or reads a tuple: each element in order.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The tuple to write from or read into.
template<typename Archive, typename... Ts>
void serialize(Archive &archive, std::tuple<Ts...> &value) {
    std::apply([&](auto &...elements) { archive(elements...); }, value);
}

/// Writes or reads an optional: whether it has a value, then the value if so.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The optional to write from or read into.
template<typename Archive, typename T>
void serialize(Archive &archive, std::optional<T> &value) {
    bool has_value = value.has_value();
    archive(has_value);
    if constexpr (Archive::is_output) {
        if (has_value) archive(*value);
    } else {
        if (archive.failed()) return;
        if (has_value) {
            archive(value.emplace());
        } else {
            value.reset();
        }
    }
}

/// Writes or reads a variant: the index of its alternative (one byte), then the alternative. An
/// index past the last alternative fails the archive.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The variant to write from or read into.
template<typename Archive, typename... Ts>
void serialize(Archive &archive, std::variant<Ts...> &value) {
    static_assert(sizeof...(Ts) < 256);
    auto index = static_cast<std::uint8_t>(value.index());
    archive(index);
    if constexpr (Archive::is_output) {
        std::visit([&](auto &alternative) { archive(alternative); }, value);
    } else {
        if (archive.failed()) return;
        if (index >= sizeof...(Ts)) {
            archive.fail();
            return;
        }
        // Constructs the alternative `index` names, then reads it.
        [&]<std::size_t... Is>(std::index_sequence<Is...>) {
            ((Is == index ? (archive(value.template emplace<Is>()), 0) : 0), ...);
        }
        (std::index_sequence_for<Ts...>{});
    }
}

/// Writes or reads a map: its size, then each key and value in key order. Reading replaces the
/// contents; a repeated key keeps the last value read.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param values The map to write from or read into.
template<typename Archive, typename Key, typename T, typename Compare, typename Allocator>
void serialize(Archive &archive, std::map<Key, T, Compare, Allocator> &values) {
    if constexpr (Archive::is_output) {
        archive.write_size(values.size());
        for (auto &[key, v] : values)
            archive(key, v);
    } else {
        auto size = detail::read_count<std::pair<Key, T>>(archive);
        if (archive.failed()) return;
        values.clear();
        for (std::size_t i = 0; i < size && !archive.failed(); ++i) {
            Key key{};
            T v{};
            archive(key, v);
            if (!archive.failed()) values.insert_or_assign(std::move(key), std::move(v));
        }
    }
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_STD_TYPES_HPP
