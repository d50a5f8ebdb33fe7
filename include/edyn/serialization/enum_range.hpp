#ifndef EDYN_SERIALIZATION_ENUM_RANGE_HPP
#define EDYN_SERIALIZATION_ENUM_RANGE_HPP

// The archives write and read enumerations as their raw underlying integers without looking at
// them, so `archive(e)` can produce a value no enumerator names. Serialize functions pass each
// enumeration member through serialize_enum instead, which fails the input archive on a value
// past the last enumerator: a switch over the enumeration never meets a value it does not
// handle.

#include <type_traits>

namespace edyn {

/// Writes or reads an enumeration as its underlying integer, checking the range when reading.
///
/// For enumerations whose enumerators run from 0 to `last` without gaps. Call it from a
/// serialize function instead of `archive(value)`, which does not check: an input archive fails
/// on a value past `last` (or below 0), so a switch over the enumeration never meets a value it
/// does not handle.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param value The value to write from or read into; left as it was when reading fails.
/// @param last The last enumerator.
template<typename Archive, typename Enum>
void serialize_enum(Archive &archive, Enum &value, Enum last) {
    static_assert(std::is_enum_v<Enum>);
    using underlying = std::underlying_type_t<Enum>;
    auto raw = static_cast<underlying>(value);
    archive(raw);
    if constexpr (Archive::is_input) {
        if (archive.failed()) return;
        bool in_range = raw <= static_cast<underlying>(last);
        if constexpr (std::is_signed_v<underlying>) in_range = in_range && raw >= 0;
        if (!in_range) {
            archive.fail();
            return;
        }
        value = static_cast<Enum>(raw);
    }
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_ENUM_RANGE_HPP
