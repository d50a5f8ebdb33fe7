#ifndef EDYN_TESTS_UNIT_SERIALIZATION_ARCHIVE_ROUND_TRIP_HPP
#define EDYN_TESTS_UNIT_SERIALIZATION_ARCHIVE_ROUND_TRIP_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

// Helpers shared by the shape, rigidbody_def and constraint serialization tests.
namespace edyn::test {

inline std::string describe(const vector3 &v) {
    std::ostringstream os;
    os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return os.str();
}

inline std::string describe(const quaternion &q) {
    std::ostringstream os;
    os << '(' << q.x << ", " << q.y << ", " << q.z << ", " << q.w << ')';
    return os.str();
}

// Bitwise equality is what a round trip promises, so no tolerance.
#define EDYN_EXPECT_SAME(actual, expected)                                                                   \
    EXPECT_TRUE((actual) == (expected)) << #actual " is " << ::edyn::test::describe(actual) << ", expected " \
                                        << ::edyn::test::describe(expected)

template<typename T>
std::vector<std::uint8_t> encode(const T &value) {
    std::vector<std::uint8_t> bytes;
    memory_output_archive archive(bytes);
    archive(value);
    return bytes;
}

// Decodes `bytes` into `value`; whether the archive failed. A decoder must never throw.
template<typename T>
bool decode_fails(const std::vector<std::uint8_t> &bytes, T &value) {
    memory_input_archive archive(bytes.data(), bytes.size());
    EXPECT_NO_THROW(archive(value));
    return archive.failed();
}

template<typename T>
bool decode_fails(const std::vector<std::uint8_t> &bytes) {
    T value{};
    return decode_fails(bytes, value);
}

// Decodes what `original` encodes to, expecting the whole encoding consumed, and checks that
// the copy encodes to the same bytes.
template<typename T>
T round_trip(const T &original) {
    auto bytes = encode(original);
    T copy{};
    memory_input_archive archive(bytes.data(), bytes.size());
    EXPECT_NO_THROW(archive(copy));
    EXPECT_FALSE(archive.failed()) << "decoding failed at byte " << archive.position() << " of "
                                   << bytes.size();
    EXPECT_EQ(archive.remaining(), 0u) << "bytes left unread out of " << bytes.size();
    auto again = encode(copy);
    EXPECT_EQ(again, bytes) << "the copy encodes differently: " << again.size() << " bytes against "
                            << bytes.size();
    return copy;
}

// Every proper prefix of the encoding of `original` must fail to decode.
template<typename T>
void expect_truncations_fail(const T &original) {
    auto bytes = encode(original);
    ASSERT_FALSE(bytes.empty());
    for (std::size_t size = 0; size < bytes.size(); ++size) {
        std::vector<std::uint8_t> prefix(bytes.begin(), bytes.begin() + std::ptrdiff_t(size));
        EXPECT_TRUE(decode_fails<T>(prefix))
            << "a prefix of " << size << " bytes out of " << bytes.size() << " decoded";
    }
}

// Offset of the first byte where the two objects differ, or -1 when none does.
template<typename T>
long first_byte_difference(const T &a, const T &b) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char ba[sizeof(T)], bb[sizeof(T)];
    std::memcpy(ba, &a, sizeof(T));
    std::memcpy(bb, &b, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        if (ba[i] != bb[i]) return long(i);
    }
    return -1;
}

} // namespace edyn::test

#endif // EDYN_TESTS_UNIT_SERIALIZATION_ARCHIVE_ROUND_TRIP_HPP
