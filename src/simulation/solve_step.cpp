#include "edyn/simulation/solve_step.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/dynamics/integration.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/simulation/island.hpp"

namespace edyn {

namespace {

// Axes about which a contact resists rolling: both tangents for spheres and capsules, only the
// main axis for cylinders, none for shapes that do not roll.
std::uint32_t roll_axes(const registry &registry, entity body, const vector3 &normal, vector3 (&axes)[2]) {
    if (!registry.all_of<shape_index>(body)) return 0;
    return visit_shape(registry, body, [&](const auto &shape) -> std::uint32_t {
        using S = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<S, sphere_shape> || std::is_same_v<S, capsule_shape>) {
            plane_space(normal, axes[0], axes[1]);
            return 2;
        } else if constexpr (std::is_same_v<S, cylinder_shape>) {
            auto axis =
                project_plane(coordinate_axis_vector(shape.axis, registry.get<orientation>(body)), normal);
            if (!try_normalize(axis)) return 0;
            axes[0] = axis;
            return 1;
        } else {
            return 0;
        }
    });
}

} // namespace

void gather_bodies(registry &registry, world_state &world, const settings &settings) {
    world.bodies.clear();
    world.body_entities.clear();
    world.bodies.emplace_back();
    world.body_entities.push_back(null);

    auto view = registry.view<rigidbody_tag, linvel, angvel, mass_inv, inertia_world_inv>(
        exclude<sleeping_tag, static_tag>);
    for (auto e : view) {
        auto index = to_index(e);
        if (world.body_index.size() <= index) world.body_index.resize(index + 1, 0);
        world.body_index[index] = std::uint32_t(world.bodies.size());
        world.body_entities.push_back(e);

        solver_body body;
        body.linvel = view.get<linvel>(e);
        body.angvel = view.get<angvel>(e);
        body.inv_mass = view.get<mass_inv>(e).s;
        body.inv_inertia = view.get<inertia_world_inv>(e);
        if (registry.all_of<dynamic_tag>(e)) {
            auto *g = registry.try_get<gravity>(e);
            body.acceleration = g ? static_cast<vector3>(*g) : settings.gravity;
        }
        world.bodies.push_back(body);
    }
}

namespace {

// Bodies resting against a moving kinematic body must not fall asleep, nor stay asleep.
void wake_bodies_on_moving_kinematics(registry &registry, world_state &world) {
    for (auto manifold_entity : world.manifolds) {
        auto &manifold = registry.get<contact_manifold>(manifold_entity);
        if (manifold.num_points == 0) continue;
        auto a = manifold.body[0], b = manifold.body[1];
        for (auto [body, other] : {std::pair{a, b}, std::pair{b, a}}) {
            if (registry.all_of<kinematic_tag>(other) && (registry.get<linvel>(other) != vector3_zero ||
                                                          registry.get<angvel>(other) != vector3_zero)) {
                world.islands.wake_entity(registry, body);
            }
        }
    }
}

void gather_contact(registry &registry, world_state &world, entity manifold_entity,
                    const contact_manifold &manifold) {
    if (manifold.num_points == 0) return;
    auto a = manifold.body[0], b = manifold.body[1];
    auto *matA = registry.try_get<material>(a);
    auto *matB = registry.try_get<material>(b);
    if (!matA || !matB) return; // a sensor
    auto ia = body_index_of(world.body_index, a), ib = body_index_of(world.body_index, b);
    if (ia == 0 && ib == 0) return;

    auto mixed = get_mixed_material(registry, *matA, *matB);
    // The narrowphase left the pivots in world space; offsets are from the centres of mass.
    auto &posA = registry.get<position>(a), &posB = registry.get<position>(b);

    contact_solver_constraint c;
    c.body[0] = ia;
    c.body[1] = ib;
    c.friction = mixed.friction;
    c.restitution = mixed.restitution;
    c.roll_friction = mixed.roll_friction;
    c.spin_friction = mixed.spin_friction;
    c.stiffness = mixed.stiffness;
    c.damping = mixed.damping;
    c.normal = manifold.point[manifold.ids[0]].normal;
    c.source = std::uint32_t(world.contact_manifolds.size());

    scalar spin_impulse = 0;
    std::array<scalar, 2> roll_impulse{0, 0};
    auto *points = world.contacts.add(c, manifold.num_points);
    for (std::uint32_t i = 0; i < manifold.num_points; ++i) {
        auto &cp = manifold.point[manifold.ids[i]];
        auto &p = points[i];
        p.rA = cp.positionA - posA;
        p.rB = cp.positionB - posB;
        p.normal = cp.normal;
        p.adjusted_separation = cp.distance - dot(cp.normal, p.rA - p.rB);
        p.normal_impulse = cp.warm_start.normal;
        p.tangent_impulse[0] = cp.warm_start.friction[0];
        p.tangent_impulse[1] = cp.warm_start.friction[1];
        spin_impulse += cp.warm_start.spin;
        roll_impulse[0] += cp.warm_start.roll[0];
        roll_impulse[1] += cp.warm_start.roll[1];
    }
    auto &added = world.contacts.constraints.back();
    added.spin_impulse = spin_impulse;
    if (added.roll_friction > 0) {
        added.num_roll_axes = roll_axes(registry, a, added.normal, added.roll_axis);
        if (added.num_roll_axes == 0)
            added.num_roll_axes = roll_axes(registry, b, added.normal, added.roll_axis);
        added.roll_impulse[0] = roll_impulse[0];
        added.roll_impulse[1] = roll_impulse[1];
    }
    world.contact_manifolds.push_back(manifold_entity);
}

} // namespace

void gather_contacts(registry &registry, world_state &world) {
    world.contacts.clear();
    world.contact_manifolds.clear();
    wake_bodies_on_moving_kinematics(registry, world);

    // Island by island, so that each island's rows lie together in the arrays.
    for (auto island_entity : registry.view<island>(exclude<sleeping_tag>)) {
        for (auto edge : registry.get<island>(island_entity).edges) {
            if (auto *manifold = registry.try_get<contact_manifold>(edge)) {
                gather_contact(registry, world, edge, *manifold);
            }
        }
    }
}

void solve_constraints(world_state &world, const settings &settings) {
    auto dt = settings.fixed_dt;
    auto substeps = std::max(settings.num_substeps, 1u);
    auto h = dt / scalar(substeps);
    std::span<solver_body> bodies(world.bodies);
    auto &contacts = world.contacts;

    auto biased = make_constraint_solve_context(settings.joint, h, true);
    auto relax = make_constraint_solve_context(settings.joint, h, false);

    prepare_contacts(contacts, bodies);

    for (unsigned i = 0; i < substeps; ++i) {
        integrate_velocities(bodies, h);
        solve_restitution(contacts, bodies, settings.contact, h, settings.num_restitution_iterations,
                          settings.num_individual_restitution_iterations);
        // Joints before contacts in each pass: contacts, solved last, keep bodies apart.
        warm_start_constraints(world.joints, bodies);
        warm_start_contacts(contacts, bodies);
        solve_joint_constraints(world.joints, bodies, biased);
        solve_contacts(contacts, bodies, h, settings.contact, true);
        integrate_positions(bodies, h);
        project_joint_positions(world.joints, bodies, settings.joint);
        for (unsigned k = 0; k < settings.num_relax_iterations; ++k) {
            solve_joint_constraints(world.joints, bodies, relax);
            solve_contacts(contacts, bodies, h, settings.contact, false);
        }
        accumulate_contact_impulses(contacts);
    }
}

namespace {

// Bodies or contacts per parallel range in write_back.
constexpr std::size_t write_backs_per_task = 256;

} // namespace

void write_back(registry &registry, world_state &world, scalar dt) {
    // Each body and each contact writes only its own components: they go back in parallel.
    parallel_for(world.scheduler.get(), std::size_t(1), world.bodies.size(), write_backs_per_task,
                 [&](std::size_t i) {
                     auto e = world.body_entities[i];
                     auto &body = world.bodies[i];
                     auto &pos = registry.get<position>(e);
                     auto &orn = registry.get<orientation>(e);
                     pos += body.delta_position;
                     orn = normalize(body.delta_rotation * orn);
                     registry.get<linvel>(e) = body.linvel;
                     registry.get<angvel>(e) = body.angvel;

                     if (registry.all_of<dynamic_tag>(e)) {
                         auto r = to_matrix3x3(orn);
                         registry.get<inertia_world_inv>(e) = r * registry.get<inertia_inv>(e) * transpose(r);
                     }
                     if (auto *aabb = registry.try_get<AABB>(e)) {
                         auto origin = get_rigidbody_origin(registry, e);
                         *aabb = visit_shape(
                             registry, e, [&](const auto &shape) { return shape_aabb(shape, origin, orn); });
                         // Swept over the next step's motion, so that pairs are found before they touch.
                         auto sweep = body.linvel * dt;
                         aabb->min += min(sweep, vector3_zero);
                         aabb->max += max(sweep, vector3_zero);
                     }
                     world.body_index[to_index(e)] = 0;
                 });

    auto &constraints = world.contacts.constraints;
    parallel_for(
        world.scheduler.get(), std::size_t(0), constraints.size(), write_backs_per_task, [&](std::size_t k) {
            auto &c = constraints[k];
            auto &manifold = registry.get<contact_manifold>(world.contact_manifolds[c.source]);
            for (std::uint32_t i = 0; i < c.num_points; ++i) {
                auto &p = world.contacts.points[c.first_point + i];
                auto &t = world.contacts.totals[c.first_point + i];
                auto &cp = manifold.point[manifold.ids[i]];
                auto share = scalar(1) / scalar(c.num_points);
                cp.warm_start.normal = p.normal_impulse;
                cp.warm_start.friction = {p.tangent_impulse[0], p.tangent_impulse[1]};
                cp.warm_start.spin = c.spin_impulse * share;
                cp.warm_start.roll = {c.roll_impulse[0] * share, c.roll_impulse[1] * share};
                cp.normal_impulse = t.normal_impulse;
                cp.friction_impulse = {t.tangent_impulse[0], t.tangent_impulse[1]};
                cp.normal_restitution_impulse = t.restitution_impulse;
                cp.friction_restitution_impulse = {t.tangent_restitution_impulse[0],
                                                   t.tangent_restitution_impulse[1]};
                // Torsional and rolling impulses are shared evenly by the points for reporting.
                cp.spin_friction_impulse = c.total_spin_impulse * share;
                cp.roll_friction_impulse = {c.total_roll_impulse[0] * share, c.total_roll_impulse[1] * share};
            }
        });
    store_constraint_impulses(registry, world.joints);
}

} // namespace edyn
