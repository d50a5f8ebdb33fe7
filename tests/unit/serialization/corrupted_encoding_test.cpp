// Decoding shapes, body definitions and constraints from damaged bytes: whatever the damage,
// the decoder fails or produces a value, and never throws or crashes (run under the sanitizers
// to see the latter).
#include "edyn/serialization/constraint_types.hpp"
#include "edyn/serialization/dynamics_types.hpp"
#include "edyn/serialization/shape_types.hpp"
#include "unit/serialization/archive_round_trip.hpp"
#include <cstdint>
#include <edyn/edyn.hpp>
#include <random>
#include <stdexcept>
#include <vector>

using namespace edyn;
using edyn::test::encode;

namespace {

// Damages a copy of `bytes`: overwrites, inserts or erases a few bytes, or cuts the end.
std::vector<std::uint8_t> damage(std::vector<std::uint8_t> bytes, std::mt19937 &rng) {
    std::uniform_int_distribution<int> byte(0, 255);
    auto at = [&](std::size_t size) { return std::uniform_int_distribution<std::size_t>(0, size - 1)(rng); };
    auto edits = std::uniform_int_distribution<int>(1, 4)(rng);
    for (int i = 0; i < edits && !bytes.empty(); ++i) {
        switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
        case 0:
            bytes[at(bytes.size())] = std::uint8_t(byte(rng));
            break;
        case 1:
            bytes.insert(bytes.begin() + std::ptrdiff_t(at(bytes.size())), std::uint8_t(byte(rng)));
            break;
        case 2:
            bytes.erase(bytes.begin() + std::ptrdiff_t(at(bytes.size())));
            break;
        default:
            bytes.resize(at(bytes.size()));
            break;
        }
    }
    return bytes;
}

// Decodes `damages` damaged copies of the encoding of `original`; how many decoded.
template<typename T, typename Check>
int decode_damaged(const T &original, int damages, Check &&check) {
    std::mt19937 rng(12345);
    auto bytes = encode(original);
    int decoded = 0;
    for (int i = 0; i < damages; ++i) {
        auto damaged = damage(bytes, rng);
        T value{};
        memory_input_archive archive(damaged.data(), damaged.size());
        EXPECT_NO_THROW(archive(value)) << "damage " << i;
        if (!archive.failed()) {
            ++decoded;
            check(value);
        }
    }
    return decoded;
}

rigidbody_def body_with_compound() {
    compound_shape compound;
    compound.add_shape(polyhedron_shape(std::vector<vector3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}),
                       vector3{-1, 0, 0});
    compound.add_shape(cylinder_shape{1, 1, coordinate_axis::y}, vector3{1, 0, 0},
                       normalize(quaternion{0, 1, 0, 1}));
    compound.finish();
    rigidbody_def def;
    def.shape = compound;
    def.gravity = vector3{0, -1, 0};
    return def;
}

} // namespace

TEST(corrupted_encoding_test, damaged_body_definitions_decode_or_fail) {
    registry reg;
    attach(reg);
    int made = 0;
    // A decoded definition may still hold values make_rigidbody refuses; it must refuse them
    // with invalid_argument and nothing else.
    auto decoded = decode_damaged(body_with_compound(), 3000, [&](const rigidbody_def &def) {
        try {
            make_rigidbody(reg, def);
            ++made;
        } catch (const std::invalid_argument &) {
        }
    });
    // Some damage only changes values: the decoder must not refuse everything.
    EXPECT_GT(decoded, 0);
    EXPECT_GT(made, 0);
    detach(reg);
}

TEST(corrupted_encoding_test, damaged_polyhedra_decode_or_fail) {
    std::vector<vector3> points{{1, 2, 3},  {-1, 2, 3},  {1, -2, 3},  {-1, -2, 3},
                                {1, 2, -3}, {-1, 2, -3}, {1, -2, -3}, {-1, -2, -3}};
    // Whatever decodes was rebuilt and validated by the polyhedron's constructor.
    auto decoded =
        decode_damaged(shapes_variant_t{polyhedron_shape(points)}, 3000, [](const shapes_variant_t &s) {
            if (auto *p = std::get_if<polyhedron_shape>(&s); p && p->mesh) {
                EXPECT_NO_THROW(validate_convex_mesh(*p->mesh));
            }
        });
    EXPECT_GT(decoded, 0);
}

TEST(corrupted_encoding_test, damaged_constraints_decode_or_fail) {
    generic_constraint generic;
    generic.linear[1].mode = dof_mode::limited;
    auto decoded = decode_damaged(generic, 3000, [](const generic_constraint &c) {
        for (auto &dof : c.linear)
            EXPECT_LE(static_cast<int>(dof.mode), static_cast<int>(dof_mode::limited));
        for (auto &dof : c.angular)
            EXPECT_LE(static_cast<int>(dof.mode), static_cast<int>(dof_mode::limited));
    });
    EXPECT_GT(decoded, 0);
    hinge_constraint hinge;
    hinge.angle_min = -1;
    hinge.angle_max = 1;
    EXPECT_GT(decode_damaged(hinge, 1000, [](const hinge_constraint &) {}), 0);
}
