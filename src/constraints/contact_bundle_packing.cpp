#include "../math/wide_scalar.hpp"
#include "contact_bundle_solver.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include <cstddef>

// Packing a step's bundled contacts into bundles and filling their slots; their passes are in
// contact_bundle_solver.cpp.

namespace edyn::detail {

namespace {

constexpr std::uint32_t bundle_lanes = contact_bundle_lanes;

// Bundles per parallel range when filling their slots.
constexpr std::size_t bundles_per_task = 16;

// A slot is its lanes' points side by side: the k-th scalar of contact_solver_point becomes the
// slot's k-th array, of one scalar per lane. Filling it is a transposition of the scalars before
// the rows (make_slot_rows() makes the tangents, masses and rows over them).
constexpr std::size_t point_scalars = sizeof(contact_solver_point) / sizeof(scalar);
constexpr std::size_t carried_scalars = offsetof(contact_solver_point, normal_row) / sizeof(scalar);
static_assert(sizeof(contact_solver_point) == point_scalars * sizeof(scalar) &&
              sizeof(contact_bundle_slot) == point_scalars * bundle_lanes * sizeof(scalar));
static_assert(
    offsetof(contact_solver_point, tangent) == offsetof(contact_bundle_slot, tangent) / bundle_lanes &&
    offsetof(contact_solver_point, adjusted_separation) ==
        offsetof(contact_bundle_slot, adjusted_separation) / bundle_lanes &&
    offsetof(contact_solver_point, normal_mass) ==
        offsetof(contact_bundle_slot, normal_mass) / bundle_lanes &&
    offsetof(contact_solver_point, normal_impulse) ==
        offsetof(contact_bundle_slot, normal_impulse) / bundle_lanes &&
    offsetof(contact_solver_point, normal_row) == offsetof(contact_bundle_slot, normal_row) / bundle_lanes &&
    offsetof(contact_solver_point, tangent_row) == offsetof(contact_bundle_slot, tangent_row) / bundle_lanes);

void fill_slot(contact_bundle_slot &slot, const contact_solver_point *(&points)[bundle_lanes]) {
    const scalar *in[bundle_lanes];
    for (std::uint32_t i = 0; i < bundle_lanes; ++i)
        in[i] = reinterpret_cast<const scalar *>(points[i]);
    auto *out = reinterpret_cast<scalar *>(&slot);
    std::size_t k = 0;
#if defined(EDYN_WIDE_AVX2)
    for (; k + bundle_lanes <= carried_scalars; k += bundle_lanes) {
        __m256 g[bundle_lanes];
        for (std::uint32_t i = 0; i < bundle_lanes; ++i)
            g[i] = _mm256_loadu_ps(in[i] + k);
        transpose(g);
        for (std::uint32_t r = 0; r < bundle_lanes; ++r)
            _mm256_storeu_ps(out + (k + r) * bundle_lanes, g[r]);
    }
#elif defined(EDYN_WIDE_SSE2)
    for (; k + bundle_lanes <= carried_scalars; k += bundle_lanes) {
        __m128 g[bundle_lanes];
        for (std::uint32_t i = 0; i < bundle_lanes; ++i)
            g[i] = _mm_loadu_ps(in[i] + k);
        _MM_TRANSPOSE4_PS(g[0], g[1], g[2], g[3]);
        for (std::uint32_t r = 0; r < bundle_lanes; ++r)
            _mm_storeu_ps(out + (k + r) * bundle_lanes, g[r]);
    }
#endif
    for (; k < carried_scalars; ++k)
        for (std::uint32_t i = 0; i < bundle_lanes; ++i)
            out[k * bundle_lanes + i] = in[i][k];
}

void wide3_store(scalar (&p)[3][bundle_lanes], const wide3 &v) {
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

wide_inertia gather_inertia(const solver_body *bodies, const solver_body_index (&index)[bundle_lanes]) {
    scalar m[10][bundle_lanes];
    for (std::uint32_t i = 0; i < bundle_lanes; ++i) {
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
wide make_wide_row(scalar (&to)[4][3][bundle_lanes], wide_mask active, const wide_inertia &a,
                   const wide_inertia &b, const wide3 &d, const wide3 &rA, const wide3 &rB) {
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
    bundle.holds = false;
    for (std::uint32_t i = 0; i < bundle_lanes; ++i) {
        // A lane without points is empty: the static body on both sides.
        bundle.body[0][i] = bundle.body[1][i] = static_solver_body;
        bundle.friction[i] = 0;
        bundle.held[i] = 0;
        if (bundle.num_points[i] > 0) {
            auto &c = contacts.constraints[bundle.constraint[i]];
            bundle.body[0][i] = c.body[0];
            bundle.body[1][i] = c.body[1];
            bundle.friction[i] = c.friction;
            if (bundle.fixed_side == fixed_side::none) bundle.held[i] = static_cast<std::uint32_t>(c.held);
            bundle.holds = bundle.holds || bundle.held[i] != 0;
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
        const contact_solver_point *points[bundle_lanes];
        for (std::uint32_t i = 0; i < bundle_lanes; ++i) {
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
    reserve(contacts.bundles, contacts.constraints.size() / bundle_lanes + num_sides * num_colours);
    reserve(contacts.bundle_slots,
            contacts.points.size() / bundle_lanes + num_sides * max_points * num_colours);
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
            for (std::uint32_t i = 0; i < bundle_lanes; ++i) {
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
} // namespace edyn::detail
