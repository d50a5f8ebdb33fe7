// The memory archives (memory_archive.hpp) with the standard and math types (std_types.hpp,
// math_types.hpp): round trips, sizes, and input that comes from anyone — truncated, oversized,
// out of range or random — which must fail cleanly and never read past the buffer.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <edyn/networking/packet/edyn_packet.hpp>
#include <edyn/serialization/math_types.hpp>
#include <edyn/serialization/memory_archive.hpp>
#include <edyn/serialization/std_types.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

using namespace edyn;

namespace test_types {

enum class color : std::uint8_t { red = 1, green = 2, blue = 200 };
enum class wide : std::int64_t { low = std::numeric_limits<std::int64_t>::min(), high = 1 };
enum plain_enum : std::int16_t { plain_a = -300, plain_b = 300 };

struct empty {};

struct user_struct {
    int count{};
    std::string name;
    vector3 position{};
    std::vector<entity> targets;
    std::optional<color> tint;
};

// Found by argument-dependent lookup, as a program's own components are.
template<typename Archive>
void serialize(Archive &archive, user_struct &s) {
    archive(s.count, s.name, s.position, s.targets, s.tint);
}

bool operator==(const user_struct &a, const user_struct &b) {
    return a.count == b.count && a.name == b.name && a.position == b.position && a.targets == b.targets &&
           a.tint == b.tint;
}

} // namespace test_types

using namespace test_types;

namespace {

template<typename... Ts>
std::vector<std::uint8_t> encode(const Ts &...values) {
    std::vector<std::uint8_t> data;
    memory_output_archive archive(data);
    archive(values...);
    return data;
}

// Decodes from a heap block of exactly the given bytes, so that AddressSanitizer reports any
// read past the end.
template<typename T>
bool decode(const std::uint8_t *bytes, std::size_t size, T &value, std::size_t *left = nullptr) {
    // Exactly `size` bytes are allocated, so that AddressSanitizer sees a read past them (none for
    // an empty input, which may come as a null pointer).
    std::vector<std::uint8_t> block;
    if (size > 0) block.assign(bytes, bytes + size);
    memory_input_archive archive(block.data(), block.size());
    archive(value);
    EXPECT_LE(archive.position(), size);
    if (left) *left = archive.remaining();
    return !archive.failed();
}

template<typename T>
bool decode(const std::vector<std::uint8_t> &data, T &value, std::size_t *left = nullptr) {
    return decode(data.data(), data.size(), value, left);
}

// Encodes, decodes into a default value, and checks that every byte was consumed.
template<typename T>
T decoded_copy(const T &value) {
    auto data = encode(value);
    T result{};
    std::size_t left = 0;
    EXPECT_TRUE(decode(data, result, &left)) << "decoding " << data.size() << " bytes failed";
    EXPECT_EQ(left, 0u) << "bytes left unread";
    return result;
}

template<typename T>
bool same_bits(const T &a, const T &b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template<typename T>
class archive_arithmetic : public ::testing::Test {};

using arithmetic_types =
    ::testing::Types<char, signed char, unsigned char, char8_t, char16_t, char32_t, wchar_t, short,
                     unsigned short, int, unsigned, long, unsigned long, long long, unsigned long long,
                     std::int8_t, std::uint16_t, std::int32_t, std::uint64_t, float, double, long double>;
TYPED_TEST_SUITE(archive_arithmetic, arithmetic_types);

TYPED_TEST(archive_arithmetic, round_trip_extremes_with_own_width) {
    using T = TypeParam;
    using limits = std::numeric_limits<T>;
    for (T value : {limits::lowest(), limits::max(), limits::min(), T(0), T(1), T(limits::max() / 3)}) {
        auto data = encode(value);
        EXPECT_EQ(data.size(), sizeof(T));
        auto result = decoded_copy(value);
        EXPECT_EQ(result, value);
    }
}

TEST(archive, integers_are_little_endian) {
    EXPECT_EQ(encode(std::uint32_t{0x04030201}), (std::vector<std::uint8_t>{1, 2, 3, 4}));
    EXPECT_EQ(encode(std::int16_t{-2}), (std::vector<std::uint8_t>{0xfe, 0xff}));
}

TEST(archive, floats_keep_their_bits) {
    for (double value :
         {-0.0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::quiet_NaN()}) {
        auto result = decoded_copy(value);
        EXPECT_TRUE(same_bits(result, value)) << "sent " << value << ", received " << result;
    }
    auto nan = std::bit_cast<float>(std::uint32_t{0x7fc12345});
    EXPECT_TRUE(same_bits(decoded_copy(nan), nan));
}

TEST(archive, bool_takes_one_byte) {
    EXPECT_EQ(encode(true), (std::vector<std::uint8_t>{1}));
    EXPECT_EQ(encode(false), (std::vector<std::uint8_t>{0}));
    EXPECT_TRUE(decoded_copy(true));
    EXPECT_FALSE(decoded_copy(false));
}

TEST(archive, enums_and_entities) {
    EXPECT_EQ(decoded_copy(color::blue), color::blue);
    EXPECT_EQ(encode(color::blue).size(), 1u);
    EXPECT_EQ(decoded_copy(wide::low), wide::low);
    EXPECT_EQ(decoded_copy(plain_a), plain_a);
    EXPECT_EQ(decoded_copy(plain_b), plain_b);

    auto e = make_entity(123456, 789);
    EXPECT_EQ(decoded_copy(e), e);
    // Entities are varints: an early entity of version 0 takes a byte or two.
    EXPECT_EQ(encode(e).size(), 5u);
    EXPECT_EQ(encode(make_entity(100, 0)).size(), 1u);
    EXPECT_EQ(encode(make_entity(10000, 0)).size(), 2u);
    EXPECT_TRUE(decoded_copy(entity(null)) == null);
    // A varint past 32 bits is not an entity.
    auto bytes = std::vector<std::uint8_t>{0xff, 0xff, 0xff, 0xff, 0x7f};
    auto archive = memory_input_archive(bytes.data(), bytes.size());
    auto decoded = make_entity(5, 0);
    archive(decoded);
    EXPECT_TRUE(archive.failed());
    EXPECT_EQ(decoded, make_entity(5, 0));
}

TEST(archive, math_types) {
    auto v = vector3{scalar(1.5), scalar(-2.25), scalar(1e-7)};
    EXPECT_EQ(decoded_copy(v), v);
    EXPECT_EQ(encode(v).size(), 3 * sizeof(scalar));

    auto q = quaternion{scalar(0.1), scalar(-0.2), scalar(0.3), scalar(0.9)};
    EXPECT_EQ(decoded_copy(q), q);
    EXPECT_EQ(encode(q).size(), 4 * sizeof(scalar));

    auto m = matrix3x3{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            m.row[i][j] = scalar(i * 3 + j) - scalar(4.5);
    }
    auto result = decoded_copy(m);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(result.row[i], m.row[i]) << "row " << i;
    EXPECT_EQ(encode(m).size(), 9 * sizeof(scalar));
}

TEST(archive, containers) {
    EXPECT_EQ(decoded_copy(std::vector<int>{1, -2, 3}), (std::vector<int>{1, -2, 3}));
    EXPECT_EQ(decoded_copy(std::vector<int>{}), std::vector<int>{});
    // The byte vector is copied in bulk; 300 elements need a two-byte count.
    std::vector<std::uint8_t> bytes(300);
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = std::uint8_t(i * 7);
    EXPECT_EQ(decoded_copy(bytes), bytes);
    EXPECT_EQ(encode(bytes).size(), 302u);

    auto text = std::string("with\0nul and ü", 15);
    EXPECT_EQ(decoded_copy(text), text);
    EXPECT_EQ(encode(text).size(), 16u);
    EXPECT_EQ(decoded_copy(std::vector<std::string>{"a", "", "ccc"}),
              (std::vector<std::string>{"a", "", "ccc"}));

    auto array = std::array<double, 3>{1.5, -2.5, 1e300};
    EXPECT_EQ(decoded_copy(array), array);
    EXPECT_EQ(encode(array).size(), 24u);

    auto pair = std::pair<int, std::string>{-7, "seven"};
    EXPECT_EQ(decoded_copy(pair), pair);

    auto tuple = std::tuple<std::int8_t, double, std::vector<std::uint16_t>>{-8, 0.5, {1, 65535}};
    EXPECT_EQ(decoded_copy(tuple), tuple);

    EXPECT_EQ(decoded_copy(std::optional<int>{42}), std::optional<int>{42});
    EXPECT_EQ(decoded_copy(std::optional<int>{}), std::optional<int>{});
    EXPECT_EQ(encode(std::optional<int>{}).size(), 1u);

    using var = std::variant<int, std::string, vector3>;
    for (auto value : {var{5}, var{std::string("five")}, var{vector3{1, 2, 3}}}) {
        auto result = decoded_copy(value);
        EXPECT_EQ(result, value) << "alternative " << value.index();
    }
    EXPECT_EQ(encode(var{5}).size(), 5u);

    auto map = std::map<std::string, std::vector<int>>{{"a", {1}}, {"b", {}}, {"c", {2, 3}}};
    EXPECT_EQ(decoded_copy(map), map);
}

TEST(archive, nested) {
    using inner = std::variant<std::string, std::pair<int, int>>;
    using nested = std::vector<std::map<int, std::optional<inner>>>;
    auto value = nested{{{1, inner{"x"}}, {2, std::nullopt}}, {}, {{-3, inner{std::pair{4, 5}}}}};
    EXPECT_EQ(decoded_copy(value), value);

    auto deep = std::vector<std::vector<std::tuple<entity, std::array<vector3, 2>>>>{
        {{make_entity(1, 1), {vector3{1, 2, 3}, vector3{4, 5, 6}}}}, {}};
    EXPECT_EQ(decoded_copy(deep), deep);
}

TEST(archive, user_struct_with_free_serialize) {
    auto value = user_struct{7, "crate", {1, 2, 3}, {make_entity(1, 0), make_entity(2, 3)}, color::green};
    EXPECT_EQ(decoded_copy(value), value);
    // int, name (1 + 5), vector3, count + two entities (varints of 1 and 4 bytes), optional
    // flag + enum.
    EXPECT_EQ(encode(value).size(), 4 + 6 + 3 * sizeof(scalar) + 1 + 1 + 4 + 2);
}

TEST(archive, empty_types_take_no_bytes) {
    EXPECT_EQ(encode(empty{}, empty{}).size(), 0u);
    empty e;
    EXPECT_TRUE(decode(nullptr, 0, e));
    // A count of empty elements is not limited by the bytes left, which they do not use.
    auto many = std::vector<empty>(1000);
    EXPECT_EQ(encode(many).size(), 2u);
    EXPECT_EQ(decoded_copy(many).size(), 1000u);
}

TEST(archive, varint_encoding) {
    EXPECT_EQ(encode(std::vector<std::uint8_t>(127)).size(), 128u);
    EXPECT_EQ(encode(std::vector<std::uint8_t>(128)).size(), 130u);

    std::vector<std::uint8_t> data;
    memory_output_archive output(data);
    output.write_varint(std::numeric_limits<std::uint64_t>::max());
    output.write_varint(0);
    EXPECT_EQ(data.size(), 11u);
    memory_input_archive input(data.data(), data.size());
    EXPECT_EQ(input.read_varint(std::numeric_limits<std::uint64_t>::max()),
              std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(input.read_varint(0), 0u);
    EXPECT_FALSE(input.failed());
}

TEST(archive, varint_longer_than_ten_bytes_fails) {
    // Ten continuation bytes: the eleventh would be needed.
    std::vector<std::uint8_t> data(10, 0x80);
    data.push_back(0);
    memory_input_archive input(data.data(), data.size());
    EXPECT_EQ(input.read_varint(std::numeric_limits<std::uint64_t>::max()), 0u);
    EXPECT_TRUE(input.failed());

    // A tenth byte with bits beyond the 64th.
    std::vector<std::uint8_t> overflow(9, 0xff);
    overflow.push_back(0x02);
    memory_input_archive overflowing(overflow.data(), overflow.size());
    overflowing.read_varint(std::numeric_limits<std::uint64_t>::max());
    EXPECT_TRUE(overflowing.failed());
}

TEST(archive, read_size_is_capped) {
    std::vector<std::uint8_t> data;
    memory_output_archive output(data);
    output.write_size(max_archive_count + 1);
    output.write_size(10);
    memory_input_archive input(data.data(), data.size());
    EXPECT_EQ(input.read_size(std::numeric_limits<std::size_t>::max()), 0u);
    EXPECT_TRUE(input.failed());

    memory_input_archive second(data.data() + data.size() - 1, 1);
    EXPECT_EQ(second.read_size(9), 0u);
    EXPECT_TRUE(second.failed()) << "10 read with a maximum of 9";

    auto many = encode(std::vector<empty>(max_archive_count + 1));
    std::vector<empty> result;
    EXPECT_FALSE(decode(many, result));
}

TEST(archive, bool_byte_above_one_fails) {
    for (std::uint8_t byte : {std::uint8_t{2}, std::uint8_t{0x80}, std::uint8_t{0xff}}) {
        bool value = true;
        EXPECT_FALSE(decode(&byte, 1, value)) << "byte " << int(byte);
        EXPECT_TRUE(value) << "a failed read changed the value";
    }
}

TEST(archive, variant_index_out_of_range_fails) {
    using var = std::variant<int, float>;
    for (std::uint8_t index : {std::uint8_t{2}, std::uint8_t{255}}) {
        std::vector<std::uint8_t> data{index, 0, 0, 0, 0};
        auto value = var{123};
        EXPECT_FALSE(decode(data, value)) << "index " << int(index);
        EXPECT_EQ(value, var{123});
    }
}

TEST(archive, counts_beyond_the_bytes_left_fail_without_allocating) {
    auto claim = [](std::uint64_t count) {
        std::vector<std::uint8_t> data;
        memory_output_archive output(data);
        output.write_size(count);
        // Three uint64s' worth of bytes, far fewer than the counts claim.
        data.insert(data.end(), 24, 0xab);
        return data;
    };
    for (std::uint64_t count : {std::uint64_t{1} << 40, std::uint64_t{1} << 19, std::uint64_t{25}}) {
        auto data = claim(count);
        // Fails at the count, before reserving anything: the values are as they were.
        auto values = std::vector<std::uint64_t>{1, 2};
        EXPECT_FALSE(decode(data, values)) << "count " << count;
        EXPECT_EQ(values, (std::vector<std::uint64_t>{1, 2})) << "count " << count;

        auto bytes = std::vector<std::uint8_t>{9};
        EXPECT_FALSE(decode(data, bytes)) << "count " << count;
        EXPECT_EQ(bytes, std::vector<std::uint8_t>{9});

        auto text = std::string("kept");
        EXPECT_FALSE(decode(data, text)) << "count " << count;
        EXPECT_EQ(text, "kept");

        auto map = std::map<std::uint8_t, std::uint8_t>{{1, 2}};
        EXPECT_FALSE(decode(data, map)) << "count " << count;
        EXPECT_EQ(map, (std::map<std::uint8_t, std::uint8_t>{{1, 2}}));
    }

    // Four elements fit the count check (one byte each at least) but not the bytes: the read
    // fails at the fourth, having reserved four.
    auto values = std::vector<std::uint64_t>{};
    EXPECT_FALSE(decode(claim(4), values));
    EXPECT_LE(values.capacity(), 4u);
}

TEST(archive, every_truncation_fails_inside_the_buffer) {
    using nested =
        std::tuple<user_struct, std::map<int, std::string>, std::variant<double, std::vector<vector3>>,
                   std::optional<std::array<std::uint16_t, 3>>>;
    auto value = nested{user_struct{-1, "name", {4, 5, 6}, {make_entity(9, 9)}, color::red},
                        {{1, "one"}, {300, "three hundred"}},
                        std::vector<vector3>{{1, 2, 3}, {4, 5, 6}},
                        std::array<std::uint16_t, 3>{1, 2, 3}};
    auto data = encode(value);
    for (std::size_t size = 0; size < data.size(); ++size) {
        nested result;
        EXPECT_FALSE(decode(data.data(), size, result))
            << "prefix of " << size << " of " << data.size() << " bytes";
    }
    nested result;
    EXPECT_TRUE(decode(data, result));
    EXPECT_EQ(result, value);
}

TEST(archive, a_failed_archive_leaves_values_untouched) {
    std::uint8_t byte = 7; // an invalid bool
    memory_input_archive input(&byte, 1);
    bool flag = false;
    input(flag);
    ASSERT_TRUE(input.failed());

    int number = 5;
    auto text = std::string("text");
    auto values = std::vector<int>{1, 2};
    auto maybe = std::optional<int>{3};
    auto alternative = std::variant<int, std::string>{"v"};
    auto map = std::map<int, int>{{1, 1}};
    auto v = vector3{1, 2, 3};
    auto user = user_struct{1, "u", {}, {}, std::nullopt};
    input(number, text, values, maybe, alternative, map, v, user);
    EXPECT_TRUE(input.failed());
    EXPECT_EQ(number, 5);
    EXPECT_EQ(text, "text");
    EXPECT_EQ(values, (std::vector<int>{1, 2}));
    EXPECT_EQ(maybe, std::optional<int>{3});
    EXPECT_EQ(alternative, (std::variant<int, std::string>{"v"}));
    EXPECT_EQ(map, (std::map<int, int>{{1, 1}}));
    EXPECT_EQ(v, (vector3{1, 2, 3}));
    EXPECT_EQ(user, (user_struct{1, "u", {}, {}, std::nullopt}));
    EXPECT_FALSE(input.read_bytes(&byte, 0)) << "reads after failure must report it";
    EXPECT_EQ(input.read_size(), 0u);
}

TEST(archive, null_buffer_is_empty) {
    memory_input_archive input(nullptr, 100);
    EXPECT_EQ(input.remaining(), 0u);
    int value = 1;
    input(value);
    EXPECT_TRUE(input.failed());
    EXPECT_EQ(value, 1);
}

// Random bytes as a packet: mostly rejected, never a crash, an over-read (under ASan) or an
// undefined operation (under UBSan); what does decode re-encodes to the same packet.
TEST(archive, random_bytes_as_packets) {
    constexpr auto kinds = std::variant_size_v<packet::edyn_packet_variant>;
    std::mt19937 rng(20240611);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<std::size_t> length(0, 96);
    std::uniform_int_distribution<int> kind(0, int(kinds) + 1);
    std::size_t decoded = 0;
    std::vector<std::uint8_t> data;

    for (int i = 0; i < 100000; ++i) {
        data.resize(length(rng));
        for (auto &b : data)
            b = std::uint8_t(byte(rng));
        // Half start with a valid kind, or just past the last one, to reach the decoders.
        if (!data.empty() && (i & 1)) data[0] = std::uint8_t(kind(rng));
        // Small counts make it past the count checks more often.
        if (data.size() > 9 && (i & 2)) data[9] &= 0x07;

        packet::edyn_packet packet;
        if (!decode(data, packet)) continue;
        ++decoded;
        auto first = encode(packet);
        packet::edyn_packet again;
        ASSERT_TRUE(decode(first, again)) << "re-decoding failed at iteration " << i;
        ASSERT_EQ(encode(again), first) << "re-encoding differs at iteration " << i;
    }
    std::printf("random packets: %zu of 100000 decoded\n", decoded);
    EXPECT_GT(decoded, 1000u);
}

} // namespace
