#include "edyn/simulation/solve_step.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/config/prefetch.hpp"
#include "edyn/constraints/constraint_colouring.hpp"
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
#include <algorithm>

namespace edyn {

namespace {

// Axes about which a contact resists rolling: both tangents for spheres and capsules, only the
// main axis for cylinders, none for shapes that do not roll.
std::uint32_t roll_axes(world_state::rolling rolls, const quaternion &orientation, const vector3 &normal,
                        vector3 (&axes)[2]) {
    using rolling = world_state::rolling;
    switch (rolls) {
    case rolling::both_tangents:
        plane_space(normal, axes[0], axes[1]);
        return 2;
    case rolling::about_x:
    case rolling::about_y:
    case rolling::about_z: {
        auto main =
            static_cast<coordinate_axis>(static_cast<int>(rolls) - static_cast<int>(rolling::about_x));
        auto axis = project_plane(coordinate_axis_vector(main, orientation), normal);
        if (!try_normalize(axis)) return 0;
        axes[0] = axis;
        return 1;
    }
    case rolling::none:
        break;
    }
    return 0;
}

// Bodies per parallel range in gather_bodies.
constexpr std::size_t gathered_bodies_per_task = 256;

} // namespace

void gather_bodies(registry &registry, world_state &world, const settings &settings) {
    // The bodies in the view's order, which numbers them: whether each candidate of the view
    // belongs to it is looked up on the scheduler's threads, and those that do are listed here in
    // the order the view walks them...
    auto view = registry.view<rigidbody_tag, linvel, angvel, mass_inv, inertia_world_inv>(
        exclude<sleeping_tag, static_tag>);
    auto &candidates = view.handle();
    auto num_candidates = candidates.size();
    world.body_candidates.resize(num_candidates);
    parallel_for(world.step_scheduler, std::size_t(0), num_candidates, gathered_bodies_per_task,
                 [&](std::size_t i) { world.body_candidates[i] = view.contains(candidates.data()[i]); });
    world.body_entities.clear();
    world.body_entities.push_back(null);
    std::size_t index_bound = 0;
    for (auto i = num_candidates; i-- > 0;) {
        if (!world.body_candidates[i]) continue;
        auto e = candidates.data()[i];
        world.body_entities.push_back(e);
        index_bound = std::max(index_bound, std::size_t(to_index(e)) + 1);
    }
    if (world.body_index.size() < index_bound) world.body_index.resize(index_bound, 0);
    // (Resized from last step's size, not cleared first: growth stays geometric.) The first is
    // the static body, which every body that does not move shares.
    world.bodies.resize(world.body_entities.size());
    world.bodies[0] = solver_body{};

    // ...then each body's state, at once on the scheduler's threads.
    auto fill = [&](std::size_t i) {
        auto e = world.body_entities[i];
        world.body_index[to_index(e)] = std::uint32_t(i);
        auto &body = world.bodies[i];
        body = solver_body{};
        body.linvel = view.get<linvel>(e);
        body.angvel = view.get<angvel>(e);
        body.inv_mass = view.get<mass_inv>(e).s;
        body.inv_inertia = view.get<inertia_world_inv>(e);
        if (registry.all_of<dynamic_tag>(e)) {
            auto *g = registry.try_get<gravity>(e);
            body.acceleration = g ? static_cast<vector3>(*g) : settings.gravity;
            // Once a step, before the constraints: its torque turns the angular velocity with
            // the body, so that the angular momentum is what a free body keeps.
            body.angvel = gyroscopic_step(body.angvel, registry.get<inertia>(e), registry.get<orientation>(e),
                                          settings.fixed_dt);
        }
    };
    parallel_for(world.step_scheduler, std::size_t(1), world.bodies.size(), gathered_bodies_per_task, fill);
}

namespace {

// The solver bodies and point count of the contact an island edge stands for; no points when
// the edge is not a contact to solve (a joint, a manifold without points, a sensor's, or one
// between two bodies that do not move).
world_state::edge_contact contact_of_edge(const storage<contact_manifold> &manifold_pool,
                                          const world_state &world, entity edge) {
    auto *manifold = manifold_pool.try_get(edge);
    if (!manifold || manifold->num_points == 0) return {};
    auto a = manifold->body[0], b = manifold->body[1];
    if (!world.contact_bodies[to_index(a)].mat || !world.contact_bodies[to_index(b)].mat)
        return {}; // a sensor
    auto ia = body_index_of(world.body_index, a), ib = body_index_of(world.body_index, b);
    if (ia == static_solver_body && ib == static_solver_body) return {};
    return {{ia, ib}, manifold->num_points, static_cast<std::uint32_t>(manifold_pool.index(edge))};
}

// Fills the constraint the manifold `source` was given a place for, and its points, from the
// manifold, the mixed material and last step's impulses. Reads what the narrowphase gathered of
// the bodies (world_state::collision_body), not the registry, and writes only the constraint
// and its points: manifolds are gathered at once on the scheduler's threads.
void gather_contact(const storage<contact_manifold> &manifold_pool, const material_mix_table *mix_table,
                    world_state &world, std::uint32_t source) {
    auto &place = world.contact_places[source];
    auto &manifold = manifold_pool.value_at(place.slot);
    auto a = manifold.body[0], b = manifold.body[1];
    auto &bodyA = world.collision_bodies[to_index(a)], &bodyB = world.collision_bodies[to_index(b)];
    auto &contactA = world.contact_bodies[to_index(a)], &contactB = world.contact_bodies[to_index(b)];
    auto mixed = get_mixed_material(mix_table, *contactA.mat, *contactB.mat);
    // The narrowphase left the pivots in world space; offsets are from the centres of mass.
    auto &posA = contactA.centre, &posB = contactB.centre;

    auto &c = world.contacts.constraints[place.constraint];
    c.first_point = place.first_point;
    c.num_points = place.num_points;
    c.body[0] = body_index_of(world.body_index, a);
    c.body[1] = body_index_of(world.body_index, b);
    c.friction = mixed.friction;
    c.restitution = mixed.restitution;
    c.roll_friction = mixed.roll_friction;
    c.spin_friction = mixed.spin_friction;
    c.stiffness = mixed.stiffness;
    c.damping = mixed.damping;
    c.normal = manifold.point[manifold.ids[0]].normal;
    c.source = source;
    c.held = place.held;
    if (bodyA.point_materials || bodyB.point_materials) {
        // The points' own values (the narrowphase interpolated them), averaged over the manifold
        // whose friction and restitution the solver shares between its points.
        scalar friction = 0, restitution = 0;
        for (std::uint32_t i = 0; i < manifold.num_points; ++i) {
            friction += manifold.point[manifold.ids[i]].friction;
            restitution += manifold.point[manifold.ids[i]].restitution;
        }
        c.friction = friction / scalar(manifold.num_points);
        c.restitution = restitution / scalar(manifold.num_points);
    }

    c.spin_impulse = 0;
    c.roll_impulse[0] = c.roll_impulse[1] = 0;
    for (std::uint32_t i = 0; i < c.num_points; ++i) {
        auto &cp = manifold.point[manifold.ids[i]];
        // Not cleared first: prepare_contacts() or the point's bundle makes every field not set
        // here (clearing each point, 256 bytes in single precision, took a third of this
        // function's time in the 20-wide pyramid).
        auto &p = world.contacts.points[c.first_point + i];
        p.rA = cp.positionA - posA;
        p.rB = cp.positionB - posB;
        p.normal = cp.normal;
        p.adjusted_separation = cp.distance - dot(cp.normal, p.rA - p.rB);
        // Static friction holds a point that has lasted where its pivots lie: the narrowphase
        // keeps them on the bodies while it reuses the pair's points (can_reuse_contacts), so how
        // far they lie apart along the surfaces is how far the surfaces slid since then. A young
        // point is held only against this step's sliding (see contact_anchor_min_lifetime).
        auto apart = cp.lifetime >= contact_anchor_min_lifetime ? cp.positionA - cp.positionB : cp.normal;
        p.adjusted_anchor_gap = (apart - cp.normal * dot(apart, cp.normal)) - (p.rA - p.rB);
        p.normal_impulse = cp.warm_start.normal;
        p.tangent_impulse[0] = cp.warm_start.friction[0];
        p.tangent_impulse[1] = cp.warm_start.friction[1];
        c.spin_impulse += cp.warm_start.spin;
        c.roll_impulse[0] += cp.warm_start.roll[0];
        c.roll_impulse[1] += cp.warm_start.roll[1];
    }
    c.num_roll_axes = 0;
    if (c.roll_friction > 0) {
        c.num_roll_axes = roll_axes(contactA.rolls, bodyA.orientation, c.normal, c.roll_axis);
        if (c.num_roll_axes == 0)
            c.num_roll_axes = roll_axes(contactB.rolls, bodyB.orientation, c.normal, c.roll_axis);
    } else {
        c.roll_impulse[0] = c.roll_impulse[1] = 0;
    }
}

// Manifolds per parallel range in gather_contacts.
constexpr std::size_t gathered_manifolds_per_task = 64;
// How many manifolds ahead gather_contacts and write_back ask for a manifold's memory (twice as
// far ahead) and, once it has come, for its bodies'.
constexpr std::uint32_t gather_prefetch_distance = 8;

// A manifold's first cache line: its bodies, point count and point ids.
void prefetch_manifold_head(const contact_manifold &manifold) { prefetch(&manifold, cache_line_size); }

// The live points of a manifold whose first line has come: gathering reads their geometry and
// warm start (their first two lines), writing back their warm start and impulses (the second).
void prefetch_gather_points(const contact_manifold &manifold) {
    for (std::uint32_t i = 0; i < manifold.num_points; ++i)
        prefetch(&manifold.point[manifold.ids[i]], 2 * cache_line_size);
}
void prefetch_write_back_points(const contact_manifold &manifold) {
    for (std::uint32_t i = 0; i < manifold.num_points; ++i)
        prefetch(&manifold.point[manifold.ids[i]].lifetime, cache_line_size);
}

// What gather_contact reads of a manifold's bodies...
void prefetch_gather_bodies(const world_state &world, const contact_manifold &manifold) {
    for (auto e : manifold.body) {
        prefetch(&world.collision_bodies[to_index(e)], sizeof(world_state::collision_body));
        prefetch(&world.contact_bodies[to_index(e)], sizeof(world_state::contact_body));
    }
}
// ...and, once those have come, their materials.
void prefetch_gather_materials(const world_state &world, const contact_manifold &manifold) {
    for (auto e : manifold.body) {
        if (auto *mat = world.contact_bodies[to_index(e)].mat) prefetch(mat, sizeof(material));
    }
}

} // namespace

namespace {

// The manifolds are taken island by island, in the order of each island's edges. What each edge
// needs from the registry is looked up at once on the scheduler's threads, a manifold asked for
// a few edges ahead.
void find_island_contacts(registry &registry, world_state &world) {
    world.island_edges.clear();
    for (auto island_entity : registry.view<island>(exclude<sleeping_tag>)) {
        auto &edges = registry.get<island>(island_entity).edges;
        world.island_edges.insert(world.island_edges.end(), edges.begin(), edges.end());
    }
    auto num_edges = static_cast<std::uint32_t>(world.island_edges.size());
    world.edge_contacts.resize(num_edges);
    auto &manifold_pool = registry.storage<contact_manifold>();
    parallel_for(world.step_scheduler, 0u, num_edges, gathered_manifolds_per_task, [&](std::uint32_t i) {
        if (i + gather_prefetch_distance < num_edges) {
            if (auto *ahead = manifold_pool.try_get(world.island_edges[i + gather_prefetch_distance])) {
                prefetch(ahead);
            }
        }
        world.edge_contacts[i] = contact_of_edge(manifold_pool, world, world.island_edges[i]);
    });
}

// The contacts to solve in the order they are solved in, outward from the bodies that do not
// move (contact_order.hpp), each given its colour in that order, on this thread: the colour
// after those of the earlier contacts it shares a moving body with. Then each manifold's place:
// colours in order, in the order found within a colour.
void place_contacts(world_state &world) {
    world.solved_edges.clear();
    world.ordering.reset(world.bodies);
    for (std::uint32_t i = 0; i < world.edge_contacts.size(); ++i) {
        auto &edge = world.edge_contacts[i];
        if (edge.num_points == 0) continue;
        world.solved_edges.push_back(i);
        world.ordering.add(edge.body[0], edge.body[1]);
    }
    world.contact_colours.clear();
    world.contact_places.clear();
    world.colouring.reset(world.bodies);
    for (auto k : world.ordering.sorted()) {
        auto &edge = world.edge_contacts[world.solved_edges[k]];
        world.contact_colours.push_back(world.colouring.assign(edge.body[0], edge.body[1], edge.num_points));
        auto da = world.ordering.depth_of(edge.body[0]), db = world.ordering.depth_of(edge.body[1]);
        auto held = da < db ? fixed_side::a : db < da ? fixed_side::b : fixed_side::none;
        world.contact_places.push_back({0, 0, edge.num_points, edge.slot, held});
    }

    auto &contacts = world.contacts;
    world.colouring.colour_ranges(contacts.colour_begin);
    contacts.constraints.resize(contacts.colour_begin.back());
    std::uint32_t num_points = 0;
    for (std::uint32_t k = 0; k < world.contact_places.size(); ++k) {
        auto &place = world.contact_places[k];
        auto found = world.colouring.next_place(world.contact_colours[k], place.num_points);
        place.constraint = found.constraint;
        place.first_point = found.first_point;
        num_points += place.num_points;
    }
    contacts.points.resize(num_points);
    contacts.totals.resize(num_points);
}

} // namespace

void gather_contacts(registry &registry, world_state &world) {
    find_island_contacts(registry, world);
    place_contacts(world);

    // Manifolds are gathered in island order, which is no order in memory: each is asked for
    // ahead, then its points and bodies, then the bodies' materials.
    auto &manifold_pool = registry.storage<contact_manifold>();
    auto *mix_table = registry.ctx().find<material_mix_table>();
    auto num_contacts = static_cast<std::uint32_t>(world.contact_places.size());
    auto manifold_of = [&](std::uint32_t k) -> auto & {
        return manifold_pool.value_at(world.contact_places[k].slot);
    };
    parallel_for(world.step_scheduler, 0u, num_contacts, gathered_manifolds_per_task, [&](std::uint32_t k) {
        if (k + 2 * gather_prefetch_distance < num_contacts)
            prefetch_manifold_head(manifold_of(k + 2 * gather_prefetch_distance));
        if (k + gather_prefetch_distance < num_contacts) {
            auto &ahead = manifold_of(k + gather_prefetch_distance);
            prefetch_gather_points(ahead);
            prefetch_gather_bodies(world, ahead);
        }
        if (k + gather_prefetch_distance / 2 < num_contacts)
            prefetch_gather_materials(world, manifold_of(k + gather_prefetch_distance / 2));
        gather_contact(manifold_pool, mix_table, world, k);
    });
}

void solve_constraints(world_state &world, const settings &settings) {
    auto dt = settings.fixed_dt;
    auto substeps = std::max(settings.num_substeps, 1u);
    auto h = dt / scalar(substeps);
    std::span<solver_body> bodies(world.bodies);
    auto &contacts = world.contacts;

    auto biased = make_constraint_solve_context(settings.joint, h, true);
    auto relax = make_constraint_solve_context(settings.joint, h, false);

    // Contacts and joints are solved colour by colour, each colour on the scheduler's threads
    // when there is one. Their passes and the integrations are queued, and the queue is handed
    // to the scheduler as one task: once per step when nothing bounces. Restitution runs its own
    // passes: the passes queued before them run first.
    auto *scheduler = world.step_scheduler;
    prepare_contacts(contacts, bodies, scheduler);
    auto &queue = world.solver_stages;
    queue.clear(); // of what a step that threw may have left
    refresh_joint_geometry(world.joints, bodies, queue);
    auto bounces = !contacts.bouncy.empty();
    auto restitution_solver =
        settings.num_restitution_iterations > 0 && settings.num_individual_restitution_iterations > 0;

    for (unsigned i = 0; i < substeps; ++i) {
        integrate_velocities(bodies, h, settings.max_linear_speed, queue);
        if (bounces) {
            queue.run(scheduler);
            if (restitution_solver) {
                solve_restitution(contacts, bodies, settings.contact, h, settings.num_restitution_iterations,
                                  settings.num_individual_restitution_iterations);
            } else {
                record_approach_speeds(contacts, bodies);
            }
        }
        // Joints before contacts in each pass: contacts, solved last, keep bodies apart.
        warm_start_constraints(world.joints, bodies, queue);
        warm_start_contacts(contacts, bodies, queue);
        solve_joint_constraints(world.joints, bodies, biased, queue);
        solve_contacts(contacts, bodies, h, i, settings.contact, true, queue);
        integrate_positions(bodies, h, queue);
        project_joint_positions(world.joints, bodies, settings.joint, queue);
        // Only integration and projection move bodies: the joints' rows measured now serve
        // every velocity pass until the next sub-step's integration.
        refresh_joint_geometry(world.joints, bodies, queue);
        for (unsigned k = 0; k < settings.num_relax_iterations; ++k) {
            solve_joint_constraints(world.joints, bodies, relax, queue);
            solve_contacts(contacts, bodies, h, i, settings.contact, false, queue);
        }
        accumulate_contact_impulses(contacts, queue);
    }
    queue.run(scheduler);
    unpack_contact_impulses(contacts, scheduler);
    if (restitution_solver) {
        solve_restitution(contacts, bodies, settings.contact, h, settings.num_restitution_iterations,
                          settings.num_individual_restitution_iterations, bounce_moment::step_end);
    } else if (bounces) {
        bounce_without_restitution_solver(contacts, bodies, settings.contact);
    }
    // The passes after the last integration (relax, restitution) may have sped bodies up again.
    limit_speeds(bodies, h, settings.max_linear_speed, queue);
    queue.run(scheduler);
}

namespace {

// Bodies or contacts per parallel range in write_back.
constexpr std::size_t write_backs_per_task = 256;

} // namespace

namespace {

// Each body writes only its own components: they go back in parallel. The pools are found once,
// here, rather than once per body and component.
void write_back_bodies(registry &registry, world_state &world, scalar dt) {
    auto &positions = registry.storage<position>();
    auto &orientations = registry.storage<orientation>();
    auto &linvels = registry.storage<linvel>();
    auto &angvels = registry.storage<angvel>();
    auto &dynamics = registry.storage<dynamic_tag>();
    auto &inertias = registry.storage<inertia_inv>();
    auto &world_inertias = registry.storage<inertia_world_inv>();
    auto &aabbs = registry.storage<AABB>();
    auto &centres = registry.storage<center_of_mass>();
    parallel_for(world.step_scheduler, std::size_t(1), world.bodies.size(), write_backs_per_task,
                 [&](std::size_t i) {
                     auto e = world.body_entities[i];
                     auto &body = world.bodies[i];
                     auto &pos = positions.get(e);
                     auto &orn = orientations.get(e);
                     pos += body.delta_position;
                     orn = normalize(body.delta_rotation * orn);
                     linvels.get(e) = body.linvel;
                     angvels.get(e) = body.angvel;

                     if (dynamics.contains(e)) {
                         auto r = to_matrix3x3(orn);
                         world_inertias.get(e) = r * inertias.get(e) * transpose(r);
                     }
                     if (auto *aabb = aabbs.try_get(e)) {
                         auto origin = rigidbody_origin(pos, orn, centres.try_get(e));
                         *aabb = visit_shape(
                             registry, e, [&](const auto &shape) { return shape_aabb(shape, origin, orn); });
                         // Swept over the next step's motion, so that pairs are found before they touch.
                         auto sweep = body.linvel * dt;
                         aabb->min += min(sweep, vector3_zero);
                         aabb->max += max(sweep, vector3_zero);
                     }
                     world.body_index[to_index(e)] = 0;
                 });
}

// Each contact writes only its own manifold's points: they go back in parallel.
void write_back_contacts(registry &registry, world_state &world) {
    auto &constraints = world.contacts.constraints;
    auto &manifold_pool = registry.storage<contact_manifold>();
    parallel_for(
        world.step_scheduler, std::size_t(0), constraints.size(), write_backs_per_task, [&](std::size_t k) {
            if (k + 2 * gather_prefetch_distance < constraints.size()) {
                auto ahead = world.contact_places[constraints[k + 2 * gather_prefetch_distance].source].slot;
                prefetch_manifold_head(manifold_pool.value_at(ahead));
            }
            if (k + gather_prefetch_distance < constraints.size()) {
                auto ahead = world.contact_places[constraints[k + gather_prefetch_distance].source].slot;
                prefetch_write_back_points(manifold_pool.value_at(ahead));
            }
            auto &c = constraints[k];
            auto &manifold = manifold_pool.value_at(world.contact_places[c.source].slot);
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
}

} // namespace

void write_back(registry &registry, world_state &world, scalar dt) {
    write_back_bodies(registry, world, dt);
    write_back_contacts(registry, world);
    store_constraint_impulses(registry, world.joints);
}

} // namespace edyn
