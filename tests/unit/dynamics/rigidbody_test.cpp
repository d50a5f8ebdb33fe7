// rigidbody_def validation, make_rigidbody and the functions that change a body.
#include <cmath>
#include <edyn/dynamics/visit_shape.hpp>
#include <edyn/edyn.hpp>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

using namespace edyn;

namespace {

constexpr scalar qnan = std::numeric_limits<scalar>::quiet_NaN();
constexpr scalar pinf = std::numeric_limits<scalar>::infinity();

template<typename... Components>
struct component_list {};

// Every component make_rigidbody may put on an entity, and the simulation's own.
using body_components =
    component_list<rigidbody_tag, dynamic_tag, static_tag, kinematic_tag, sleeping_tag, sleeping_disabled_tag,
                   sensor_tag, position, orientation, present_position, present_orientation, linvel, angvel,
                   gravity, mass, mass_inv, inertia, inertia_inv, inertia_world_inv, center_of_mass,
                   rigidbody_dynamic_mass, material, shape_index, AABB, collision_filter, collision_exclusion,
                   plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape, polyhedron_shape,
                   compound_shape, contact_manifold>;

// The number of live entities and the size of every pool.
struct registry_snapshot {
    std::size_t alive;
    std::vector<std::size_t> pool_sizes;

    bool operator==(const registry_snapshot &) const = default;
};

template<typename... Components>
registry_snapshot snapshot(const registry &reg, component_list<Components...>) {
    return {reg.alive(), {reg.storage<Components>().size()...}};
}

registry_snapshot snapshot(const registry &reg) { return snapshot(reg, body_components{}); }

struct rigidbody_test : ::testing::Test {
    registry reg;
    entity existing{null};

    void SetUp() override {
        attach(reg);
        // A body and a plain entity already there, so that "untouched" has something to keep.
        rigidbody_def def;
        def.shape = box_shape{1, 1, 1};
        make_rigidbody(reg, def);
        existing = reg.create();
    }
    void TearDown() override { detach(reg); }

    // Every entry point must reject `def`, name `field` and leave the registry as it was.
    void expect_rejected(const rigidbody_def &def, const std::string &field) {
        auto before = snapshot(reg);
        auto check = [&](const char *how, const std::function<void()> &call) {
            try {
                call();
                ADD_FAILURE() << how << " accepted a definition with a bad " << field;
            } catch (const std::invalid_argument &e) {
                EXPECT_NE(std::string(e.what()).find(field), std::string::npos)
                    << how << ": message \"" << e.what() << "\" does not name " << field;
            } catch (...) {
                ADD_FAILURE() << how << " threw something other than std::invalid_argument for " << field;
            }
            EXPECT_TRUE(snapshot(reg) == before) << how << " changed the registry when rejecting " << field;
        };
        check("validate_rigidbody_def", [&] { validate_rigidbody_def(def); });
        check("make_rigidbody(registry, def)", [&] { make_rigidbody(reg, def); });
        check("make_rigidbody(entity, registry, def)", [&] { make_rigidbody(existing, reg, def); });
        EXPECT_FALSE(reg.all_of<rigidbody_tag>(existing));
    }
};

rigidbody_def valid_box() {
    rigidbody_def def;
    def.mass = 2;
    def.shape = box_shape{scalar(0.5), scalar(0.5), scalar(0.5)};
    return def;
}

} // namespace

TEST_F(rigidbody_test, a_dynamic_body_needs_a_positive_finite_mass) {
    for (scalar m : {qnan, scalar(0), scalar(-1), pinf, scalar(1e-30), scalar(1e30)}) {
        auto def = valid_box();
        def.mass = m;
        SCOPED_TRACE(m);
        expect_rejected(def, "mass");
    }
    // Static and kinematic bodies have infinite mass: theirs is ignored.
    auto def = valid_box();
    def.mass = 0;
    def.kind = rigidbody_kind::rb_static;
    EXPECT_NO_THROW(make_rigidbody(reg, def));
    def.kind = rigidbody_kind::rb_kinematic;
    EXPECT_NO_THROW(make_rigidbody(reg, def));
}

TEST_F(rigidbody_test, an_amorphous_dynamic_body_needs_a_valid_inertia) {
    rigidbody_def def;
    def.mass = 1;
    expect_rejected(def, "inertia");
    def.inertia = diagonal_matrix(vector3{1, -1, 1});
    expect_rejected(def, "inertia");
    def.inertia = diagonal_matrix(vector3{1, qnan, 1});
    expect_rejected(def, "inertia");
    // Values a server sent a client, which its simulation could not survive: too small or too
    // large to invert in a float, not symmetric, positive diagonal and determinant yet two
    // negative eigenvalues.
    def.inertia = diagonal_matrix(vector3{scalar(1e-13), scalar(1e-13), scalar(1e-13)});
    expect_rejected(def, "inertia");
    def.inertia = diagonal_matrix(vector3{scalar(1e32), 1, 1});
    expect_rejected(def, "inertia");
    def.inertia = matrix3x3{{vector3{1, scalar(0.9), 0}, vector3{scalar(-0.9), 1, 0}, vector3{0, 0, 1}}};
    expect_rejected(def, "inertia");
    def.inertia = matrix3x3{{vector3{1, 2, 2}, vector3{2, 1, 2}, vector3{2, 2, 1}}};
    expect_rejected(def, "inertia");
    // Nearly singular: a diagonal in range, a principal moment far below it.
    auto small = scalar(1e-6);
    auto next = std::nextafter(small, scalar(1));
    def.inertia = matrix3x3{{vector3{small, small, 0}, vector3{small, next, 0}, vector3{0, 0, small}}};
    expect_rejected(def, "inertia");
    // A rotated tensor, symmetric to rounding, and the bounds themselves are accepted.
    auto r = to_matrix3x3(normalize(quaternion{scalar(0.3), scalar(0.2), scalar(0.1), 1}));
    def.inertia = r * diagonal_matrix(vector3{1, 2, 3}) * transpose(r);
    EXPECT_NO_THROW(make_rigidbody(reg, def));
    def.inertia = diagonal_matrix(vector3{min_body_inertia, max_body_inertia, 1});
    EXPECT_NO_THROW(make_rigidbody(reg, def));
    // Uniform tensors anywhere in the range, whose determinants overflow a float from 1e13 up,
    // are accepted with their inverse (they were refused from 1e20, and 1e13 had an inverse of 0).
    for (auto moment : {scalar(1e13), scalar(1e20), max_body_inertia}) {
        def.inertia = diagonal_matrix(vector3{moment, moment, moment});
        auto big = make_rigidbody(reg, def);
        EXPECT_NEAR(reg.get<inertia_inv>(big)[1][1] * moment, 1, scalar(1e-6)) << moment;
    }
    def.inertia = diagonal_matrix(vector3{1, 2, 3});
    auto e = make_rigidbody(reg, def);
    EXPECT_EQ(static_cast<const matrix3x3 &>(reg.get<inertia>(e)), diagonal_matrix(vector3{1, 2, 3}));
    EXPECT_FALSE((reg.any_of<AABB, shape_index>(e)));
    // Amorphous static bodies need nothing.
    rigidbody_def static_def;
    static_def.kind = rigidbody_kind::rb_static;
    EXPECT_NO_THROW(make_rigidbody(reg, static_def));
}

TEST_F(rigidbody_test, orientation_must_be_a_finite_unit_quaternion) {
    auto def = valid_box();
    def.orientation = quaternion{0, 0, 0, 2};
    expect_rejected(def, "orientation");
    def.orientation = quaternion{qnan, 0, 0, 1};
    expect_rejected(def, "orientation");
    def.orientation = quaternion{0, 0, 0, 0};
    expect_rejected(def, "orientation");
}

TEST_F(rigidbody_test, material_values_must_be_in_range) {
    auto with = [](auto change) {
        auto def = valid_box();
        change(*def.material);
        return def;
    };
    expect_rejected(with([](material &m) { m.friction = -scalar(0.1); }), "friction");
    expect_rejected(with([](material &m) { m.friction = qnan; }), "friction");
    expect_rejected(with([](material &m) { m.restitution = scalar(1.5); }), "restitution");
    expect_rejected(with([](material &m) { m.restitution = -scalar(0.1); }), "restitution");
    expect_rejected(with([](material &m) { m.restitution = qnan; }), "restitution");
    expect_rejected(with([](material &m) { m.roll_friction = -1; }), "roll_friction");
    expect_rejected(with([](material &m) { m.spin_friction = qnan; }), "spin_friction");
    // The range ends are allowed.
    EXPECT_NO_THROW(make_rigidbody(reg, with([](material &m) {
                                       m.friction = 0;
                                       m.restitution = 1;
                                   })));
}

// The manual's hello world sets def.restitution beside def.material->friction.
TEST_F(rigidbody_test, restitution_set_on_the_def_replaces_the_materials) {
    auto def = valid_box();
    def.material->friction = scalar(0.8);
    def.material->restitution = scalar(0.3);
    def.restitution = 0;
    auto e = make_rigidbody(reg, def);
    EXPECT_EQ(reg.get<material>(e).restitution, 0);
    EXPECT_EQ(reg.get<material>(e).friction, scalar(0.8));
    def.restitution.reset();
    EXPECT_EQ(reg.get<material>(make_rigidbody(reg, def)).restitution, scalar(0.3));

    def.restitution = scalar(1.5);
    expect_rejected(def, "restitution");
    def.restitution = qnan;
    expect_rejected(def, "restitution");
    def.restitution = scalar(0.5);
    def.material.reset(); // a sensor has no material to take it
    expect_rejected(def, "restitution");
}

TEST_F(rigidbody_test, vectors_must_be_finite) {
    auto def = valid_box();
    def.position = {qnan, 0, 0};
    expect_rejected(def, "position");
    def = valid_box();
    def.position = {0, pinf, 0};
    expect_rejected(def, "position");
    def = valid_box();
    def.linvel = {0, 0, qnan};
    expect_rejected(def, "linvel");
    def = valid_box();
    def.angvel = {pinf, 0, 0};
    expect_rejected(def, "angvel");
    def = valid_box();
    def.gravity = vector3{0, qnan, 0};
    expect_rejected(def, "gravity");
    def.gravity = vector3{0, scalar(-4e34), 0};
    expect_rejected(def, "gravity");
    def = valid_box();
    def.center_of_mass = vector3{qnan, 0, 0};
    expect_rejected(def, "center_of_mass");
}

TEST_F(rigidbody_test, shapes_must_be_valid_and_planes_static) {
    auto def = valid_box();
    def.shape = box_shape{0, 1, 1};
    expect_rejected(def, "box_shape");
    def.shape = sphere_shape{0};
    expect_rejected(def, "sphere_shape");
    def.shape = sphere_shape{-1};
    expect_rejected(def, "sphere_shape");
    def.shape = plane_shape{vector3_y, 0};
    expect_rejected(def, "plane_shape");
    def.kind = rigidbody_kind::rb_kinematic;
    expect_rejected(def, "plane_shape");
}

TEST_F(rigidbody_test, an_entity_is_made_a_rigid_body_only_once_and_only_if_valid) {
    auto e = make_rigidbody(reg, valid_box());
    auto before = snapshot(reg);
    EXPECT_THROW(make_rigidbody(e, reg, valid_box()), std::invalid_argument);
    EXPECT_TRUE(snapshot(reg) == before);
    auto dead = reg.create();
    reg.destroy(dead);
    before = snapshot(reg);
    EXPECT_THROW(make_rigidbody(dead, reg, valid_box()), std::invalid_argument);
    EXPECT_TRUE(snapshot(reg) == before);
}

// A kind outside the enumeration, a body that is not one: refused, naming the function, and
// nothing changes.
TEST_F(rigidbody_test, an_unknown_kind_and_an_entity_that_is_no_body_are_refused) {
    auto expect_refused = [](const char *what, auto &&call) {
        try {
            call();
            ADD_FAILURE() << "accepted: " << what;
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    auto def = valid_box();
    def.kind = static_cast<rigidbody_kind>(9);
    auto before = snapshot(reg);
    expect_refused("make_rigidbody: kind 9 is not a rigidbody_kind", [&] { make_rigidbody(reg, def); });
    EXPECT_TRUE(snapshot(reg) == before);

    auto body = make_rigidbody(reg, valid_box());
    expect_refused("rigidbody_set_kind: kind 7 is not a rigidbody_kind",
                   [&] { rigidbody_set_kind(reg, body, static_cast<rigidbody_kind>(7)); });
    EXPECT_TRUE(reg.all_of<dynamic_tag>(body));

    auto plain = reg.create();
    expect_refused("get_rigidbody_origin: entity is not a rigid body",
                   [&] { get_rigidbody_origin(reg, plain); });
}

// make_rigidbody creates the components the manual names.
TEST_F(rigidbody_test, a_dynamic_body_gets_the_manuals_components) {
    auto def = valid_box();
    def.position = {1, 2, 3};
    def.orientation = quaternion_axis_angle(normalize(vector3{1, 1, 0}), scalar(0.7));
    def.linvel = {4, 5, 6};
    def.angvel = {scalar(0.1), scalar(0.2), scalar(0.3)};
    def.material->friction = scalar(0.3);
    def.material->id = 7;
    def.collision_group = 2;
    def.collision_mask = 5;
    auto e = make_rigidbody(reg, def);

    EXPECT_TRUE((reg.all_of<rigidbody_tag, dynamic_tag, position, orientation, linvel, angvel,
                            present_position, present_orientation, mass, mass_inv, inertia, inertia_inv,
                            inertia_world_inv, material, AABB, box_shape, collision_filter>(e)));
    EXPECT_FALSE((reg.any_of<static_tag, kinematic_tag, sensor_tag, center_of_mass, gravity>(e)));
    EXPECT_EQ(static_cast<vector3>(reg.get<position>(e)), def.position);
    EXPECT_EQ(static_cast<vector3>(reg.get<present_position>(e)), def.position);
    EXPECT_EQ(static_cast<quaternion>(reg.get<orientation>(e)), def.orientation);
    EXPECT_EQ(static_cast<quaternion>(reg.get<present_orientation>(e)), def.orientation);
    EXPECT_EQ(static_cast<vector3>(reg.get<linvel>(e)), def.linvel);
    EXPECT_EQ(static_cast<vector3>(reg.get<angvel>(e)), def.angvel);
    EXPECT_EQ(reg.get<mass>(e).s, 2);
    EXPECT_EQ(reg.get<mass_inv>(e).s, scalar(0.5));
    // Solid box: I = m/3 (b^2 + c^2) with half extents, 2/3 * 0.5 = 1/3 on each axis.
    auto I = scalar(1) / 3;
    auto &inertia_value = reg.get<inertia>(e);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(inertia_value.row[i][i], I, 1e-6) << "axis " << i;
        EXPECT_NEAR(reg.get<inertia_inv>(e).row[i][i], 1 / I, 1e-5) << "axis " << i;
    }
    // World inverse inertia: R I^-1 R^T, the same for a cube in any orientation.
    auto r = to_matrix3x3(def.orientation);
    auto expected_world = r * static_cast<const matrix3x3 &>(reg.get<inertia_inv>(e)) * transpose(r);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(reg.get<inertia_world_inv>(e).row[i][j], expected_world.row[i][j], 1e-5);
    EXPECT_EQ(static_cast<const material &>(reg.get<material>(e)), *def.material);
    EXPECT_EQ(reg.get<collision_filter>(e).group, 2u);
    EXPECT_EQ(reg.get<collision_filter>(e).mask, 5u);
    // The AABB holds every corner of the rotated box.
    auto &aabb = reg.get<AABB>(e);
    for (int c = 0; c < 8; ++c) {
        vector3 corner{c & 1 ? scalar(0.5) : -scalar(0.5), c & 2 ? scalar(0.5) : -scalar(0.5),
                       c & 4 ? scalar(0.5) : -scalar(0.5)};
        auto p = def.position + rotate(def.orientation, corner);
        EXPECT_TRUE(contains(inset(aabb, vector3{scalar(1e-4), scalar(1e-4), scalar(1e-4)}), p))
            << "corner " << c;
    }
}

TEST_F(rigidbody_test, static_and_kinematic_bodies_have_infinite_mass) {
    auto def = valid_box();
    def.linvel = {1, 0, 0};
    def.angvel = {0, 1, 0};
    def.kind = rigidbody_kind::rb_static;
    auto s = make_rigidbody(reg, def);
    EXPECT_TRUE((reg.all_of<rigidbody_tag, static_tag, mass_inv, inertia_inv, AABB>(s)));
    EXPECT_FALSE((reg.any_of<dynamic_tag, kinematic_tag>(s)));
    EXPECT_EQ(reg.get<mass_inv>(s).s, 0);
    EXPECT_EQ(static_cast<const matrix3x3 &>(reg.get<inertia_inv>(s)), matrix3x3_zero);
    EXPECT_EQ(static_cast<vector3>(reg.get<linvel>(s)), vector3_zero) << "a static body never moves";
    EXPECT_EQ(static_cast<vector3>(reg.get<angvel>(s)), vector3_zero);

    def.kind = rigidbody_kind::rb_kinematic;
    auto k = make_rigidbody(reg, def);
    EXPECT_TRUE((reg.all_of<rigidbody_tag, kinematic_tag>(k)));
    EXPECT_EQ(reg.get<mass_inv>(k).s, 0);
    EXPECT_EQ(static_cast<vector3>(reg.get<linvel>(k)), def.linvel) << "a kinematic body keeps its velocity";
}

TEST_F(rigidbody_test, options_of_the_definition_become_components) {
    auto def = valid_box();
    def.material.reset();
    def.sleeping_disabled = true;
    def.gravity = vector3{0, 0, -1};
    def.center_of_mass = vector3{scalar(0.1), 0, 0};
    def.position = {0, 1, 0};
    def.orientation = quaternion_axis_angle(vector3_z, std::numbers::pi_v<scalar> / 2);
    auto e = make_rigidbody(reg, def);
    EXPECT_TRUE((reg.all_of<sensor_tag, sleeping_disabled_tag, gravity, center_of_mass>(e)));
    EXPECT_FALSE(reg.all_of<material>(e));
    EXPECT_EQ(static_cast<vector3>(reg.get<gravity>(e)), (vector3{0, 0, -1}));
    // position is the centre of mass: the origin plus the rotated offset, (0, 1.1, 0).
    auto p = static_cast<vector3>(reg.get<position>(e));
    EXPECT_NEAR(p.x, 0, 1e-6);
    EXPECT_NEAR(p.y, scalar(1.1), 1e-6);
    auto origin = get_rigidbody_origin(reg, e);
    EXPECT_NEAR(length(origin - def.position), 0, 1e-6);
}

// rigidbody_origin() from the components gives get_rigidbody_origin()'s bits, with a centre of
// mass and without one.
TEST_F(rigidbody_test, the_origin_from_components_is_get_rigidbody_origins) {
    auto def = valid_box();
    def.position = {1, 2, 3};
    def.orientation = quaternion_axis_angle(normalize(vector3{1, 1, 0}), scalar(0.7));
    auto plain = make_rigidbody(reg, def);
    def.center_of_mass = vector3{scalar(0.1), scalar(-0.2), scalar(0.3)};
    auto shifted = make_rigidbody(reg, def);
    for (auto e : {plain, shifted}) {
        auto origin =
            rigidbody_origin(reg.get<position>(e), reg.get<orientation>(e), reg.try_get<center_of_mass>(e));
        EXPECT_EQ(origin, get_rigidbody_origin(reg, e));
        EXPECT_NEAR(length(origin - def.position), 0, 1e-5);
    }
}

TEST_F(rigidbody_test, the_entity_overload_keeps_the_programs_components) {
    struct health {
        int points;
    };
    auto e = reg.create();
    reg.emplace<health>(e, 42);
    make_rigidbody(e, reg, valid_box());
    EXPECT_TRUE(reg.all_of<rigidbody_tag>(e));
    EXPECT_EQ(reg.get<health>(e).points, 42);

    clear_rigidbody(reg, e);
    EXPECT_TRUE(reg.valid(e));
    EXPECT_EQ(reg.get<health>(e).points, 42);
    EXPECT_FALSE((reg.any_of<rigidbody_tag, dynamic_tag, position, orientation, linvel, angvel, mass,
                             mass_inv, inertia, inertia_inv, inertia_world_inv, material, AABB, box_shape,
                             collision_filter, present_position, present_orientation>(e)));
    // And it can become a body again.
    EXPECT_NO_THROW(make_rigidbody(e, reg, valid_box()));
}

TEST_F(rigidbody_test, set_mass_scales_the_inertia_with_the_mass) {
    auto e = make_rigidbody(reg, valid_box());
    auto I = reg.get<inertia>(e).row[0].x;
    rigidbody_set_mass(reg, e, 6);
    EXPECT_EQ(reg.get<mass>(e).s, 6);
    EXPECT_NEAR(reg.get<mass_inv>(e).s, scalar(1) / 6, 1e-7);
    EXPECT_NEAR(reg.get<inertia>(e).row[0].x, 3 * I, 1e-6);
    EXPECT_NEAR(reg.get<inertia_inv>(e).row[0].x, 1 / (3 * I), 1e-5);
    EXPECT_NEAR(reg.get<inertia_world_inv>(e).row[1].y, 1 / (3 * I), 1e-5);
    EXPECT_THROW(rigidbody_set_mass(reg, e, 0), std::invalid_argument);
    EXPECT_THROW(rigidbody_set_mass(reg, e, qnan), std::invalid_argument);
    EXPECT_EQ(reg.get<mass>(e).s, 6);

    auto def = valid_box();
    def.kind = rigidbody_kind::rb_static;
    auto s = make_rigidbody(reg, def);
    EXPECT_THROW(rigidbody_set_mass(reg, s, 2), std::invalid_argument);
}

TEST_F(rigidbody_test, an_impulse_changes_momentum_and_angular_momentum) {
    // Box of mass 2, I = 1/3 on each axis. p = (0, 2, 0) applied 1 m along x from the centre of
    // mass: dv = p / m = (0, 1, 0), dw = I^-1 (r x p) = 3 (0, 0, 2) = (0, 0, 6).
    auto e = make_rigidbody(reg, valid_box());
    rigidbody_apply_impulse(reg, e, {0, 2, 0}, {1, 0, 0});
    auto v = static_cast<vector3>(reg.get<linvel>(e));
    auto w = static_cast<vector3>(reg.get<angvel>(e));
    EXPECT_NEAR(length(v - vector3{0, 1, 0}), 0, 1e-6)
        << "linvel (" << v.x << ", " << v.y << ", " << v.z << ")";
    EXPECT_NEAR(length(w - vector3{0, 0, 6}), 0, 1e-4)
        << "angvel (" << w.x << ", " << w.y << ", " << w.z << ")";

    // Bodies of infinite mass do not move.
    auto def = valid_box();
    def.kind = rigidbody_kind::rb_static;
    auto s = make_rigidbody(reg, def);
    rigidbody_apply_impulse(reg, s, {0, 2, 0}, {1, 0, 0});
    EXPECT_EQ(static_cast<vector3>(reg.get<linvel>(s)), vector3_zero);
    EXPECT_THROW(rigidbody_apply_impulse(reg, e, {qnan, 0, 0}, vector3_zero), std::invalid_argument);
}

TEST_F(rigidbody_test, changing_kind_and_shape_updates_the_mass_properties) {
    auto e = make_rigidbody(reg, valid_box());
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_kinematic);
    EXPECT_TRUE(reg.all_of<kinematic_tag>(e));
    EXPECT_EQ(reg.get<mass_inv>(e).s, 0);
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic);
    EXPECT_EQ(reg.get<mass>(e).s, 2);
    EXPECT_NEAR(reg.get<inertia>(e).row[2].z, scalar(1) / 3, 1e-6);

    // A sphere of radius 1 and mass 2: I = 2/5 m r^2 = 0.8.
    rigidbody_set_shape(reg, e, shapes_variant_t{sphere_shape{1}});
    EXPECT_TRUE(reg.all_of<sphere_shape>(e));
    EXPECT_FALSE(reg.all_of<box_shape>(e));
    EXPECT_NEAR(reg.get<inertia>(e).row[2].z, scalar(0.8), 1e-6);
    EXPECT_NEAR(reg.get<AABB>(e).max.x - reg.get<AABB>(e).min.x, 2, 1e-5);

    EXPECT_THROW(rigidbody_set_shape(reg, e, shapes_variant_t{plane_shape{vector3_y, 0}}),
                 std::invalid_argument);
    EXPECT_THROW(rigidbody_set_shape(reg, e, shapes_variant_t{sphere_shape{0}}), std::invalid_argument);
    EXPECT_TRUE(reg.all_of<sphere_shape>(e)) << "a rejected shape must leave the old one";
    EXPECT_THROW(rigidbody_set_kind(reg, reg.create(), rigidbody_kind::rb_static), std::invalid_argument);
}

// The new shape's inertia is taken about the body's centre of mass, which stays put: a body
// without a center_of_mass component keeps it at its origin even where the new shape's centroid
// lies elsewhere, and gets the inertia a body made with that shape and centre would.
TEST_F(rigidbody_test, a_new_shape_s_inertia_is_about_the_centre_of_mass_that_stays) {
    // A square pyramid, base 0.6 m wide on the origin, apex 0.4 m up: its centroid is a quarter
    // of the height up. Of 2 kg, about the centroid I_xx = m (a^2 / 20 + 3 h^2 / 80) = 0.048;
    // about the base's centre 0.048 + m (h / 4)^2 = 0.068.
    auto pyramid = polyhedron_shape{std::vector<vector3>{{-scalar(0.3), 0, -scalar(0.3)},
                                                         {scalar(0.3), 0, -scalar(0.3)},
                                                         {scalar(0.3), 0, scalar(0.3)},
                                                         {-scalar(0.3), 0, scalar(0.3)},
                                                         {0, scalar(0.4), 0}}};
    auto def = valid_box();
    auto e = make_rigidbody(reg, def);
    auto origin = get_rigidbody_origin(reg, e);
    rigidbody_set_shape(reg, e, shapes_variant_t{pyramid});
    EXPECT_EQ(get_rigidbody_origin(reg, e), origin);
    EXPECT_EQ(static_cast<vector3>(reg.get<position>(e)), origin) << "the centre of mass moved";
    auto &I = reg.get<inertia>(e);
    EXPECT_NEAR(I.row[0].x, scalar(0.068), 1e-5);
    EXPECT_NEAR(I.row[1].y, scalar(2) * scalar(0.36) / 10, 1e-5) << "I_yy = m a^2 / 10 about the axis";
    EXPECT_NEAR(I.row[2].z, scalar(0.068), 1e-5);

    def.shape = pyramid;
    def.center_of_mass = vector3_zero;
    auto made = make_rigidbody(reg, def);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(I[i][j], reg.get<inertia>(made)[i][j], 1e-6) << i << ", " << j;
    // Setting the centre of mass where it already is changes nothing.
    auto before = static_cast<matrix3x3>(I);
    set_center_of_mass(reg, e, vector3_zero);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(reg.get<inertia>(e)[i][j], before[i][j], 1e-6) << i << ", " << j;
}

// A body kept static or kinematic for a while comes back with its mass, and with the inertia of
// the shape and centre of mass it has when it becomes dynamic again, not of those it had when it
// stopped being dynamic.
TEST_F(rigidbody_test, a_shape_or_centre_given_while_not_dynamic_is_the_one_it_comes_back_with) {
    auto e = make_rigidbody(reg, valid_box());
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_kinematic);
    rigidbody_set_shape(reg, e, shapes_variant_t{sphere_shape{1}});
    EXPECT_EQ(reg.get<mass_inv>(e).s, 0) << "a kinematic body stays of infinite mass";
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic);
    // A sphere of radius 1 and mass 2: I = 2/5 m r^2 = 0.8 about every axis.
    EXPECT_EQ(reg.get<mass>(e).s, 2);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(reg.get<inertia>(e)[i][i], scalar(0.8), 1e-6) << i;

    // The centre of mass moved 0.5 m along x while static: about it, I_yy = I_zz = 0.8 + 2 * 0.5^2.
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_static);
    set_center_of_mass(reg, e, {scalar(0.5), 0, 0});
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic);
    auto &I = reg.get<inertia>(e);
    EXPECT_NEAR(I.row[0].x, scalar(0.8), 1e-6);
    EXPECT_NEAR(I.row[1].y, scalar(1.3), 1e-6);
    EXPECT_NEAR(I.row[2].z, scalar(1.3), 1e-6);
    EXPECT_NEAR(reg.get<inertia_world_inv>(e).row[1].y, 1 / scalar(1.3), 1e-6);

    // The same as a body made that way.
    auto def = valid_box();
    def.shape = sphere_shape{1};
    def.center_of_mass = vector3{scalar(0.5), 0, 0};
    auto made = make_rigidbody(reg, def);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(I[i][j], reg.get<inertia>(made)[i][j], 1e-6) << i << ", " << j;

    // A mass changed while dynamic is the one kept; a shape removed while kinematic keeps the
    // inertia the body had.
    rigidbody_set_mass(reg, e, 4);
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_kinematic);
    rigidbody_set_shape(reg, e, std::nullopt);
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic);
    EXPECT_EQ(reg.get<mass>(e).s, 4);
    EXPECT_NEAR(reg.get<inertia>(e).row[1].y, scalar(2.6), 1e-5);
}

// A body that was never dynamic gets 1 kg and its shape's inertia about the centre of mass it
// keeps, its origin here, not about the shape's centroid.
TEST_F(rigidbody_test, a_body_never_dynamic_takes_its_shape_s_inertia_about_its_centre_of_mass) {
    // The square pyramid of the test above, 1 kg: about its base's centre I_xx = 0.048 / 2 + (0.1)^2.
    auto def = valid_box();
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = polyhedron_shape{std::vector<vector3>{{-scalar(0.3), 0, -scalar(0.3)},
                                                      {scalar(0.3), 0, -scalar(0.3)},
                                                      {scalar(0.3), 0, scalar(0.3)},
                                                      {-scalar(0.3), 0, scalar(0.3)},
                                                      {0, scalar(0.4), 0}}};
    auto e = make_rigidbody(reg, def);
    rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic);
    EXPECT_FALSE(reg.all_of<center_of_mass>(e)) << "the centre of mass stays at the origin";
    EXPECT_EQ(reg.get<mass>(e).s, 1);
    EXPECT_NEAR(reg.get<inertia>(e).row[0].x, scalar(0.034), 1e-5);
    EXPECT_NEAR(reg.get<inertia>(e).row[1].y, scalar(0.036), 1e-5);
    EXPECT_NEAR(reg.get<inertia>(e).row[2].z, scalar(0.034), 1e-5);
}

TEST(rigidbody, a_shape_ref_reaches_the_body_s_shape_component) {
    registry reg;
    std::vector<shapes_variant_t> shapes{sphere_shape{scalar(0.5)}, box_shape{vector3{1, 2, 3}},
                                         cylinder_shape{scalar(0.5), 1, coordinate_axis::z},
                                         capsule_shape{scalar(0.25), 1, coordinate_axis::x}};
    for (auto &shape : shapes) {
        rigidbody_def def;
        def.shape = shape;
        auto e = make_rigidbody(reg, def);
        auto ref = get_shape_ref(reg, e);
        EXPECT_EQ(ref.index, reg.get<shape_index>(e).value);
        EXPECT_EQ(ref.index, shape.index());
        // Visiting through the ref sees the component itself, as visiting through the registry.
        auto address = visit_shape(ref, [](const auto &s) { return static_cast<const void *>(&s); });
        EXPECT_EQ(address, ref.shape);
        EXPECT_EQ(address, visit_shape(reg, e, [](const auto &s) { return static_cast<const void *>(&s); }));
        std::visit([&](const auto &s) { EXPECT_EQ(ref.shape, &reg.get<std::decay_t<decltype(s)>>(e)); },
                   shape);
    }
}
