#include "contact_bundle_solver.hpp"
#include "../math/wide_scalar.hpp"
#include "edyn/config/prefetch.hpp"
#include <cstddef>

namespace edyn::detail {

namespace {

constexpr std::uint32_t lanes = contact_bundle_lanes;
static_assert(lanes == wide_lanes);

// The solver state of one body in each lane.
struct wide_body {
    wide3 linvel, angvel, delta_position;
    wide_quaternion delta_rotation;
    wide inv_mass;
};

#if defined(EDYN_WIDE_AVX2) || defined(EDYN_WIDE_SSE2)
// The state a bundle reads is the first 14 floats of solver_body: loaded as groups of four or
// eight floats per lane (the last group runs two floats into inv_inertia) and transposed.
static_assert(offsetof(solver_body, linvel) == 0 && offsetof(solver_body, angvel) == 12 &&
              offsetof(solver_body, delta_position) == 24 && offsetof(solver_body, delta_rotation) == 36 &&
              offsetof(solver_body, inv_mass) == 52 && sizeof(solver_body) >= 64);
#endif

#ifdef EDYN_WIDE_AVX2

wide_body gather(const solver_body *bodies, const solver_body_index (&index)[lanes]) {
    __m256 g[2][lanes];
    for (std::uint32_t i = 0; i < lanes; ++i) {
        auto *p = reinterpret_cast<const float *>(&bodies[index[i]]);
        g[0][i] = _mm256_loadu_ps(p);
        g[1][i] = _mm256_loadu_ps(p + 8);
    }
    transpose(g[0]);
    transpose(g[1]);
    wide_body b;
    b.linvel = {{g[0][0]}, {g[0][1]}, {g[0][2]}};
    b.angvel = {{g[0][3]}, {g[0][4]}, {g[0][5]}};
    b.delta_position = {{g[0][6]}, {g[0][7]}, {g[1][0]}};
    b.delta_rotation = {{g[1][1]}, {g[1][2]}, {g[1][3]}, {g[1][4]}};
    b.inv_mass = {g[1][5]};
    return b;
}

// Writes the velocities of the lanes whose bit is set; the two floats after them go back
// unchanged.
void scatter(solver_body *bodies, const solver_body_index (&index)[lanes], std::uint32_t bits,
             const wide_body &b) {
    __m256 g[lanes] = {b.linvel.x.v, b.linvel.y.v, b.linvel.z.v,         b.angvel.x.v,
                       b.angvel.y.v, b.angvel.z.v, b.delta_position.x.v, b.delta_position.y.v};
    transpose(g);
    for (std::uint32_t i = 0; i < lanes; ++i) {
        if (bits & (1u << i)) _mm256_storeu_ps(reinterpret_cast<float *>(&bodies[index[i]]), g[i]);
    }
}

#elif defined(EDYN_WIDE_SSE2)

wide_body gather(const solver_body *bodies, const solver_body_index (&index)[lanes]) {
    const float *p[lanes];
    for (std::uint32_t i = 0; i < lanes; ++i)
        p[i] = reinterpret_cast<const float *>(&bodies[index[i]]);
    __m128 g[4][lanes];
    for (int k = 0; k < 4; ++k) {
        for (std::uint32_t i = 0; i < lanes; ++i)
            g[k][i] = _mm_loadu_ps(p[i] + 4 * k);
        _MM_TRANSPOSE4_PS(g[k][0], g[k][1], g[k][2], g[k][3]);
    }
    wide_body b;
    b.linvel = {{g[0][0]}, {g[0][1]}, {g[0][2]}};
    b.angvel = {{g[0][3]}, {g[1][0]}, {g[1][1]}};
    b.delta_position = {{g[1][2]}, {g[1][3]}, {g[2][0]}};
    b.delta_rotation = {{g[2][1]}, {g[2][2]}, {g[2][3]}, {g[3][0]}};
    b.inv_mass = {g[3][1]};
    return b;
}

// Writes the velocities of the lanes whose bit is set; the two floats after them go back
// unchanged.
void scatter(solver_body *bodies, const solver_body_index (&index)[lanes], std::uint32_t bits,
             const wide_body &b) {
    __m128 g0[lanes] = {b.linvel.x.v, b.linvel.y.v, b.linvel.z.v, b.angvel.x.v};
    __m128 g1[lanes] = {b.angvel.y.v, b.angvel.z.v, b.delta_position.x.v, b.delta_position.y.v};
    _MM_TRANSPOSE4_PS(g0[0], g0[1], g0[2], g0[3]);
    _MM_TRANSPOSE4_PS(g1[0], g1[1], g1[2], g1[3]);
    for (std::uint32_t i = 0; i < lanes; ++i) {
        if (!(bits & (1u << i))) continue;
        auto *p = reinterpret_cast<float *>(&bodies[index[i]]);
        _mm_storeu_ps(p, g0[i]);
        _mm_storeu_ps(p + 4, g1[i]);
    }
}

#else

// Any other representation of the lanes: the bodies' fields copied into arrays of lanes first.
wide_body gather(const solver_body *bodies, const solver_body_index (&index)[lanes]) {
    scalar f[14][lanes];
    for (std::uint32_t i = 0; i < lanes; ++i) {
        auto &s = bodies[index[i]];
        const scalar in[14] = {s.linvel.x,         s.linvel.y,         s.linvel.z,         s.angvel.x,
                               s.angvel.y,         s.angvel.z,         s.delta_position.x, s.delta_position.y,
                               s.delta_position.z, s.delta_rotation.x, s.delta_rotation.y, s.delta_rotation.z,
                               s.delta_rotation.w, s.inv_mass};
        for (std::size_t k = 0; k < 14; ++k)
            f[k][i] = in[k];
    }
    wide_body b;
    b.linvel = {wide_load(f[0]), wide_load(f[1]), wide_load(f[2])};
    b.angvel = {wide_load(f[3]), wide_load(f[4]), wide_load(f[5])};
    b.delta_position = {wide_load(f[6]), wide_load(f[7]), wide_load(f[8])};
    b.delta_rotation = {wide_load(f[9]), wide_load(f[10]), wide_load(f[11]), wide_load(f[12])};
    b.inv_mass = wide_load(f[13]);
    return b;
}

void scatter(solver_body *bodies, const solver_body_index (&index)[lanes], std::uint32_t bits,
             const wide_body &b) {
    scalar f[6][lanes];
    wide_store(f[0], b.linvel.x);
    wide_store(f[1], b.linvel.y);
    wide_store(f[2], b.linvel.z);
    wide_store(f[3], b.angvel.x);
    wide_store(f[4], b.angvel.y);
    wide_store(f[5], b.angvel.z);
    for (std::uint32_t i = 0; i < lanes; ++i) {
        if (!(bits & (1u << i))) continue;
        auto &s = bodies[index[i]];
        s.linvel = {f[0][i], f[1][i], f[2][i]};
        s.angvel = {f[3][i], f[4][i], f[5][i]};
    }
}

#endif

// A contact row as stored in a slot: angularA, angularB, inv_angularA, inv_angularB.
struct wide_row {
    wide3 angularA, angularB, inv_angularA, inv_angularB;
};

EDYN_WIDE_INLINE wide_row load_row(const scalar (&row)[4][3][lanes]) {
    return {wide3_load(row[0]), wide3_load(row[1]), wide3_load(row[2]), wide3_load(row[3])};
}

// Relative velocity along d, as row_velocity() in contact_solver.cpp.
template<fixed_side F>
EDYN_WIDE_INLINE wide row_velocity(const wide_row &row, const wide3 &d, const wide_body &a,
                                   const wide_body &b) {
    if constexpr (F == fixed_side::b) {
        return dot(d, a.linvel) + dot(row.angularA, a.angvel);
    } else if constexpr (F == fixed_side::a) {
        return -(dot(d, b.linvel) + dot(row.angularB, b.angvel));
    } else {
        return dot(d, a.linvel - b.linvel) + dot(row.angularA, a.angvel) - dot(row.angularB, b.angvel);
    }
}

// Applies the impulse along the row, as apply_row() in contact_solver.cpp.
template<fixed_side F>
EDYN_WIDE_INLINE void apply_row(const wide_row &row, const wide3 &d, wide impulse, wide_body &a,
                                wide_body &b) {
    if constexpr (F != fixed_side::a) {
        a.linvel = a.linvel + d * (a.inv_mass * impulse);
        a.angvel = a.angvel + row.inv_angularA * impulse;
    }
    if constexpr (F != fixed_side::b) {
        b.linvel = b.linvel - d * (b.inv_mass * impulse);
        b.angvel = b.angvel - row.inv_angularB * impulse;
    }
}

// held_row_mass() in contact_solver.cpp, lane by lane, from the not held body's k.
EDYN_WIDE_INLINE wide held_row_mass(wide k) {
    auto zero = wide_set(0);
    return select(zero < k, wide_set(1) / k, zero);
}

// The velocities a partly filled slot must leave alone in its empty lanes (the static side's
// are never written back).
struct velocities {
    wide3 linvelA, angvelA, linvelB, angvelB;
};

inline velocities velocities_of(const wide_body &a, const wide_body &b) {
    return {a.linvel, a.angvel, b.linvel, b.angvel};
}

template<fixed_side F>
inline void keep_unmasked(wide_mask active, const velocities &before, wide_body &a, wide_body &b) {
    if constexpr (F != fixed_side::a) {
        a.linvel = select(active, a.linvel, before.linvelA);
        a.angvel = select(active, a.angvel, before.angvelA);
    }
    if constexpr (F != fixed_side::b) {
        b.linvel = select(active, b.linvel, before.linvelB);
        b.angvel = select(active, b.angvel, before.angvelB);
    }
}

// A lever turned exactly across the normal and to first order along it, as turned_lever() in
// contact_solver.cpp.
inline wide3 turned_lever(const wide_quaternion &q, const wide3 &r, const wide3 &normal) {
    auto axis = wide3{q.x, q.y, q.z};
    auto across = r - normal * dot(normal, r);
    auto second = cross(axis, cross(axis, across)) * wide_set(scalar(2));
    return r + cross(axis, r) * (q.w * wide_set(scalar(2))) + (second - normal * dot(normal, second));
}

// The bodies' relative motion at the slot's points since the step began, as point_motion() in
// contact_solver.cpp.
template<fixed_side F>
inline wide3 point_motion(const contact_bundle_slot &slot, const wide_body &a, const wide_body &b) {
    auto normal = wide3_load(slot.normal);
    if constexpr (F == fixed_side::b) {
        return a.delta_position +
               (turned_lever(a.delta_rotation, wide3_load(slot.rA), normal) - wide3_load(slot.rB));
    } else if constexpr (F == fixed_side::a) {
        return (wide3_load(slot.rA) - turned_lever(b.delta_rotation, wide3_load(slot.rB), normal)) -
               b.delta_position;
    } else {
        return (a.delta_position - b.delta_position) +
               (turned_lever(a.delta_rotation, wide3_load(slot.rA), normal) -
                turned_lever(b.delta_rotation, wide3_load(slot.rB), normal));
    }
}

// The bundle's two sides, the static one left at zero (none of its terms is used).
template<fixed_side F>
void gather_sides(const solver_body *bodies, const contact_bundle &bundle, wide_body &a, wide_body &b) {
    if constexpr (F != fixed_side::a) a = gather(bodies, bundle.body[0]);
    if constexpr (F != fixed_side::b) b = gather(bodies, bundle.body[1]);
}

template<fixed_side F>
void scatter_sides(solver_body *bodies, const contact_bundle &bundle, const wide_body &a,
                   const wide_body &b) {
    if constexpr (F != fixed_side::a) scatter(bodies, bundle.body[0], bundle.moves_a, a);
    if constexpr (F != fixed_side::b) scatter(bodies, bundle.body[1], bundle.moves_b, b);
}

// Calls fn with the bundle's fixed side as a std::integral_constant.
template<typename Fn>
void with_fixed_side(const contact_bundle &bundle, Fn &&fn) {
    switch (bundle.fixed_side) {
    case fixed_side::a:
        fn(std::integral_constant<fixed_side, fixed_side::a>{});
        break;
    case fixed_side::b:
        fn(std::integral_constant<fixed_side, fixed_side::b>{});
        break;
    default:
        fn(std::integral_constant<fixed_side, fixed_side::none>{});
    }
}

} // namespace

namespace {

template<fixed_side F>
void warm_start_bundle(contact_solver_set &contacts, contact_bundle &bundle, std::span<solver_body> bodies) {
    wide_body a{}, b{};
    gather_sides<F>(bodies.data(), bundle, a, b);

    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        auto partial = s >= bundle.full_slots;
        auto before = velocities_of(a, b);
        apply_row<F>(load_row(slot.normal_row), wide3_load(slot.normal), wide_load(slot.normal_impulse), a,
                     b);
        for (int t = 0; t < 2; ++t) {
            apply_row<F>(load_row(slot.tangent_row[t]), wide3_load(slot.tangent[t]),
                         wide_load(slot.tangent_impulse[t]), a, b);
        }
        if (partial) keep_unmasked<F>(slot_mask(bundle, s), before, a, b);
    }
    scatter_sides<F>(bodies.data(), bundle, a, b);
}

// Hold: a relax pass over a bundle some of whose lanes hold a side (contact_bundle::holds),
// compiled apart so that the other passes keep their registers.
template<fixed_side F, bool Hold>
void solve_bundle(contact_solver_set &contacts, contact_bundle &bundle, std::span<solver_body> bodies,
                  const bundle_pass &pass) {
    wide_body a{}, b{};
    gather_sides<F>(bodies.data(), bundle, a, b);
    auto zero = wide_set(0);
    auto one = wide_set(1);
    auto half = wide_set(scalar(0.5));
    auto inv_h = wide_set(pass.inv_h);
    auto bias_rate = wide_set(pass.rigid.bias_rate);
    auto rigid_mass_scale = wide_set(pass.rigid.mass_scale);
    auto rigid_impulse_scale = wide_set(pass.rigid.impulse_scale);
    auto min_bias = wide_set(-pass.max_push_out_velocity);
    auto max_bias = wide_set(pass.max_push_out_velocity);
    auto anchor_bias_rate = wide_set(pass.anchor.bias_rate);
    auto elapsed = wide_set(pass.elapsed);
    auto anchor_mass_scale = wide_set(pass.anchor.mass_scale);
    auto anchor_impulse_scale = wide_set(pass.anchor.impulse_scale);
    wide3 motion[contact_solver_constraint::max_points];

    // The slots whose motion is worked out before the normal rows.
    std::uint32_t motion_ready = 0;
    // The lanes whose body A or B the relax pass holds still, as relax_hold() in
    // contact_solver.cpp: every point of the lane parts faster than contact_hold_parting_speed.
    wide_mask hold_a{}, hold_b{};
    auto any_hold = false;
    if constexpr (Hold) {
        static_assert(F == fixed_side::none);
        auto parting_speed = wide_set(contact_hold_parting_speed);
        // Lanes with points; resting contacts part too slowly at their first point already, and
        // the look ends there.
        auto all_part = slot_mask(bundle, 0);
        while (motion_ready < bundle.num_slots && any(all_part)) {
            auto s = motion_ready++;
            auto &slot = contacts.bundle_slots[bundle.first_slot + s];
            auto normal = wide3_load(slot.normal);
            motion[s] = point_motion<F>(slot, a, b);
            auto sep = dot(normal, motion[s]) + wide_load(slot.adjusted_separation);
            auto parting = row_velocity<F>(load_row(slot.normal_row), normal, a, b) +
                           select(zero < sep, sep * inv_h, zero);
            // A lane without a point in this slot does not stop its others from holding.
            parting = select(slot_mask(bundle, s), parting, parting_speed + one);
            all_part = all_part & (parting_speed < parting);
        }
        auto held = wide_from_counts(bundle.held);
        hold_a = all_part & (half < held) & (held < wide_set(scalar(1.5)));
        hold_b = all_part & (wide_set(scalar(1.5)) < held);
        any_hold = any(hold_a | hold_b);
    }

    // Normal rows of every point, then friction, as the one-at-a-time pass does.
    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        auto partial = s >= bundle.full_slots;
        auto before = velocities_of(a, b);
        auto normal = wide3_load(slot.normal);
        if (s >= motion_ready) motion[s] = point_motion<F>(slot, a, b);
        auto sep = dot(normal, motion[s]) + wide_load(slot.adjusted_separation);
        // Speculative where still apart; else the soft push-out in the biased pass, nothing in
        // the relax pass.
        auto apart = zero < sep;
        auto bias = select(apart, sep * inv_h, zero);
        auto mass_scale = one, impulse_scale = zero;
        if (pass.use_bias) {
            bias = select(apart, bias, std_max(bias_rate * sep, min_bias));
            mass_scale = select(apart, one, rigid_mass_scale);
            impulse_scale = select(apart, zero, rigid_impulse_scale);
        }
        auto row = load_row(slot.normal_row);
        auto old_impulse = wide_load(slot.normal_impulse);
        auto vn = row_velocity<F>(row, normal, a, b);
        auto mass = wide_load(slot.normal_mass);
        if (any_hold) {
            // The effective mass of the body not held, where a lane holds one.
            auto k = select(hold_a, b.inv_mass + dot(row.angularB, row.inv_angularB),
                            a.inv_mass + dot(row.angularA, row.inv_angularA));
            mass = select(hold_a | hold_b, held_row_mass(k), mass);
        }
        auto impulse = -mass * mass_scale * (vn + bias) - impulse_scale * old_impulse;
        auto new_impulse = std_max(old_impulse + impulse, zero);
        apply_row<F>(row, normal, new_impulse - old_impulse, a, b);
        if (any_hold) {
            a.linvel = select(hold_a, before.linvelA, a.linvel);
            a.angvel = select(hold_a, before.angvelA, a.angvel);
            b.linvel = select(hold_b, before.linvelB, b.linvel);
            b.angvel = select(hold_b, before.angvelB, b.angvel);
        }
        if (partial) {
            auto active = slot_mask(bundle, s);
            keep_unmasked<F>(active, before, a, b);
            new_impulse = select(active, new_impulse, old_impulse);
        }
        wide_store(slot.normal_impulse, new_impulse);
    }

    // Both tangents from the same velocities, limited together to the friction disc, as
    // solve_friction() in contact_solver.cpp (and with the same operations, for the same bits).
    auto friction = wide_load(bundle.friction);
    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        auto partial = s >= bundle.full_slots;
        auto before = velocities_of(a, b);
        auto mean_mass = (wide_load(slot.tangent_mass[0]) + wide_load(slot.tangent_mass[1])) * half;
        // The points' relative velocity in the middle of the sub-step, as in solve_friction().
        auto path_acceleration = wide3_load(slot.path_acceleration);
        wide_row row[2];
        wide3 tangent[2];
        wide old_impulse[2], new_impulse[2], shared[2];
        for (int t = 0; t < 2; ++t) {
            row[t] = load_row(slot.tangent_row[t]);
            tangent[t] = wide3_load(slot.tangent[t]);
            old_impulse[t] = wide_load(slot.tangent_impulse[t]);
            auto vt =
                row_velocity<F>(row[t], tangent[t], a, b) + elapsed * dot(tangent[t], path_acceleration);
            auto mass_scale = one, impulse_scale = zero;
            if (pass.use_bias) {
                // Friction anchors, as solve_friction() in contact_solver.cpp.
                auto slid = dot(tangent[t], wide3_load(slot.adjusted_anchor_gap) + motion[s]);
                vt = vt + std_clamp(anchor_bias_rate * slid, min_bias, max_bias);
                mass_scale = anchor_mass_scale;
                impulse_scale = anchor_impulse_scale;
            }
            auto relaxed = old_impulse[t] - impulse_scale * old_impulse[t];
            new_impulse[t] = relaxed - wide_load(slot.tangent_mass[t]) * mass_scale * vt;
            shared[t] = relaxed - mean_mass * mass_scale * vt;
        }
        // limit_to_disc() in contact_solver.cpp, lane by lane.
        auto limit = friction * wide_load(slot.normal_impulse);
        auto length2 = new_impulse[0] * new_impulse[0] + new_impulse[1] * new_impulse[1];
        auto outside = limit * limit < length2;
        if (any(outside)) {
            auto shared2 = shared[0] * shared[0] + shared[1] * shared[1];
            auto use_shared = zero < shared2;
            auto scale = limit / wide_sqrt(select(use_shared, shared2, length2));
            for (int t = 0; t < 2; ++t)
                new_impulse[t] =
                    select(outside, select(use_shared, shared[t], new_impulse[t]) * scale, new_impulse[t]);
        }
        for (int t = 0; t < 2; ++t)
            apply_row<F>(row[t], tangent[t], new_impulse[t] - old_impulse[t], a, b);
        if (partial) {
            auto active = slot_mask(bundle, s);
            keep_unmasked<F>(active, before, a, b);
            for (int t = 0; t < 2; ++t)
                new_impulse[t] = select(active, new_impulse[t], old_impulse[t]);
        }
        for (int t = 0; t < 2; ++t)
            wide_store(slot.tangent_impulse[t], new_impulse[t]);
    }

    scatter_sides<F>(bodies.data(), bundle, a, b);
}

} // namespace

void prefetch_bundle_bodies(const contact_solver_set &contacts, std::uint32_t index,
                            std::span<const solver_body> bodies) noexcept {
    auto &bundle = contacts.bundles[index];
    for (std::uint32_t i = 0; i < lanes; ++i) {
        prefetch(&bodies[bundle.body[0][i]]);
        prefetch(&bodies[bundle.body[1][i]]);
    }
}

void warm_start_bundle(contact_solver_set &contacts, std::uint32_t index, std::span<solver_body> bodies) {
    auto &bundle = contacts.bundles[index];
    with_fixed_side(bundle, [&](auto side) { warm_start_bundle<side()>(contacts, bundle, bodies); });
}

void solve_bundle(contact_solver_set &contacts, std::uint32_t index, std::span<solver_body> bodies,
                  const bundle_pass &pass) {
    auto &bundle = contacts.bundles[index];
    with_fixed_side(bundle, [&](auto side) {
        if constexpr (side() == fixed_side::none) {
            if (!pass.use_bias && bundle.holds) {
                solve_bundle<fixed_side::none, true>(contacts, bundle, bodies, pass);
                return;
            }
        }
        solve_bundle<side(), false>(contacts, bundle, bodies, pass);
    });
}

void accumulate_bundle_impulses(contact_solver_set &contacts, std::uint32_t index) {
    auto &bundle = contacts.bundles[index];
    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        auto &totals = contacts.bundle_totals[bundle.first_slot + s];
        auto add = [](scalar *total, const scalar *impulse) {
            wide_store(total, wide_load(total) + wide_load(impulse));
        };
        add(totals.normal_impulse, slot.normal_impulse);
        add(totals.tangent_impulse[0], slot.tangent_impulse[0]);
        add(totals.tangent_impulse[1], slot.tangent_impulse[1]);
    }
}

void unpack_bundle_impulses(contact_solver_set &contacts, std::uint32_t index) {
    auto &bundle = contacts.bundles[index];
    for (std::uint32_t i = 0; i < lanes; ++i) {
        if (bundle.num_points[i] == 0) continue;
        auto &c = contacts.constraints[bundle.constraint[i]];
        for (std::uint32_t s = 0; s < c.num_points; ++s) {
            auto &slot = contacts.bundle_slots[bundle.first_slot + s];
            auto &p = contacts.points[c.first_point + s];
            p.normal_impulse = slot.normal_impulse[i];
            p.tangent_impulse[0] = slot.tangent_impulse[0][i];
            p.tangent_impulse[1] = slot.tangent_impulse[1][i];
            auto &totals = contacts.bundle_totals[bundle.first_slot + s];
            auto &t = contacts.totals[c.first_point + s];
            t.normal_impulse = totals.normal_impulse[i];
            t.tangent_impulse[0] = totals.tangent_impulse[0][i];
            t.tangent_impulse[1] = totals.tangent_impulse[1][i];
        }
    }
}

} // namespace edyn::detail
