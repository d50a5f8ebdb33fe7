#include "contact_bundle_solver.hpp"
#include "../math/wide_scalar.hpp"
#include "edyn/config/prefetch.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include <cstddef>

namespace edyn::detail {

namespace {

constexpr std::uint32_t lanes = contact_bundle_lanes;
static_assert(lanes == wide_lanes);

// Bundles per parallel range when filling their slots.
constexpr std::size_t bundles_per_task = 16;

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

wide_body gather(const solver_body *bodies, const solver_body_index (&index)[lanes]) {
    wide_body b;
    for (std::uint32_t i = 0; i < lanes; ++i) {
        auto &s = bodies[index[i]];
        b.linvel.x.v[i] = s.linvel.x;
        b.linvel.y.v[i] = s.linvel.y;
        b.linvel.z.v[i] = s.linvel.z;
        b.angvel.x.v[i] = s.angvel.x;
        b.angvel.y.v[i] = s.angvel.y;
        b.angvel.z.v[i] = s.angvel.z;
        b.delta_position.x.v[i] = s.delta_position.x;
        b.delta_position.y.v[i] = s.delta_position.y;
        b.delta_position.z.v[i] = s.delta_position.z;
        b.delta_rotation.x.v[i] = s.delta_rotation.x;
        b.delta_rotation.y.v[i] = s.delta_rotation.y;
        b.delta_rotation.z.v[i] = s.delta_rotation.z;
        b.delta_rotation.w.v[i] = s.delta_rotation.w;
        b.inv_mass.v[i] = s.inv_mass;
    }
    return b;
}

void scatter(solver_body *bodies, const solver_body_index (&index)[lanes], std::uint32_t bits,
             const wide_body &b) {
    for (std::uint32_t i = 0; i < lanes; ++i) {
        if (!(bits & (1u << i))) continue;
        auto &s = bodies[index[i]];
        s.linvel = {b.linvel.x.v[i], b.linvel.y.v[i], b.linvel.z.v[i]};
        s.angvel = {b.angvel.x.v[i], b.angvel.y.v[i], b.angvel.z.v[i]};
    }
}

#endif

// A contact row as stored in a slot: angularA, angularB, inv_angularA, inv_angularB.
struct wide_row {
    wide3 angularA, angularB, inv_angularA, inv_angularB;
};

wide_row load_row(const scalar (&row)[4][3][lanes]) {
    return {wide3_load(row[0]), wide3_load(row[1]), wide3_load(row[2]), wide3_load(row[3])};
}

// Relative velocity along d, as row_velocity() in contact_solver.cpp.
template<fixed_side F>
inline wide row_velocity(const wide_row &row, const wide3 &d, const wide_body &a, const wide_body &b) {
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
inline void apply_row(const wide_row &row, const wide3 &d, wide impulse, wide_body &a, wide_body &b) {
    if constexpr (F != fixed_side::a) {
        a.linvel = a.linvel + d * (a.inv_mass * impulse);
        a.angvel = a.angvel + row.inv_angularA * impulse;
    }
    if constexpr (F != fixed_side::b) {
        b.linvel = b.linvel - d * (b.inv_mass * impulse);
        b.angvel = b.angvel - row.inv_angularB * impulse;
    }
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

// Lanes that have a point in slot s.
inline wide_mask slot_mask(const contact_bundle &bundle, std::uint32_t s) {
    return wide_set(scalar(s)) < wide_from_counts(bundle.num_points);
}

// The bodies' relative motion at the slot's points since the step began, as point_motion() in
// contact_solver.cpp.
template<fixed_side F>
inline wide3 point_motion(const contact_bundle_slot &slot, const wide_body &a, const wide_body &b) {
    if constexpr (F == fixed_side::b) {
        return a.delta_position + (rotate(a.delta_rotation, wide3_load(slot.rA)) - wide3_load(slot.rB));
    } else if constexpr (F == fixed_side::a) {
        return (wide3_load(slot.rA) - rotate(b.delta_rotation, wide3_load(slot.rB))) - b.delta_position;
    } else {
        return (a.delta_position - b.delta_position) + (rotate(a.delta_rotation, wide3_load(slot.rA)) -
                                                        rotate(b.delta_rotation, wide3_load(slot.rB)));
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

// A slot is its lanes' points side by side: the k-th scalar of contact_solver_point becomes the
// slot's k-th array, of one scalar per lane. Filling it is a transposition of the scalars before
// the rows (make_slot_rows() makes the tangents, masses and rows over them).
constexpr std::size_t point_scalars = sizeof(contact_solver_point) / sizeof(scalar);
constexpr std::size_t carried_scalars = offsetof(contact_solver_point, normal_row) / sizeof(scalar);
static_assert(sizeof(contact_solver_point) == point_scalars * sizeof(scalar) &&
              sizeof(contact_bundle_slot) == point_scalars * lanes * sizeof(scalar));
static_assert(
    offsetof(contact_solver_point, tangent) == offsetof(contact_bundle_slot, tangent) / lanes &&
    offsetof(contact_solver_point, adjusted_separation) ==
        offsetof(contact_bundle_slot, adjusted_separation) / lanes &&
    offsetof(contact_solver_point, normal_mass) == offsetof(contact_bundle_slot, normal_mass) / lanes &&
    offsetof(contact_solver_point, normal_impulse) == offsetof(contact_bundle_slot, normal_impulse) / lanes &&
    offsetof(contact_solver_point, normal_row) == offsetof(contact_bundle_slot, normal_row) / lanes &&
    offsetof(contact_solver_point, tangent_row) == offsetof(contact_bundle_slot, tangent_row) / lanes);

void fill_slot(contact_bundle_slot &slot, const contact_solver_point *(&points)[lanes]) {
    const scalar *in[lanes];
    for (std::uint32_t i = 0; i < lanes; ++i)
        in[i] = reinterpret_cast<const scalar *>(points[i]);
    auto *out = reinterpret_cast<scalar *>(&slot);
    std::size_t k = 0;
#if defined(EDYN_WIDE_AVX2)
    for (; k + lanes <= carried_scalars; k += lanes) {
        __m256 g[lanes];
        for (std::uint32_t i = 0; i < lanes; ++i)
            g[i] = _mm256_loadu_ps(in[i] + k);
        transpose(g);
        for (std::uint32_t r = 0; r < lanes; ++r)
            _mm256_storeu_ps(out + (k + r) * lanes, g[r]);
    }
#elif defined(EDYN_WIDE_SSE2)
    for (; k + lanes <= carried_scalars; k += lanes) {
        __m128 g[lanes];
        for (std::uint32_t i = 0; i < lanes; ++i)
            g[i] = _mm_loadu_ps(in[i] + k);
        _MM_TRANSPOSE4_PS(g[0], g[1], g[2], g[3]);
        for (std::uint32_t r = 0; r < lanes; ++r)
            _mm_storeu_ps(out + (k + r) * lanes, g[r]);
    }
#endif
    for (; k < carried_scalars; ++k)
        for (std::uint32_t i = 0; i < lanes; ++i)
            out[k * lanes + i] = in[i][k];
}

void wide3_store(scalar (&p)[3][lanes], const wide3 &v) {
    wide_store(p[0], v.x);
    wide_store(p[1], v.y);
    wide_store(p[2], v.z);
}

// A matrix3x3 in each lane, by rows.
struct wide_matrix {
    wide3 row[3];
};

inline wide3 operator*(const wide_matrix &m, const wide3 &v) {
    return {dot(m.row[0], v), dot(m.row[1], v), dot(m.row[2], v)};
}

// One side's inverse masses and inertias, lane by lane.
struct wide_inertia {
    wide inv_mass;
    wide_matrix inv_inertia;
};

wide_inertia gather_inertia(const solver_body *bodies, const solver_body_index (&index)[lanes]) {
    scalar m[10][lanes];
    for (std::uint32_t i = 0; i < lanes; ++i) {
        auto &body = bodies[index[i]];
        m[0][i] = body.inv_mass;
        for (int r = 0; r < 3; ++r) {
            m[1 + 3 * r][i] = body.inv_inertia[r].x;
            m[2 + 3 * r][i] = body.inv_inertia[r].y;
            m[3 + 3 * r][i] = body.inv_inertia[r].z;
        }
    }
    wide_inertia out;
    out.inv_mass = wide_load(m[0]);
    for (int r = 0; r < 3; ++r)
        out.inv_inertia.row[r] = {wide_load(m[1 + 3 * r]), wide_load(m[2 + 3 * r]), wide_load(m[3 + 3 * r])};
    return out;
}

// A row of the slot and its effective mass, as make_row() and row_mass() in contact_solver.cpp,
// lane by lane; the mass is 0 in the lanes without a point.
wide make_wide_row(scalar (&to)[4][3][lanes], wide_mask active, const wide_inertia &a, const wide_inertia &b,
                   const wide3 &d, const wide3 &rA, const wide3 &rB) {
    auto angularA = cross(rA, d);
    auto angularB = cross(rB, d);
    auto inv_angularA = a.inv_inertia * angularA;
    auto inv_angularB = b.inv_inertia * angularB;
    wide3_store(to[0], angularA);
    wide3_store(to[1], angularB);
    wide3_store(to[2], inv_angularA);
    wide3_store(to[3], inv_angularB);
    auto k = ((a.inv_mass + b.inv_mass) + dot(angularA, inv_angularA)) + dot(angularB, inv_angularB);
    auto zero = wide_set(0);
    return select(active & (zero < k), wide_set(1) / k, zero);
}

// The tangents, rows and effective masses of a slot's lanes from their normals and lever arms,
// as prepare_contacts() works them out one point at a time (plane_space() included, both of its
// branches taken and the lane's chosen); zeros in the lanes without a point.
void make_slot_rows(contact_bundle_slot &slot, wide_mask active, const wide_inertia &a,
                    const wide_inertia &b) {
    auto n = wide3_load(slot.normal);
    auto rA = wide3_load(slot.rA), rB = wide3_load(slot.rB);
    auto zero = wide_set(0), one = wide_set(1);
    auto limit = wide_set(scalar(0.7071067811865476));
    auto near_z = (limit < n.z) | (limit < -n.z);
    auto a_z = n.y * n.y + n.z * n.z;
    auto a_xy = n.x * n.x + n.y * n.y;
    auto k_z = one / wide_sqrt(a_z);
    auto k_xy = one / wide_sqrt(a_xy);
    wide3 t0_z{zero, -n.z * k_z, n.y * k_z};
    wide3 t1_z{a_z * k_z, -n.x * t0_z.z, n.x * t0_z.y};
    wide3 t0_xy{-n.y * k_xy, n.x * k_xy, zero};
    wide3 t1_xy{-n.z * t0_xy.y, n.z * t0_xy.x, a_xy * k_xy};
    wide3 none{zero, zero, zero};
    wide3 tangent[2] = {select(active, select(near_z, t0_z, t0_xy), none),
                        select(active, select(near_z, t1_z, t1_xy), none)};
    wide3_store(slot.tangent[0], tangent[0]);
    wide3_store(slot.tangent[1], tangent[1]);
    wide_store(slot.normal_mass, make_wide_row(slot.normal_row, active, a, b, n, rA, rB));
    for (int t = 0; t < 2; ++t)
        wide_store(slot.tangent_mass[t],
                   make_wide_row(slot.tangent_row[t], active, a, b, tangent[t], rA, rB));
}

// Fills the bundle's slots from its constraints' points; lanes without a point get zeros, and
// so do the slots' totals.
void fill_bundle(contact_solver_set &contacts, std::uint32_t index, std::span<const solver_body> bodies) {
    auto &bundle = contacts.bundles[index];
    bundle.moves_a = bundle.moves_b = 0;
    for (std::uint32_t i = 0; i < lanes; ++i) {
        // A lane without points is empty: the static body on both sides.
        bundle.body[0][i] = bundle.body[1][i] = static_solver_body;
        bundle.friction[i] = 0;
        if (bundle.num_points[i] > 0) {
            auto &c = contacts.constraints[bundle.constraint[i]];
            bundle.body[0][i] = c.body[0];
            bundle.body[1][i] = c.body[1];
            bundle.friction[i] = c.friction;
        }
        if (moves(bodies[bundle.body[0][i]])) bundle.moves_a |= 1u << i;
        if (moves(bodies[bundle.body[1][i]])) bundle.moves_b |= 1u << i;
    }
    static const contact_solver_point empty_point{}; // zeros
    // The rows of the lanes' points are made here, side by side (prepare_contacts() left them).
    auto inertia_a = gather_inertia(bodies.data(), bundle.body[0]);
    auto inertia_b = gather_inertia(bodies.data(), bundle.body[1]);
    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        contacts.bundle_totals[bundle.first_slot + s] = {}; // every sub-step adds to them
        const contact_solver_point *points[lanes];
        for (std::uint32_t i = 0; i < lanes; ++i) {
            points[i] = &empty_point;
            if (s < bundle.num_points[i])
                points[i] = &contacts.points[contacts.constraints[bundle.constraint[i]].first_point + s];
        }
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        fill_slot(slot, points);
        make_slot_rows(slot, slot_mask(bundle, s), inertia_a, inertia_b);
    }
}

} // namespace

bool is_bundled(const contact_solver_constraint &c) noexcept {
    return c.num_points > 0 && !(c.spin_friction > 0) && c.num_roll_axes == 0 && c.spin_impulse == 0 &&
           !(c.stiffness < large_scalar);
}

namespace {

constexpr std::uint32_t buckets_per_side = contact_solver_constraint::max_points + 1;

fixed_side side_of_key(std::uint8_t key) noexcept {
    return fixed_side((key & bucket_key_mask) / buckets_per_side);
}

std::uint32_t points_of_key(std::uint8_t key) noexcept {
    return contact_solver_constraint::max_points - (key & bucket_key_mask) % buckets_per_side;
}

} // namespace

std::uint8_t pack_key(const contact_solver_constraint &c) noexcept {
    auto key = is_bundled(c) ? std::uint32_t(fixed_side_of(c)) * buckets_per_side +
                                   contact_solver_constraint::max_points - c.num_points
                             : std::uint32_t(unbundled_key);
    return static_cast<std::uint8_t>(key | (c.restitution > 0 ? bouncy_key : 0));
}

void pack_contact_bundles(contact_solver_set &contacts, std::span<const solver_body> bodies,
                          task_scheduler *scheduler) {
    contacts.bundles.clear();
    contacts.bundle_begin.clear();
    contacts.singles.clear();
    contacts.single_begin.clear();
    auto &begin = contacts.colour_begin;
    std::uint32_t num_slots = 0;

    // Room for the most the packing can make of this many constraints and points, and a quarter
    // more, so that the arrays grow only when the world does, not when its colours' sizes or
    // number change: a colour of n constraints makes at most n / lanes + 3 bundles (one
    // part-filled bundle per fixed side), and, sorted as they are, its bundles' slots number at
    // most its points / lanes + 3 * 4.
    constexpr std::size_t num_sides = 3;
    auto num_colours = begin.empty() ? std::size_t(0) : begin.size() - 1;
    auto max_points = std::size_t(contact_solver_constraint::max_points);
    auto reserve = [](auto &array, std::size_t size) {
        if (size > array.capacity()) array.reserve(size + size / 4);
    };
    reserve(contacts.bundles, contacts.constraints.size() / lanes + num_sides * num_colours);
    reserve(contacts.bundle_slots, contacts.points.size() / lanes + num_sides * max_points * num_colours);
    reserve(contacts.bundle_totals, contacts.bundle_slots.capacity());
    reserve(contacts.singles, contacts.constraints.size());
    reserve(contacts.packing, contacts.constraints.size());
    reserve(contacts.bundle_begin, num_colours + 1);
    reserve(contacts.single_begin, num_colours + 1);

    auto &keys = contacts.pack_keys;
    for (std::size_t k = 0; k + 1 < begin.size(); ++k) {
        contacts.bundle_begin.push_back(std::uint32_t(contacts.bundles.size()));
        contacts.single_begin.push_back(std::uint32_t(contacts.singles.size()));

        // The colour's bundled constraints sorted by their keys: by fixed side, then by point
        // count, most first, so that a bundle holds contacts of one side and its lanes mostly
        // have as many points as each other. Their order within a colour does not matter: they
        // share no body that moves.
        std::uint32_t first_of[unbundled_key + 1]{};
        for (auto i = begin[k]; i < begin[k + 1]; ++i) {
            auto bucket = keys[i] & bucket_key_mask;
            if (bucket != unbundled_key) {
                ++first_of[bucket + 1];
            } else {
                contacts.singles.push_back(i);
            }
        }
        for (std::size_t n = 1; n < std::size(first_of); ++n)
            first_of[n] += first_of[n - 1];
        contacts.packing.resize(first_of[unbundled_key]);
        for (auto i = begin[k]; i < begin[k + 1]; ++i) {
            auto bucket = keys[i] & bucket_key_mask;
            if (bucket != unbundled_key) contacts.packing[first_of[bucket]++] = i;
        }

        // Which constraint each lane holds; fill_bundle() reads the rest of them on the threads.
        for (std::size_t first = 0; first < contacts.packing.size();) {
            auto side = side_of_key(keys[contacts.packing[first]]);
            auto &bundle = contacts.bundles.emplace_back();
            bundle.fixed_side = side;
            bundle.first_slot = num_slots;
            bundle.num_slots = 0;
            bundle.full_slots = contact_solver_constraint::max_points;
            std::uint32_t filled = 0;
            for (std::uint32_t i = 0; i < lanes; ++i) {
                bundle.constraint[i] = 0;
                bundle.num_points[i] = 0;
                if (first + i < contacts.packing.size()) {
                    auto constraint = contacts.packing[first + i];
                    if (side_of_key(keys[constraint]) == side) {
                        bundle.constraint[i] = constraint;
                        bundle.num_points[i] = points_of_key(keys[constraint]);
                        ++filled;
                    }
                }
                bundle.num_slots = std::max(bundle.num_slots, bundle.num_points[i]);
                bundle.full_slots = std::min(bundle.full_slots, bundle.num_points[i]);
            }
            num_slots += bundle.num_slots;
            first += filled;
        }
    }
    if (!begin.empty()) {
        contacts.bundle_begin.push_back(std::uint32_t(contacts.bundles.size()));
        contacts.single_begin.push_back(std::uint32_t(contacts.singles.size()));
    }

    contacts.bundle_slots.resize(num_slots);
    contacts.bundle_totals.resize(num_slots);
    parallel_for(scheduler, 0u, std::uint32_t(contacts.bundles.size()), bundles_per_task,
                 [&](std::uint32_t i) { fill_bundle(contacts, i, bodies); });
}

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

template<fixed_side F>
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
    auto anchor_mass_scale = wide_set(pass.anchor.mass_scale);
    auto anchor_impulse_scale = wide_set(pass.anchor.impulse_scale);
    wide3 motion[contact_solver_constraint::max_points];

    // Normal rows of every point, then friction, as the one-at-a-time pass does.
    for (std::uint32_t s = 0; s < bundle.num_slots; ++s) {
        auto &slot = contacts.bundle_slots[bundle.first_slot + s];
        auto partial = s >= bundle.full_slots;
        auto before = velocities_of(a, b);
        auto normal = wide3_load(slot.normal);
        motion[s] = point_motion<F>(slot, a, b);
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
        auto impulse = -wide_load(slot.normal_mass) * mass_scale * (vn + bias) - impulse_scale * old_impulse;
        auto new_impulse = std_max(old_impulse + impulse, zero);
        apply_row<F>(row, normal, new_impulse - old_impulse, a, b);
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
        wide_row row[2];
        wide3 tangent[2];
        wide old_impulse[2], new_impulse[2], shared[2];
        for (int t = 0; t < 2; ++t) {
            row[t] = load_row(slot.tangent_row[t]);
            tangent[t] = wide3_load(slot.tangent[t]);
            old_impulse[t] = wide_load(slot.tangent_impulse[t]);
            auto vt = row_velocity<F>(row[t], tangent[t], a, b);
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
    with_fixed_side(bundle, [&](auto side) { solve_bundle<side()>(contacts, bundle, bodies, pass); });
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
