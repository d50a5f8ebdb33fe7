#include "edyn/serialization/constraint_types.hpp"
#include "unit/serialization/archive_round_trip.hpp"
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

using namespace edyn;
using edyn::test::decode_fails;
using edyn::test::encode;
using edyn::test::expect_truncations_fail;
using edyn::test::first_byte_difference;
using edyn::test::round_trip;

namespace {
constexpr bool single = std::is_same_v<scalar, float>;
} // namespace

// The sizes seen when the serializers were written (float / double builds). A member added to a
// constraint changes them: serialize it in constraint_types.hpp, then update the size here.
static_assert(sizeof(point_constraint) == (single ? 60 : 112),
              "point_constraint changed: update its serializer");
static_assert(sizeof(distance_constraint) == (single ? 40 : 72),
              "distance_constraint changed: update its serializer");
static_assert(sizeof(soft_distance_constraint) == (single ? 48 : 88),
              "soft_distance_constraint changed: update its serializer");
static_assert(sizeof(hinge_constraint) == (single ? 188 : 368),
              "hinge_constraint changed: update its serializer");
static_assert(sizeof(cvjoint_constraint) == (single ? 200 : 392),
              "cvjoint_constraint changed: update its serializer");
static_assert(sizeof(cone_constraint) == (single ? 96 : 184),
              "cone_constraint changed: update its serializer");
static_assert(sizeof(generic_dof) == (single ? 28 : 56), "generic_dof changed: update its serializer");
static_assert(sizeof(generic_constraint) == (single ? 416 : 824),
              "generic_constraint changed: update its serializer");
static_assert(sizeof(gravity_constraint) == 8, "gravity_constraint changed: update its serializer");
static_assert(sizeof(null_constraint) == 8, "null_constraint changed: update its serializer");

namespace {

// A constraint whose every scalar-sized word holds a different value, none of them a default
// (0, 1, infinity, null): whatever member a serializer forgets keeps its default in the copy
// and shows up as a byte difference. Entities get arbitrary bits, which is all they are to the
// archive.
template<typename T>
T patterned() {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(scalar) == 0);
    unsigned char bytes[sizeof(T)];
    for (std::size_t i = 0; i < sizeof(T) / sizeof(scalar); ++i) {
        auto s = scalar(0.25) + scalar(i) * scalar(0.5);
        if (i % 2) s = -s;
        std::memcpy(bytes + i * sizeof(scalar), &s, sizeof(scalar));
    }
    T value{};
    std::memcpy(&value, bytes, sizeof(T));
    return value;
}

generic_constraint patterned_generic() {
    auto c = patterned<generic_constraint>();
    // The pattern's bytes are no dof_mode.
    dof_mode modes[] = {dof_mode::free, dof_mode::limited, dof_mode::locked};
    for (int i = 0; i < 3; ++i) {
        c.linear[i].mode = modes[i];
        c.angular[i].mode = modes[2 - i];
    }
    return c;
}

// For constraints without padding, where every byte is a member.
template<typename T>
void expect_bitwise_round_trip(const T &original) {
    auto copy = round_trip(original);
    EXPECT_EQ(first_byte_difference(copy, original), -1)
        << "offset of the first byte of the copy that differs, out of " << sizeof(T);
    EXPECT_EQ(copy.body[0], original.body[0]);
    EXPECT_EQ(copy.body[1], original.body[1]);
}

void expect_same_dof(const generic_dof &actual, const generic_dof &expected) {
    EXPECT_EQ(actual.mode, expected.mode);
    EXPECT_EQ(actual.min, expected.min);
    EXPECT_EQ(actual.max, expected.max);
    EXPECT_EQ(actual.stiffness, expected.stiffness);
    EXPECT_EQ(actual.rest, expected.rest);
    EXPECT_EQ(actual.damping, expected.damping);
    EXPECT_EQ(actual.friction, expected.friction);
}

// Offset of generic_constraint::linear[0] in its encoding.
// Where the degrees of freedom begin in `c`'s bytes (entities take as many bytes as their
// values need).
std::size_t generic_dofs_offset(generic_constraint c) {
    std::vector<std::uint8_t> bytes;
    memory_output_archive archive(bytes);
    archive(c.body[0], c.body[1], c.pivot[0], c.pivot[1], c.frame[0], c.frame[1]);
    return bytes.size();
}

} // namespace

TEST(constraint_serialization_test, point_round_trip) {
    auto original = patterned<point_constraint>();
    expect_bitwise_round_trip(original);
    EDYN_EXPECT_SAME(round_trip(original).friction_impulse, original.friction_impulse);
}

TEST(constraint_serialization_test, distance_round_trip) {
    auto original = patterned<distance_constraint>();
    expect_bitwise_round_trip(original);
    EXPECT_EQ(round_trip(original).distance, original.distance);
}

TEST(constraint_serialization_test, soft_distance_round_trip) {
    auto original = patterned<soft_distance_constraint>();
    expect_bitwise_round_trip(original);
    auto copy = round_trip(original);
    EXPECT_EQ(copy.stiffness, original.stiffness);
    EXPECT_EQ(copy.damping, original.damping);
    EXPECT_EQ(copy.impulse, original.impulse);
}

TEST(constraint_serialization_test, hinge_round_trip) {
    auto original = patterned<hinge_constraint>();
    expect_bitwise_round_trip(original);
    auto copy = round_trip(original);
    // The unwrapped angle and the warm-starting state travel with the definition.
    EXPECT_EQ(copy.angle, original.angle);
    EXPECT_EQ(copy.angle_min, original.angle_min);
    EXPECT_EQ(copy.bump_stop_impulse[1], original.bump_stop_impulse[1]);
    EXPECT_EQ(copy.spring_impulse, original.spring_impulse);
}

TEST(constraint_serialization_test, cvjoint_round_trip) {
    auto original = patterned<cvjoint_constraint>();
    expect_bitwise_round_trip(original);
    auto copy = round_trip(original);
    EXPECT_EQ(copy.twist_angle, original.twist_angle);
    EDYN_EXPECT_SAME(copy.bend_friction_impulse, original.bend_friction_impulse);
}

TEST(constraint_serialization_test, cone_round_trip) {
    auto original = patterned<cone_constraint>();
    expect_bitwise_round_trip(original);
    auto copy = round_trip(original);
    EXPECT_EQ(copy.span_angle[0], original.span_angle[0]);
    EXPECT_EQ(copy.span_angle[1], original.span_angle[1]);
    EXPECT_EQ(copy.bump_stop_impulse, original.bump_stop_impulse);
}

TEST(constraint_serialization_test, generic_round_trip) {
    auto original = patterned_generic();
    auto copy = round_trip(original);
    // generic_dof has padding after its mode, so compare member by member.
    EXPECT_EQ(first_byte_difference(copy.body, original.body), -1);
    EXPECT_EQ(first_byte_difference(copy.pivot, original.pivot), -1);
    EXPECT_EQ(first_byte_difference(copy.frame, original.frame), -1);
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        expect_same_dof(copy.linear[i], original.linear[i]);
        expect_same_dof(copy.angular[i], original.angular[i]);
    }
    EDYN_EXPECT_SAME(copy.linear_block_impulse, original.linear_block_impulse);
    EDYN_EXPECT_SAME(copy.angular_block_impulse, original.angular_block_impulse);
    EXPECT_EQ(first_byte_difference(copy.impulse, original.impulse), -1);
    EXPECT_EQ(first_byte_difference(copy.limit_impulse, original.limit_impulse), -1);
    EXPECT_EQ(first_byte_difference(copy.spring_impulse, original.spring_impulse), -1);
    EXPECT_EQ(first_byte_difference(copy.friction_impulse, original.friction_impulse), -1);
    EXPECT_EQ(copy.limit_impulse[5][1], original.limit_impulse[5][1]);
}

TEST(constraint_serialization_test, gravity_and_null_round_trip) {
    gravity_constraint gravity{{make_entity(3, 1), make_entity(7, 2)}};
    expect_bitwise_round_trip(gravity);
    null_constraint link{{make_entity(11, 0), null}};
    auto copy = round_trip(link);
    EXPECT_EQ(copy.body[0], make_entity(11, 0));
    EXPECT_TRUE(copy.body[1] == null);
}

TEST(constraint_serialization_test, dof_mode_out_of_range_fails) {
    auto original = patterned_generic();
    auto offset = generic_dofs_offset(original);
    auto dof_size = 1 + 6 * sizeof(scalar);
    auto valid = encode(original);
    ASSERT_EQ(valid[offset], std::uint8_t(dof_mode::free));
    ASSERT_EQ(valid[offset + 5 * dof_size], std::uint8_t(dof_mode::free)) << "angular[2]";
    for (auto at : {offset, offset + 5 * dof_size}) {
        for (std::uint8_t bad : {std::uint8_t(3), std::uint8_t(255)}) {
            auto bytes = valid;
            bytes[at] = bad;
            EXPECT_TRUE(decode_fails<generic_constraint>(bytes)) << "mode byte " << int(bad) << " at " << at;
        }
    }
    for (auto mode : {dof_mode::free, dof_mode::locked, dof_mode::limited}) {
        generic_constraint c;
        c.angular[1].mode = mode;
        EXPECT_EQ(round_trip(c).angular[1].mode, mode);
    }
}

TEST(constraint_serialization_test, truncated_constraints_fail) {
    expect_truncations_fail(patterned<point_constraint>());
    expect_truncations_fail(patterned<distance_constraint>());
    expect_truncations_fail(patterned<soft_distance_constraint>());
    expect_truncations_fail(patterned<hinge_constraint>());
    expect_truncations_fail(patterned<cvjoint_constraint>());
    expect_truncations_fail(patterned<cone_constraint>());
    expect_truncations_fail(patterned_generic());
    expect_truncations_fail(gravity_constraint{{make_entity(3, 1), make_entity(7, 2)}});
    expect_truncations_fail(null_constraint{{make_entity(3, 1), make_entity(7, 2)}});
}
