#include "edyn/constraints/contact_solver.hpp"
#include "contact_bundle_solver.hpp"
#include "edyn/constraints/constraint_row.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace edyn {

namespace {

std::span<contact_solver_point> points_of(contact_solver_set &contacts, const contact_solver_constraint &c) {
    return std::span(contacts.points).subspan(c.first_point, c.num_points);
}

contact_row make_row(const solver_body &a, const solver_body &b, const vector3 &d, const vector3 &rA,
                     const vector3 &rB) {
    contact_row row;
    row.angularA = cross(rA, d);
    row.angularB = cross(rB, d);
    row.inv_angularA = a.inv_inertia * row.angularA;
    row.inv_angularB = b.inv_inertia * row.angularB;
    return row;
}

// Effective mass of the row (kg); 0 when neither body can move along it. The row's angular
// parts are the products an effective mass needs: they are not worked out twice.
scalar row_mass(const solver_body &a, const solver_body &b, const contact_row &row) {
    auto k =
        a.inv_mass + b.inv_mass + dot(row.angularA, row.inv_angularA) + dot(row.angularB, row.inv_angularB);
    return k > 0 ? scalar(1) / k : scalar(0);
}

// Effective mass of the row for the body that is not held (kg): what the row's impulse moves
// when the other body is held still; 0 when that body cannot move along it.
scalar held_row_mass(const contact_row &row, const solver_body &a, const solver_body &b, fixed_side held) {
    auto k = held == fixed_side::a ? b.inv_mass + dot(row.angularB, row.inv_angularB)
                                   : a.inv_mass + dot(row.angularA, row.inv_angularA);
    return k > 0 ? scalar(1) / k : scalar(0);
}

// Relative velocity of the row's points along d.
template<fixed_side F>
inline scalar row_velocity(const contact_row &row, const vector3 &d, const solver_body &a,
                           const solver_body &b) {
    if constexpr (F == fixed_side::b) {
        return dot(d, a.linvel) + dot(row.angularA, a.angvel);
    } else if constexpr (F == fixed_side::a) {
        return -(dot(d, b.linvel) + dot(row.angularB, b.angvel));
    } else {
        return dot(d, a.linvel - b.linvel) + dot(row.angularA, a.angvel) - dot(row.angularB, b.angvel);
    }
}

// Applies `impulse` along the row: +impulse d to A, -impulse d to B (not to the static side).
template<fixed_side F>
inline void apply_row(const contact_row &row, const vector3 &d, scalar impulse, solver_body &a,
                      solver_body &b) {
    if constexpr (F != fixed_side::a) {
        a.linvel += d * (a.inv_mass * impulse);
        a.angvel += row.inv_angularA * impulse;
    }
    if constexpr (F != fixed_side::b) {
        b.linvel -= d * (b.inv_mass * impulse);
        b.angvel -= row.inv_angularB * impulse;
    }
}

// Coulomb's law in every direction along the surface. `impulse` is the pair of new impulses
// along two orthogonal rows, each worked out with its own row's mass, and `shared` the same pair
// worked out with one mass for both (their mean). While `impulse` lies in the disc of radius
// `limit` the surfaces stick and it stands. Outside, they slide: the pair goes to the disc's
// edge, in the direction of `shared`. Repeated pass after pass, that step leaves the friction
// opposite the slip, where the rows' own masses would turn it towards the lighter row; and
// limiting each row alone would let a slide across both rows take up to sqrt(2) times the force.
// contact_bundle_solver.cpp does the same operations lane by lane, for the same bits.
inline void limit_to_disc(scalar (&impulse)[2], const scalar (&shared)[2], scalar limit) {
    auto length2 = impulse[0] * impulse[0] + impulse[1] * impulse[1];
    if (!(limit * limit < length2)) return;
    auto shared2 = shared[0] * shared[0] + shared[1] * shared[1];
    auto use_shared = scalar(0) < shared2;
    auto x = use_shared ? shared[0] : impulse[0];
    auto y = use_shared ? shared[1] : impulse[1];
    auto scale = limit / std::sqrt(use_shared ? shared2 : length2);
    impulse[0] = x * scale;
    impulse[1] = y * scale;
}

// Calls fn with the constraint's fixed side as a std::integral_constant.
template<typename Fn>
decltype(auto) with_fixed_side(const contact_solver_constraint &c, Fn &&fn) {
    switch (detail::fixed_side_of(c)) {
    case fixed_side::a:
        return fn(std::integral_constant<fixed_side, fixed_side::a>{});
    case fixed_side::b:
        return fn(std::integral_constant<fixed_side, fixed_side::b>{});
    default:
        return fn(std::integral_constant<fixed_side, fixed_side::none>{});
    }
}

// Constraints per parallel range: enough work to outweigh handing a range to a thread.
constexpr std::uint32_t contacts_per_task = 64;
// Bundles or single constraints per block of a colour: about this many blocks per thread, so
// that the threads finish a colour close together, but blocks no smaller than this, so that
// taking one costs little beside its work, nor larger.
constexpr std::uint32_t colour_blocks_per_thread = 4;
constexpr std::uint32_t min_colour_block_items = 4;
constexpr std::uint32_t max_colour_block_items = 32;

// Number of bundles and single constraints of colour k.
std::uint32_t colour_items(const contact_solver_set &contacts, std::size_t k) {
    return contacts.bundle_begin[k + 1] - contacts.bundle_begin[k] + contacts.single_begin[k + 1] -
           contacts.single_begin[k];
}

// Cuts every colour's items into blocks for `threads` threads, numbered colour after colour:
// colour k's blocks are [block_begin[k], block_begin[k + 1]), of block_items[k] items each
// (the last may have fewer). The cut changes which thread solves what, never the result.
void number_colour_blocks(contact_solver_set &contacts, std::uint32_t threads) {
    contacts.block_begin.clear();
    contacts.block_items.clear();
    std::uint32_t blocks = 0;
    for (std::size_t k = 0; k + 1 < contacts.bundle_begin.size(); ++k) {
        auto items = colour_items(contacts, k);
        auto wanted = threads * colour_blocks_per_thread;
        auto size = std::clamp((items + wanted - 1) / wanted, min_colour_block_items, max_colour_block_items);
        contacts.block_begin.push_back(blocks);
        contacts.block_items.push_back(size);
        blocks += (items + size - 1) / size;
    }
    contacts.block_begin.push_back(blocks);
}

// Queues bundle(i) for every bundle i and single(k) for every constraint k solved on its own,
// colour after colour, each colour a stage whose blocks may run at once on different threads;
// then the overflow, in order, as a stage of one block. Both functions are copied into the queue.
// Before each bundle of a block, the bodies of the block's next bundle are asked for: a bundle's
// sixteen bodies lie anywhere in `bodies` (and, on more than one thread, often in another core's
// cache, written there by the colour before), so their loads otherwise stall the bundle's start.
template<typename Bundle, typename Single>
void queue_in_colour_order(const contact_solver_set &contacts, std::span<const solver_body> bodies,
                           stage_queue &queue, Bundle bundle, Single single) {
    for (std::uint32_t k = 0; k + 1 < contacts.block_begin.size(); ++k) {
        auto block = [&contacts, bodies, k, bundle, single](std::uint32_t b) {
            auto num_bundles = contacts.bundle_begin[k + 1] - contacts.bundle_begin[k];
            auto first = b * contacts.block_items[k];
            auto last = std::min(first + contacts.block_items[k], colour_items(contacts, k));
            for (auto i = first; i < last; ++i) {
                if (i < num_bundles) {
                    if (i + 1 < last && i + 1 < num_bundles)
                        detail::prefetch_bundle_bodies(contacts, contacts.bundle_begin[k] + i + 1, bodies);
                    bundle(contacts.bundle_begin[k] + i);
                } else {
                    single(contacts.singles[contacts.single_begin[k] + i - num_bundles]);
                }
            }
        };
        queue.add(contacts.block_begin[k + 1] - contacts.block_begin[k], block);
    }
    auto &begin = contacts.colour_begin;
    auto overflow = begin.empty() ? 0u : begin.back();
    if (overflow < contacts.constraints.size()) {
        queue.add(1, [&contacts, overflow, single](std::uint32_t) {
            for (auto k = overflow; k < contacts.constraints.size(); ++k)
                single(k);
        });
    }
}

// The body a constraint solves against: a body that moves is changed in place; one that does
// not (the static body, a kinematic body) may be read by many constraints of one colour at once,
// so each works on its own copy, which is dropped.
inline solver_body &solved(solver_body &body, solver_body &copy) {
    if (moves(body)) return body;
    copy = body;
    return copy;
}

} // namespace

contact_solver_point *contact_solver_set::add(const contact_solver_constraint &c, std::uint32_t num_points) {
    auto &added = constraints.emplace_back(c);
    added.first_point = std::uint32_t(points.size());
    added.num_points = num_points;
    points.resize(points.size() + num_points);
    totals.resize(points.size());
    return &points[added.first_point];
}

void prepare_contacts(contact_solver_set &contacts, std::span<const solver_body> bodies,
                      task_scheduler *scheduler) {
    // Each constraint writes only its own points and key: any order will do.
    auto count = static_cast<std::uint32_t>(contacts.constraints.size());
    contacts.pack_keys.resize(count);
    parallel_for(scheduler, 0u, count, contacts_per_task, [&](std::uint32_t k) {
        auto &c = contacts.constraints[k];
        contacts.pack_keys[k] = detail::pack_key(c);
        auto &a = bodies[c.body[0]];
        auto &b = bodies[c.body[1]];
        // A bundled point's rows are made in its bundle (fill_bundle), eight or four at a time.
        auto own_rows = !detail::rows_made_in_bundle(contacts, k);
        for (auto i = c.first_point; i < c.first_point + c.num_points; ++i) {
            auto &p = contacts.points[i];
            // Of the levers' parts across the normal only: the foot of a rolling body's lever
            // stays below its centre, and its part along the normal would give a ball rolling
            // with side spin a slip it does not have.
            auto across_A = project_plane(p.rA, p.normal);
            auto across_B = project_plane(p.rB, p.normal);
            p.path_acceleration =
                cross(a.angvel, cross(a.angvel, across_A)) - cross(b.angvel, cross(b.angvel, across_B));
            if (own_rows) {
                plane_space(p.normal, p.tangent[0], p.tangent[1]);
                p.normal_row = make_row(a, b, p.normal, p.rA, p.rB);
                p.tangent_row[0] = make_row(a, b, p.tangent[0], p.rA, p.rB);
                p.tangent_row[1] = make_row(a, b, p.tangent[1], p.rA, p.rB);
                p.normal_mass = row_mass(a, b, p.normal_row);
                p.tangent_mass[0] = row_mass(a, b, p.tangent_row[0]);
                p.tangent_mass[1] = row_mass(a, b, p.tangent_row[1]);
            }
            contacts.totals[i] = {};
            contacts.totals[i].relative_velocity = dot(p.normal, relative_velocity(a, b, p.rA, p.rB));
        }

        c.total_spin_impulse = 0;
        c.total_roll_impulse[0] = c.total_roll_impulse[1] = 0;
        c.spin_mass = c.spin_friction > 0 ? effective_angular_mass(a, b, c.normal) : scalar(0);
        for (std::uint32_t i = 0; i < c.num_roll_axes; ++i) {
            c.roll_mass[i] = effective_angular_mass(a, b, c.roll_axis[i]);
        }
    });
    detail::pack_contact_bundles(contacts, bodies, scheduler);
    number_colour_blocks(contacts, scheduler ? scheduler->concurrency() : 1u);

    contacts.bouncy.clear();
    for (std::uint32_t k = 0; k < count; ++k) {
        if (contacts.pack_keys[k] & detail::bouncy_key) contacts.bouncy.push_back(k);
    }
}

void warm_start_contacts(contact_solver_set &contacts, std::span<solver_body> bodies, stage_queue &queue) {
    auto bundle = [&contacts, bodies](std::uint32_t i) { detail::warm_start_bundle(contacts, i, bodies); };
    auto single = [&contacts, bodies](std::uint32_t k) {
        auto &c = contacts.constraints[k];
        solver_body copies[2];
        auto &a = solved(bodies[c.body[0]], copies[0]);
        auto &b = solved(bodies[c.body[1]], copies[1]);

        with_fixed_side(c, [&](auto side) {
            for (auto &p : points_of(contacts, c)) {
                apply_row<side()>(p.normal_row, p.normal, p.normal_impulse, a, b);
                apply_row<side()>(p.tangent_row[0], p.tangent[0], p.tangent_impulse[0], a, b);
                apply_row<side()>(p.tangent_row[1], p.tangent[1], p.tangent_impulse[1], a, b);
            }
        });

        // Without spinning or rolling impulses there is nothing to apply (and a bundle, which
        // has none, applies nothing either).
        if (c.spin_impulse == 0 && c.num_roll_axes == 0) return;
        auto angular = c.normal * c.spin_impulse;
        for (std::uint32_t i = 0; i < c.num_roll_axes; ++i) {
            angular += c.roll_axis[i] * c.roll_impulse[i];
        }
        apply_angular_impulse(a, b, angular);
    };
    queue_in_colour_order(contacts, bodies, queue, bundle, single);
}

namespace {

// A contact's lever turned by the body's rotation since the step began: exactly across the
// normal, and to first order along it.
// Along the normal: a body rolling on a round surface (a ball, a wheel) keeps touching at the
// foot of its lever, not at the material point that was there. That point rises by
// (1 - cos(angle)) |r|, which at 50 m/s is most of the radius in a step, and the contact took
// the rise for a gap that gravity could close; the first-order turn, r + sin(angle) (axis x r),
// moves no lever of a rolling body along the normal.
// Across the normal the turn is exact: the first-order one lengthens a lever by |r| angle^2 / 2,
// and friction, which holds the surfaces where they touched, carried a box on a turning
// platform outward by that much every step (half a metre in 20 s at 1.5 rad/s).
// (The lever's part along the normal, the whole lever of a rolling ball, takes no second-order
// term either: turned exactly, a ball rolling with side spin seemed to slip sideways.)
inline vector3 turned_lever(const quaternion &q, const vector3 &r, const vector3 &normal) {
    auto axis = vector3{q.x, q.y, q.z};
    auto across = project_plane(r, normal);
    auto second = cross(axis, cross(axis, across)) * scalar(2);
    return r + cross(axis, r) * (2 * q.w) + project_plane(second, normal);
}

// Where the point on A is now, seen from the point on B, less where it was when the step began:
// the bodies' relative motion at the point (the static side has not moved).
template<fixed_side F>
vector3 point_motion(const contact_solver_point &p, const solver_body &a, const solver_body &b) {
    if constexpr (F == fixed_side::b) {
        return a.delta_position + (turned_lever(a.delta_rotation, p.rA, p.normal) - p.rB);
    } else if constexpr (F == fixed_side::a) {
        return (p.rA - turned_lever(b.delta_rotation, p.rB, p.normal)) - b.delta_position;
    } else {
        return (a.delta_position - b.delta_position) + (turned_lever(a.delta_rotation, p.rA, p.normal) -
                                                        turned_lever(b.delta_rotation, p.rB, p.normal));
    }
}

// Current separation of a point, from its motion since the step began.
inline scalar current_separation(const contact_solver_point &p, const vector3 &motion) {
    return dot(p.normal, motion) + p.adjusted_separation;
}

template<fixed_side F>
scalar current_separation(const contact_solver_point &p, const solver_body &a, const solver_body &b) {
    return current_separation(p, point_motion<F>(p, a, b));
}

// Coulomb friction on both tangents of every point: the pair of tangent impulses is limited to
// a disc of radius friction times that point's normal impulse. Both rows are worked out from
// the same velocities before either is applied, so that the pair can be limited as one.
// The relative velocity is taken in the middle of the sub-step, where the bodies' rotation since
// the step began has turned the points' paths (contact_solver_point::path_acceleration): with
// the step's first velocities, a box held on a turning platform went off along the tangent
// each step, |r| angle^2 / 2 outward, and crept off the platform.
// In the biased pass (`motion` given: each point's since the step began) the rows are also a
// soft spring (settings' friction_anchor_hertz) that pulls the surfaces back to where they stuck.
template<fixed_side F>
void solve_friction(const contact_solver_constraint &c, std::span<contact_solver_point> points,
                    solver_body &a, solver_body &b, const detail::bundle_pass &pass, const vector3 *motion) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        auto &p = points[i];
        auto mean_mass = (p.tangent_mass[0] + p.tangent_mass[1]) * scalar(0.5);
        scalar new_impulse[2], shared[2];
        for (int t = 0; t < 2; ++t) {
            auto vt = row_velocity<F>(p.tangent_row[t], p.tangent[t], a, b) +
                      pass.elapsed * dot(p.tangent[t], p.path_acceleration);
            scalar mass_scale = 1, impulse_scale = 0;
            if (motion) {
                auto slid = dot(p.tangent[t], p.adjusted_anchor_gap + motion[i]);
                vt += std::clamp(pass.anchor.bias_rate * slid, -pass.max_push_out_velocity,
                                 pass.max_push_out_velocity);
                mass_scale = pass.anchor.mass_scale;
                impulse_scale = pass.anchor.impulse_scale;
            }
            auto relaxed = p.tangent_impulse[t] - impulse_scale * p.tangent_impulse[t];
            new_impulse[t] = relaxed - p.tangent_mass[t] * mass_scale * vt;
            shared[t] = relaxed - mean_mass * mass_scale * vt;
        }
        limit_to_disc(new_impulse, shared, c.friction * p.normal_impulse);
        for (int t = 0; t < 2; ++t) {
            apply_row<F>(p.tangent_row[t], p.tangent[t], new_impulse[t] - p.tangent_impulse[t], a, b);
            p.tangent_impulse[t] = new_impulse[t];
        }
    }
}

// Torsional friction about the normal and rolling resistance, both proportional to the total
// normal impulse of the manifold (torque per unit weight).
void solve_spin_and_roll(contact_solver_constraint &c, solver_body &a, solver_body &b, scalar total_normal) {
    if (c.spin_friction > 0) {
        auto max_impulse = c.spin_friction * total_normal;
        auto w = dot(c.normal, a.angvel - b.angvel);
        auto new_impulse = std::clamp(c.spin_impulse - c.spin_mass * w, -max_impulse, max_impulse);
        apply_angular_impulse(a, b, c.normal * (new_impulse - c.spin_impulse));
        c.spin_impulse = new_impulse;
    }

    // Two rolling axes (a ball's) share one limit, as the friction tangents do; a cylinder
    // rolls about one.
    if (c.num_roll_axes == 0) return;
    auto max_roll = c.roll_friction * total_normal;
    auto mean_mass = (c.roll_mass[0] + c.roll_mass[1]) * scalar(0.5);
    scalar new_impulse[2]{}, shared[2]{};
    for (std::uint32_t i = 0; i < c.num_roll_axes; ++i) {
        auto w = dot(c.roll_axis[i], a.angvel - b.angvel);
        new_impulse[i] = c.roll_impulse[i] - c.roll_mass[i] * w;
        shared[i] = c.roll_impulse[i] - mean_mass * w;
    }
    if (c.num_roll_axes == 2)
        limit_to_disc(new_impulse, shared, max_roll);
    else
        new_impulse[0] = std::clamp(new_impulse[0], -max_roll, max_roll);
    for (std::uint32_t i = 0; i < c.num_roll_axes; ++i) {
        apply_angular_impulse(a, b, c.roll_axis[i] * (new_impulse[i] - c.roll_impulse[i]));
        c.roll_impulse[i] = new_impulse[i];
    }
}

} // namespace

namespace {

// The spring of a contact whose material sets its stiffness: the whole contact's stiffness and
// damping are shared evenly by its points, so that a load sinks it by load / stiffness however
// many points carry it. Capped at the frequency limit of the sub-step h, like the global one.
softness material_softness(const contact_solver_constraint &c, const contact_solver_point &p, scalar h,
                           const contact_solver_settings &settings) {
    auto share = scalar(1) / scalar(c.num_points);
    auto mass = p.normal_mass;
    auto omega_max = pi2 * settings.max_hertz_ratio / h;
    auto k = std::min(c.stiffness * share, mass * omega_max * omega_max);
    auto damping = c.damping < large_scalar ? c.damping * share
                                            : 2 * settings.contact_damping_ratio * std::sqrt(k * mass);
    return make_spring_softness(k, damping, mass, h);
}

} // namespace

namespace {

// The side the relax pass holds still at the constraint's normal rows (see
// contact_solver_constraint::held): its held side when every point parts faster than
// contact_hold_parting_speed as the pass reaches it, none otherwise. A speculative point parts
// by its velocity plus the gap it may close in the sub-step.
template<fixed_side F>
fixed_side relax_hold(const contact_solver_constraint &c, std::span<const contact_solver_point> points,
                      const solver_body &a, const solver_body &b, const detail::bundle_pass &pass) {
    if constexpr (F != fixed_side::none) {
        return fixed_side::none;
    } else {
        if (pass.use_bias || c.held == fixed_side::none) return fixed_side::none;
        for (auto &p : points) {
            auto s = current_separation<F>(p, a, b);
            auto parting =
                row_velocity<F>(p.normal_row, p.normal, a, b) + (s > 0 ? s * pass.inv_h : scalar(0));
            if (!(contact_hold_parting_speed < parting)) return fixed_side::none;
        }
        return c.held;
    }
}

// One pass of one constraint's rows: normal rows, friction, then spinning and rolling friction.
template<fixed_side F>
void solve_single(contact_solver_constraint &c, std::span<contact_solver_point> points, solver_body &a,
                  solver_body &b, const detail::bundle_pass &pass, const contact_solver_settings &settings,
                  scalar h) {
    auto is_spring = c.stiffness < large_scalar;
    scalar total_normal = 0;
    vector3 motion[contact_solver_constraint::max_points];
    auto hold = relax_hold<F>(c, points, a, b, pass);

    for (std::size_t i = 0; i < points.size(); ++i) {
        auto &p = points[i];
        motion[i] = point_motion<F>(p, a, b);
        auto s = current_separation(p, motion[i]);
        scalar bias = 0, mass_scale = 1, impulse_scale = 0;

        if (s > 0) {
            // Speculative: allow closing the gap within this sub-step, no more.
            bias = s * pass.inv_h;
        } else if (pass.use_bias) {
            // Overlap is pushed out by a stiff, heavily damped spring whose push-out speed is
            // capped; a material's spring is a force of the model and is not capped.
            auto soft = is_spring ? material_softness(c, p, h, settings) : pass.rigid;
            bias = soft.bias_rate * s;
            if (!is_spring) bias = std::max(bias, -pass.max_push_out_velocity);
            mass_scale = soft.mass_scale;
            impulse_scale = soft.impulse_scale;
        } else if (is_spring) {
            total_normal += p.normal_impulse;
            continue;
        }

        auto vn = row_velocity<F>(p.normal_row, p.normal, a, b);
        auto mass = hold == fixed_side::none ? p.normal_mass : held_row_mass(p.normal_row, a, b, hold);
        auto impulse = -mass * mass_scale * (vn + bias) - impulse_scale * p.normal_impulse;
        auto new_impulse = std::max(p.normal_impulse + impulse, scalar(0));
        if (hold == fixed_side::a) {
            apply_row<fixed_side::a>(p.normal_row, p.normal, new_impulse - p.normal_impulse, a, b);
        } else if (hold == fixed_side::b) {
            apply_row<fixed_side::b>(p.normal_row, p.normal, new_impulse - p.normal_impulse, a, b);
        } else {
            apply_row<F>(p.normal_row, p.normal, new_impulse - p.normal_impulse, a, b);
        }
        p.normal_impulse = new_impulse;
        total_normal += new_impulse;
    }

    solve_friction<F>(c, points, a, b, pass, pass.use_bias ? motion : nullptr);
    solve_spin_and_roll(c, a, b, total_normal);
}

} // namespace

void solve_contacts(contact_solver_set &contacts, std::span<solver_body> bodies, scalar h, unsigned substep,
                    const contact_solver_settings &settings, bool use_bias, stage_queue &queue) {
    // A spring stiffer than a quarter of the sub-step rate cannot be integrated stably.
    auto hertz = std::min(settings.contact_hertz, settings.max_hertz_ratio / h);
    auto rigid = make_softness(hertz, settings.contact_damping_ratio, h);
    auto inv_h = scalar(1) / h;

    auto anchor = make_softness(std::min(settings.friction_anchor_hertz, settings.max_hertz_ratio / h),
                                settings.contact_damping_ratio, h);
    auto elapsed = (scalar(substep) + scalar(0.5)) * h;
    detail::bundle_pass pass{inv_h, rigid, anchor, settings.max_push_out_velocity, use_bias, elapsed};
    auto bundle = [&contacts, bodies, pass](std::uint32_t i) {
        detail::solve_bundle(contacts, i, bodies, pass);
    };
    auto single = [&contacts, bodies, pass, &settings, h](std::uint32_t k) {
        auto &c = contacts.constraints[k];
        solver_body copies[2];
        auto &a = solved(bodies[c.body[0]], copies[0]);
        auto &b = solved(bodies[c.body[1]], copies[1]);
        with_fixed_side(
            c, [&](auto side) { solve_single<side()>(c, points_of(contacts, c), a, b, pass, settings, h); });
    };
    queue_in_colour_order(contacts, bodies, queue, bundle, single);
}

void accumulate_contact_impulses(contact_solver_set &contacts, stage_queue &queue) {
    // Each constraint writes only its own totals: any order will do.
    auto add = [&contacts](std::uint32_t k) {
        auto &c = contacts.constraints[k];
        for (auto i = c.first_point; i < c.first_point + c.num_points; ++i) {
            auto &p = contacts.points[i];
            auto &t = contacts.totals[i];
            t.normal_impulse += p.normal_impulse;
            t.tangent_impulse[0] += p.tangent_impulse[0];
            t.tangent_impulse[1] += p.tangent_impulse[1];
        }
        c.total_spin_impulse += c.spin_impulse;
        c.total_roll_impulse[0] += c.roll_impulse[0];
        c.total_roll_impulse[1] += c.roll_impulse[1];
    };
    // The bundled constraints' totals are kept in their bundles, side by side.
    queue.add_for(0u, std::uint32_t(contacts.bundles.size()), contacts_per_task / 4,
                  [&contacts](std::uint32_t i) { detail::accumulate_bundle_impulses(contacts, i); });
    queue.add_for(0u, std::uint32_t(contacts.singles.size()), contacts_per_task,
                  [&contacts, add](std::uint32_t j) { add(contacts.singles[j]); });
    auto &begin = contacts.colour_begin;
    queue.add_for(begin.empty() ? 0u : begin.back(), std::uint32_t(contacts.constraints.size()),
                  contacts_per_task, add);
}

void unpack_contact_impulses(contact_solver_set &contacts, task_scheduler *scheduler) {
    parallel_for(scheduler, 0u, std::uint32_t(contacts.bundles.size()), contacts_per_task / 4,
                 [&](std::uint32_t i) { detail::unpack_bundle_impulses(contacts, i); });
}

namespace {

// One Gauss-Seidel pass over a manifold's normal rows towards the separation speeds `target`,
// with the impulses accumulated in `normal` (from zero at the bounce) and never pulling.
// Returns the largest change it made to an impulse.
scalar bounce_normal_pass(const contact_solver_constraint &c, std::span<contact_solver_point> points,
                          const scalar *target, scalar *normal, solver_body &a, solver_body &b) {
    scalar largest_change = 0;
    for (std::uint32_t i = 0; i < c.num_points; ++i) {
        auto &p = points[i];
        auto vn = row_velocity<fixed_side::none>(p.normal_row, p.normal, a, b);
        auto new_impulse = std::max(normal[i] + p.normal_mass * (target[i] - vn), scalar(0));
        apply_row<fixed_side::none>(p.normal_row, p.normal, new_impulse - normal[i], a, b);
        largest_change = std::max(largest_change, std::abs(new_impulse - normal[i]));
        normal[i] = new_impulse;
    }
    return largest_change;
}

// A manifold's bounce has converged once a pass changes no normal impulse by more than this
// fraction of the largest.
constexpr scalar bounce_convergence = scalar(1e-4);

// Solves one manifold's bounce as an isolated collision: each call is a new collision event,
// so its impulses start from zero. Returns whether any point was hit.
bool solve_restitution_individually(const contact_solver_constraint &c,
                                    std::span<contact_solver_point> points,
                                    std::span<contact_point_totals> totals, solver_body &a, solver_body &b,
                                    scalar threshold, scalar h, unsigned iterations, bounce_moment moment) {
    scalar target[contact_solver_constraint::max_points];
    scalar normal[contact_solver_constraint::max_points]{};
    scalar tangent[contact_solver_constraint::max_points][2]{};
    bool any = false;

    for (std::uint32_t i = 0; i < c.num_points; ++i) {
        auto &p = points[i];
        // The approach speed is the fastest seen since the step began: in between, the
        // speculative contact may have braked the point so that it lands exactly on the surface.
        auto closing = dot(p.normal, relative_velocity(a, b, p.rA, p.rB));
        auto approach = std::min(closing, totals[i].relative_velocity);
        totals[i].relative_velocity = approach;
        auto hits = false;
        if (approach < -threshold) {
            if (moment == bounce_moment::sub_step) {
                // A point still apart bounces only when the gap closes within this sub-step, so
                // that the bounce starts at most one sub-step of travel early.
                hits = current_separation<fixed_side::none>(p, a, b) + approach * h <= 0;
            } else {
                // At the end of the step: a point the contact braked short of the surface
                // (closing the gap in one more sub-step) or stopped on it bounces now, at most a
                // sub-step early, rather than in the next step from a speed that only this step
                // knew. (Stopped exactly on it, when its gap was a whole number of steps'
                // travel, it was left with no bounce at all; a ten-thousandth of the approach
                // left over by rounding counts as stopped.)
                hits = closing <= -approach * scalar(1e-4) && p.normal_impulse > 0;
            }
        }
        target[i] = hits ? -c.restitution * approach : scalar(0);
        // The step's approach has been answered; later hits in this step are new collisions.
        if (hits) totals[i].relative_velocity = 0;
        any |= hits;
    }
    if (!any) return false;

    // The points of a box landing flat pull its turn each way: each pass leaves a quarter or so
    // of the last one's error, so the passes go on until the impulses settle (one pass more
    // than the first for a single point), at most `iterations`.
    for (unsigned k = 0; k < iterations; ++k) {
        auto change = bounce_normal_pass(c, points, target, normal, a, b);
        if (k > 0 && change <= bounce_convergence * *std::max_element(normal, normal + c.num_points)) break;
        for (std::uint32_t i = 0; i < c.num_points; ++i) {
            auto &p = points[i];
            auto mean_mass = (p.tangent_mass[0] + p.tangent_mass[1]) * scalar(0.5);
            scalar new_impulse[2], shared[2];
            for (int t = 0; t < 2; ++t) {
                auto vt = row_velocity<fixed_side::none>(p.tangent_row[t], p.tangent[t], a, b);
                new_impulse[t] = tangent[i][t] - p.tangent_mass[t] * vt;
                shared[t] = tangent[i][t] - mean_mass * vt;
            }
            limit_to_disc(new_impulse, shared, c.friction * normal[i]);
            for (int t = 0; t < 2; ++t) {
                apply_row<fixed_side::none>(p.tangent_row[t], p.tangent[t], new_impulse[t] - tangent[i][t], a,
                                            b);
                tangent[i][t] = new_impulse[t];
            }
        }
    }

    for (std::uint32_t i = 0; i < c.num_points; ++i) {
        auto &t = totals[i];
        t.restitution_impulse += normal[i];
        t.tangent_restitution_impulse[0] += tangent[i][0];
        t.tangent_restitution_impulse[1] += tangent[i][1];
    }
    return true;
}

} // namespace

void record_approach_speeds(contact_solver_set &contacts, std::span<const solver_body> bodies) {
    for (auto k : contacts.bouncy) {
        auto &c = contacts.constraints[k];
        auto &a = bodies[c.body[0]];
        auto &b = bodies[c.body[1]];
        for (auto i = c.first_point; i < c.first_point + c.num_points; ++i) {
            auto &p = contacts.points[i];
            auto &approach = contacts.totals[i].relative_velocity;
            approach = std::min(approach, dot(p.normal, relative_velocity(a, b, p.rA, p.rB)));
        }
    }
}

void bounce_without_restitution_solver(contact_solver_set &contacts, std::span<solver_body> bodies,
                                       const contact_solver_settings &settings) {
    // Passes over one manifold's points, for a box landing on a face to leave it level; the
    // points not hit only keep from closing in, as in the restitution solver.
    constexpr unsigned passes = 4;
    for (auto k : contacts.bouncy) {
        auto &c = contacts.constraints[k];
        auto points = points_of(contacts, c);
        auto totals = std::span(contacts.totals).subspan(c.first_point, c.num_points);
        auto &a = bodies[c.body[0]];
        auto &b = bodies[c.body[1]];
        scalar target[contact_solver_constraint::max_points]{};
        scalar normal[contact_solver_constraint::max_points]{};
        bool any = false;
        for (std::uint32_t i = 0; i < c.num_points; ++i) {
            // Approaching (at the fastest the step saw), and met by the contact in the step.
            auto hit =
                totals[i].relative_velocity < -settings.restitution_threshold && totals[i].normal_impulse > 0;
            target[i] = hit ? -c.restitution * totals[i].relative_velocity : scalar(0);
            any |= hit;
        }
        if (!any) continue;
        for (unsigned pass = 0; pass < passes; ++pass)
            bounce_normal_pass(c, points, target, normal, a, b);
        // Part of the contact's own impulse: the restitution solver's totals stay zero.
        for (std::uint32_t i = 0; i < c.num_points; ++i)
            totals[i].normal_impulse += normal[i];
    }
}

unsigned solve_restitution(contact_solver_set &contacts, std::span<solver_body> bodies,
                           const contact_solver_settings &settings, scalar h, unsigned iterations,
                           unsigned individual_iterations, bounce_moment moment) {
    if (iterations == 0 || individual_iterations == 0) return 0;

    unsigned passes = 0;
    for (; passes < iterations; ++passes) {
        bool any = false;
        for (auto k : contacts.bouncy) {
            auto &c = contacts.constraints[k];
            any |= solve_restitution_individually(
                c, points_of(contacts, c), std::span(contacts.totals).subspan(c.first_point, c.num_points),
                bodies[c.body[0]], bodies[c.body[1]], settings.restitution_threshold, h,
                individual_iterations, moment);
        }
        if (!any) break;
    }
    return passes;
}

} // namespace edyn
