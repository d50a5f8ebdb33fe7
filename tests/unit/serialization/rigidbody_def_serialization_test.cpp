#include "edyn/serialization/dynamics_types.hpp"
#include "unit/serialization/archive_round_trip.hpp"
#include <cstdint>
#include <edyn/edyn.hpp>
#include <optional>
#include <vector>

using namespace edyn;
using edyn::test::decode_fails;
using edyn::test::encode;
using edyn::test::expect_truncations_fail;
using edyn::test::first_byte_difference;
using edyn::test::round_trip;

// A member added to one of these must be serialized too (dynamics_types.hpp), then listed here.
namespace {
struct rigidbody_def_members {
    rigidbody_kind kind;
    scalar mass;
    std::optional<matrix3x3> inertia;
    std::optional<edyn::material> material;
    std::optional<scalar> restitution;
    vector3 position;
    quaternion orientation;
    vector3 linvel;
    vector3 angvel;
    std::optional<vector3> gravity;
    std::optional<shapes_variant_t> shape;
    std::uint64_t collision_group;
    std::uint64_t collision_mask;
    std::optional<vector3> center_of_mass;
    bool sleeping_disabled;
};
} // namespace
static_assert(sizeof(rigidbody_def) == sizeof(rigidbody_def_members),
              "rigidbody_def changed: update its serializer");
static_assert(sizeof(material_base) == 6 * sizeof(scalar), "material_base changed: update its serializer");
static_assert(sizeof(material) == sizeof(material_base) + (sizeof(scalar) == 4 ? 4 : 8),
              "material changed: update its serializer");

namespace {

edyn::material custom_material() {
    edyn::material m;
    m.friction = scalar(0.8);
    m.restitution = scalar(0.25);
    m.roll_friction = scalar(0.01);
    m.spin_friction = scalar(0.02);
    m.stiffness = scalar(1e5);
    m.damping = scalar(3e3);
    m.id = 42;
    return m;
}

rigidbody_def full_def() {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.mass = scalar(12.5);
    def.inertia = matrix3x3{{{1, scalar(0.1), 0}, {scalar(0.1), 2, 0}, {0, 0, 3}}};
    def.material = custom_material();
    def.restitution = scalar(0.5);
    def.position = {1, -2, 3};
    def.orientation = normalize(quaternion{1, 2, 3, 4});
    def.linvel = {scalar(0.5), 0, -1};
    def.angvel = {0, scalar(0.25), 2};
    def.gravity = vector3{0, scalar(-3.7), 0};
    def.shape = capsule_shape{scalar(0.5), 1, coordinate_axis::y};
    def.collision_group = 0x0123456789abcdefull;
    def.collision_mask = 0xfedcba9876543210ull;
    def.center_of_mass = vector3{0, scalar(0.1), 0};
    def.sleeping_disabled = true;
    return def;
}

// None of the optionals set.
rigidbody_def bare_def() {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.material.reset();
    return def;
}

void expect_same_def(const rigidbody_def &actual, const rigidbody_def &expected) {
    EXPECT_EQ(actual.kind, expected.kind);
    EXPECT_EQ(actual.mass, expected.mass);
    EXPECT_EQ(actual.inertia, expected.inertia);
    EXPECT_EQ(actual.material, expected.material);
    EXPECT_EQ(actual.restitution, expected.restitution);
    EDYN_EXPECT_SAME(actual.position, expected.position);
    EDYN_EXPECT_SAME(actual.orientation, expected.orientation);
    EDYN_EXPECT_SAME(actual.linvel, expected.linvel);
    EDYN_EXPECT_SAME(actual.angvel, expected.angvel);
    EXPECT_EQ(actual.gravity, expected.gravity);
    ASSERT_EQ(actual.shape.has_value(), expected.shape.has_value());
    if (expected.shape) {
        EXPECT_EQ(actual.shape->index(), expected.shape->index());
    }
    EXPECT_EQ(actual.collision_group, expected.collision_group);
    EXPECT_EQ(actual.collision_mask, expected.collision_mask);
    EXPECT_EQ(actual.center_of_mass, expected.center_of_mass);
    EXPECT_EQ(actual.sleeping_disabled, expected.sleeping_disabled);
}

} // namespace

TEST(rigidbody_def_serialization_test, material_round_trip) {
    auto original = custom_material();
    auto copy = round_trip(original);
    // The values bit for bit; in double precision the id is followed by padding.
    EXPECT_EQ(first_byte_difference<material_base>(copy, original), -1)
        << "byte offset of the first difference";
    EXPECT_EQ(copy.id, 42u);
    EXPECT_EQ(copy.stiffness, scalar(1e5));
    expect_truncations_fail(original);
}

TEST(rigidbody_def_serialization_test, all_optionals_set_round_trip) {
    auto original = full_def();
    auto copy = round_trip(original);
    expect_same_def(copy, original);
    ASSERT_TRUE(copy.shape && std::holds_alternative<capsule_shape>(*copy.shape));
    EXPECT_EQ(std::get<capsule_shape>(*copy.shape).axis, coordinate_axis::y);
}

TEST(rigidbody_def_serialization_test, no_optionals_set_round_trip) {
    auto original = bare_def();
    // Decoded over a def whose optionals are all set, so that reading must clear them.
    auto bytes = encode(original);
    auto copy = full_def();
    ASSERT_FALSE(decode_fails(bytes, copy));
    expect_same_def(copy, original);
    EXPECT_FALSE(copy.inertia || copy.material || copy.restitution || copy.gravity || copy.shape ||
                 copy.center_of_mass);
}

TEST(rigidbody_def_serialization_test, every_kind_round_trips) {
    for (auto kind : {rigidbody_kind::rb_dynamic, rigidbody_kind::rb_static, rigidbody_kind::rb_kinematic}) {
        rigidbody_def def;
        def.kind = kind;
        EXPECT_EQ(round_trip(def).kind, kind);
    }
}

TEST(rigidbody_def_serialization_test, malformed_defs_fail) {
    // The kind is the first byte.
    for (std::uint8_t bad : {std::uint8_t(3), std::uint8_t(200)}) {
        auto bytes = encode(full_def());
        bytes[0] = bad;
        EXPECT_TRUE(decode_fails<rigidbody_def>(bytes)) << "kind byte " << int(bad);
    }
    // The last byte is sleeping_disabled, a bool: only 0 and 1 are valid.
    auto bytes = encode(full_def());
    bytes.back() = 2;
    EXPECT_TRUE(decode_fails<rigidbody_def>(bytes));
    // The shape's axis is out of range: a capsule is the variant's last bytes before the
    // collision group, mask, centre of mass and the sleeping flag.
    auto def = full_def();
    auto axis_offset = encode(def).size() - 1 - 2 * sizeof(std::uint64_t) - (1 + 3 * sizeof(scalar)) - 1;
    bytes = encode(def);
    ASSERT_EQ(bytes[axis_offset], std::uint8_t(coordinate_axis::y));
    bytes[axis_offset] = 7;
    EXPECT_TRUE(decode_fails<rigidbody_def>(bytes));

    expect_truncations_fail(full_def());
    expect_truncations_fail(bare_def());
}

TEST(rigidbody_def_serialization_test, decoded_def_makes_a_body) {
    auto original = full_def();
    original.kind = rigidbody_kind::rb_dynamic;
    original.inertia.reset();
    original.center_of_mass.reset();
    compound_shape compound;
    compound.add_shape(box_shape{1, scalar(0.5), scalar(0.5)}, vector3{1, 0, 0});
    compound.add_shape(polyhedron_shape(std::vector<vector3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}),
                       vector3{-1, 0, 0});
    compound.finish();
    original.shape = compound;

    auto bytes = encode(original);
    rigidbody_def decoded;
    ASSERT_FALSE(decode_fails(bytes, decoded));

    registry reg;
    attach(reg);
    entity body = null;
    ASSERT_NO_THROW(body = make_rigidbody(reg, decoded));
    ASSERT_TRUE(reg.valid(body));
    EXPECT_TRUE(reg.all_of<dynamic_tag>(body));
    ASSERT_TRUE(reg.all_of<compound_shape>(body));
    EXPECT_EQ(reg.get<compound_shape>(body).children.size(), 2u);
    // def.restitution overrides the material's.
    auto expected_material = custom_material();
    expected_material.restitution = *original.restitution;
    EXPECT_TRUE(reg.get<edyn::material>(body) == expected_material)
        << "restitution " << reg.get<edyn::material>(body).restitution << ", expected "
        << expected_material.restitution;
    EXPECT_EQ(reg.get<mass>(body).s, original.mass);
    detach(reg);
}
