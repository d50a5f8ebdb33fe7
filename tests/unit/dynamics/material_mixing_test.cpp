// Default material mixing and pair overrides (material_mixing.hpp).
#include <cmath>
#include <edyn/dynamics/visit_shape.hpp>
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>

using namespace edyn;

namespace {

material make_material(scalar friction, scalar restitution, material_id_type id = invalid_material_id) {
    material m;
    m.friction = friction;
    m.restitution = restitution;
    m.id = id;
    return m;
}

} // namespace

TEST(material_mixing, default_functions_are_the_documented_ones) {
    // Friction: geometric mean, so one frictionless surface makes the contact frictionless.
    EXPECT_FLOAT_EQ(mix_friction(scalar(0.25), 1), scalar(0.5));
    EXPECT_FLOAT_EQ(mix_friction(scalar(0.4), scalar(0.4)), scalar(0.4));
    EXPECT_EQ(mix_friction(0, scalar(0.9)), 0);
    // Restitution, rolling and spinning friction: the larger value.
    EXPECT_EQ(mix_restitution(scalar(0.2), scalar(0.7)), scalar(0.7));
    EXPECT_EQ(mix_restitution(scalar(0.7), scalar(0.2)), scalar(0.7));
    EXPECT_EQ(mix_roll_friction(0, scalar(0.05)), scalar(0.05));
    EXPECT_EQ(mix_spin_friction(scalar(0.03), 0), scalar(0.03));
    // Stiffness: springs in series; a rigid side leaves the other's.
    EXPECT_FLOAT_EQ(mix_stiffness(100, 300), 75);
    EXPECT_EQ(mix_stiffness(large_scalar, 300), 300);
    EXPECT_EQ(mix_stiffness(300, large_scalar), 300);
    EXPECT_EQ(mix_stiffness(large_scalar, large_scalar), large_scalar);
    EXPECT_FLOAT_EQ(mix_damping(10, 10), 5);
}

TEST(material_mixing, mix_materials_applies_each_function) {
    material_base a, b;
    a.friction = scalar(0.25);
    b.friction = 1;
    a.restitution = scalar(0.1);
    b.restitution = scalar(0.6);
    a.roll_friction = scalar(0.02);
    b.spin_friction = scalar(0.01);
    a.stiffness = 100;
    b.stiffness = 300;
    auto m = mix_materials(a, b);
    EXPECT_FLOAT_EQ(m.friction, scalar(0.5));
    EXPECT_EQ(m.restitution, scalar(0.6));
    EXPECT_EQ(m.roll_friction, scalar(0.02));
    EXPECT_EQ(m.spin_friction, scalar(0.01));
    EXPECT_FLOAT_EQ(m.stiffness, 75);
    EXPECT_EQ(m.damping, large_scalar);
    // Symmetric.
    EXPECT_EQ(mix_materials(b, a), m);
}

TEST(material_mixing, the_defaults_are_those_of_the_manual) {
    material m;
    EXPECT_EQ(m.friction, scalar(0.5));
    EXPECT_EQ(m.restitution, 0);
    EXPECT_EQ(m.roll_friction, 0);
    EXPECT_EQ(m.spin_friction, 0);
    EXPECT_EQ(m.id, invalid_material_id);
}

TEST(material_mixing, a_pair_entry_overrides_the_default_in_either_order) {
    registry reg;
    auto ball = make_material(scalar(0.3), scalar(0.2), 0);
    auto table = make_material(scalar(0.8), scalar(0.1), 1);
    // No entry yet: the default mixing.
    EXPECT_EQ(get_mixed_material(reg, ball, table), mix_materials(ball, table));

    material_base ball_table;
    ball_table.friction = scalar(0.2);
    ball_table.restitution = scalar(0.5);
    insert_material_mixing(reg, 0, 1, ball_table);
    EXPECT_EQ(get_mixed_material(reg, ball, table), ball_table);
    EXPECT_EQ(get_mixed_material(reg, table, ball), ball_table);

    // Pairs are distinct: ball-ball still mixes by default until it has its own entry.
    EXPECT_EQ(get_mixed_material(reg, ball, ball), mix_materials(ball, ball));
    material_base ball_ball;
    ball_ball.friction = scalar(0.05);
    ball_ball.restitution = scalar(0.95);
    insert_material_mixing(reg, 0, 0, ball_ball);
    EXPECT_EQ(get_mixed_material(reg, ball, ball), ball_ball);
    EXPECT_EQ(get_mixed_material(reg, ball, table), ball_table);

    // Inserting again replaces the entry, whatever the order of the ids.
    ball_table.friction = scalar(0.7);
    insert_material_mixing(reg, 1, 0, ball_table);
    EXPECT_EQ(get_mixed_material(reg, ball, table).friction, scalar(0.7));

    // A body without an id always mixes by default.
    auto plain = make_material(scalar(0.3), scalar(0.2));
    EXPECT_EQ(get_mixed_material(reg, plain, table), mix_materials(plain, table));
}

TEST(material_mixing, insert_rejects_invalid_ids_and_values_and_keeps_the_table) {
    registry reg;
    material_base good;
    insert_material_mixing(reg, 2, 3, good);
    auto bad = [](auto change) {
        material_base m;
        change(m);
        return m;
    };
    constexpr auto qnan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_THROW(insert_material_mixing(reg, invalid_material_id, 3, good), std::invalid_argument);
    EXPECT_THROW(insert_material_mixing(reg, 2, invalid_material_id, good), std::invalid_argument);
    EXPECT_THROW(insert_material_mixing(reg, 2, 3, bad([](material_base &m) { m.friction = -1; })),
                 std::invalid_argument);
    EXPECT_THROW(insert_material_mixing(reg, 2, 3, bad([](material_base &m) { m.friction = qnan; })),
                 std::invalid_argument);
    EXPECT_THROW(
        insert_material_mixing(reg, 2, 3, bad([](material_base &m) { m.restitution = scalar(1.1); })),
        std::invalid_argument);
    EXPECT_THROW(insert_material_mixing(reg, 2, 3, bad([](material_base &m) { m.roll_friction = -1; })),
                 std::invalid_argument);
    EXPECT_THROW(insert_material_mixing(reg, 2, 3, bad([](material_base &m) { m.spin_friction = qnan; })),
                 std::invalid_argument);
    // The entry made before is unchanged.
    auto a = make_material(1, 1, 2), b = make_material(1, 1, 3);
    EXPECT_EQ(get_mixed_material(reg, a, b), good);
    EXPECT_EQ(reg.ctx().get<material_mix_table>().pairs.size(), 1u);
}

TEST(material_mixing, insert_checks_what_make_rigidbody_checks) {
    registry reg;
    attach(reg);
    material_base good;
    insert_material_mixing(reg, 2, 3, good);
    constexpr auto inf = std::numeric_limits<scalar>::infinity();
    constexpr auto qnan = std::numeric_limits<scalar>::quiet_NaN();
    struct bad_case {
        const char *field;
        material_base m;
    };
    auto with = [](auto change) {
        material_base m;
        change(m);
        return m;
    };
    const bad_case cases[]{
        {"mixed.stiffness", with([](material_base &m) { m.stiffness = 0; })},
        {"mixed.stiffness", with([&](material_base &m) { m.stiffness = -5; })},
        {"mixed.stiffness", with([&](material_base &m) { m.stiffness = qnan; })},
        {"mixed.damping", with([](material_base &m) { m.damping = -1; })},
        {"mixed.damping", with([&](material_base &m) { m.damping = qnan; })},
        {"mixed.roll_friction", with([&](material_base &m) { m.roll_friction = inf; })},
        {"mixed.spin_friction", with([&](material_base &m) { m.spin_friction = inf; })},
    };
    for (const auto &c : cases) {
        try {
            insert_material_mixing(reg, 2, 3, c.m);
            ADD_FAILURE() << "expected std::invalid_argument for " << c.field;
        } catch (const std::invalid_argument &e) {
            std::string what = e.what();
            EXPECT_NE(what.find("insert_material_mixing"), std::string::npos) << what;
            EXPECT_NE(what.find(c.field), std::string::npos) << what << "\nmissing: " << c.field;
        }
        // make_rigidbody refuses the same material.
        rigidbody_def def;
        def.shape = sphere_shape{scalar(0.5)};
        material mat;
        static_cast<material_base &>(mat) = c.m;
        def.material = mat;
        EXPECT_THROW(make_rigidbody(reg, def), std::invalid_argument) << c.field;
    }
    // The entry made before is unchanged.
    EXPECT_EQ(*reg.ctx().get<material_mix_table>().find(2, 3), good);
    // Finite stiffness and damping are accepted.
    auto soft = with([](material_base &m) {
        m.stiffness = 1e5;
        m.damping = 10;
    });
    insert_material_mixing(reg, 2, 3, soft);
    EXPECT_EQ(*reg.ctx().get<material_mix_table>().find(2, 3), soft);
    detach(reg);
}

TEST(material_mixing, a_point_on_a_mesh_takes_the_friction_between_its_triangles_vertices) {
    // One triangle whose friction is 0, 1 and 0 at its corners: at barycentric (0.2, 0.5, 0.3) the
    // mesh's friction is 0.5, mixed with the box's 1 by the geometric mean.
    auto mesh = std::make_shared<triangle_mesh>();
    std::vector<vector3> vertices{{0, 0, 0}, {2, 0, 0}, {0, 0, 2}};
    std::vector<std::uint32_t> indices{0, 2, 1};
    std::vector<scalar> friction{0, 1, 0};
    mesh->insert_vertices(vertices.begin(), vertices.end());
    mesh->insert_indices(indices.begin(), indices.end());
    mesh->insert_friction_coefficients(friction.begin(), friction.end());
    mesh->initialize();

    registry reg;
    rigidbody_def floor_def;
    floor_def.kind = rigidbody_kind::rb_static;
    floor_def.shape = mesh_shape{mesh};
    floor_def.material->restitution = scalar(0.1);
    auto floor = make_rigidbody(reg, floor_def);
    rigidbody_def box_def;
    box_def.shape = box_shape{vector3{scalar(0.5), scalar(0.5), scalar(0.5)}};
    box_def.material->friction = 1;
    box_def.material->restitution = scalar(0.4);
    auto box = make_rigidbody(reg, box_def);

    contact_point cp;
    cp.pivotA = vertices[0] * scalar(0.2) + vertices[1] * scalar(0.5) + vertices[2] * scalar(0.3);
    cp.featureA = collision_feature{};
    cp.featureA->part = 0;
    auto at_point = get_point_material(reg, floor, box, cp);
    EXPECT_NEAR(at_point.friction, std::sqrt(scalar(0.5)), scalar(1e-5));
    EXPECT_EQ(at_point.restitution, scalar(0.4));
    // The form for loops, given what it reads, gives the same.
    auto looped = get_point_material(nullptr, reg.get<material>(floor), get_shape_ref(reg, floor),
                                     reg.get<material>(box), get_shape_ref(reg, box), cp);
    EXPECT_EQ(looped, at_point);
    // A point that names no triangle takes the bodies' materials.
    contact_point plain = cp;
    plain.featureA.reset();
    EXPECT_EQ(get_point_material(reg, floor, box, plain),
              mix_materials(reg.get<material>(floor), reg.get<material>(box)));
    // A pair override wins over the mesh's coefficients, in both forms.
    reg.patch<material>(floor, [](material &m) { m.id = 1; });
    reg.patch<material>(box, [](material &m) { m.id = 2; });
    material_base override;
    override.friction = scalar(0.05);
    insert_material_mixing(reg, 1, 2, override);
    EXPECT_EQ(get_point_material(reg, floor, box, cp), override);
    EXPECT_EQ(get_point_material(reg.ctx().find<material_mix_table>(), reg.get<material>(floor),
                                 get_shape_ref(reg, floor), reg.get<material>(box), get_shape_ref(reg, box),
                                 cp),
              override);
}
