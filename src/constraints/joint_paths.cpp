#include "edyn/constraints/joint_paths.hpp"
#include "../math/wide_scalar.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>

namespace edyn {

namespace {

// Paths per block handed to one thread at a time.
constexpr std::uint32_t paths_per_task = 16;

// Pivots closer than this (m², a micrometre apart) need no correction at a sub-step's first pass.
constexpr scalar path_tolerance_sqr = scalar(1e-12);

// Ten micrometres, squared (m²): a path whose widest gap is narrower is left by a sub-step's
// later passes. The first pass solved it exactly; what opened it since is the passes of the paths
// it meets, which the later passes settle, and gaps this narrow are for the next sub-step. With
// 1 µm instead, the 64 rag dolls of edyn-bench take 3.5 % more instructions for the same worst
// joint error (0.088 mm).
constexpr scalar settled_gap_sqr = scalar(1e-10);

// A millimetre, squared (m²): an isolated path whose widest gap at a pass was narrower is left
// by the later passes, as the pass's solve leaves of a gap g about g^2 / l at lever arms l, a
// few micrometres at a chain's links; a wider gap has its path factored again.
constexpr scalar wide_gap_sqr = scalar(1e-6);

// A Schur complement whose determinant falls below this fraction of the cube of its mean
// eigenvalue is too badly conditioned to invert in the scalar's precision.
constexpr scalar min_conditioning = scalar(1e-6);

// A row of a path_block as one register. Every operation on rows below is the matrix3x3 or
// vector3 operation of the same name, component by component in the same order, so that the
// padding changes no result.
using row4 = scalar __attribute__((vector_size(4 * sizeof(scalar))));

row4 load_row(const path_block &m, int i) noexcept {
    row4 r;
    std::memcpy(&r, m.row[i], sizeof r);
    return r;
}

void store_row(path_block &m, int i, row4 r) noexcept { std::memcpy(m.row[i], &r, sizeof r); }

row4 to_row(const vector3 &v) noexcept { return row4{v.x, v.y, v.z, 0}; }

vector3 to_vector(row4 r) noexcept { return {r[0], r[1], r[2]}; }

// v^T m, as vector3 * matrix3x3 computes it: m's rows weighted by v.
row4 weighted_rows(const path_block &m, const vector3 &v) noexcept {
    return (load_row(m, 0) * v.x + load_row(m, 1) * v.y) + load_row(m, 2) * v.z;
}

// m v, as matrix3x3 * vector3 computes it.
vector3 times(const path_block &m, const vector3 &v) noexcept {
    auto dot_row = [&](int i) { return m.row[i][0] * v.x + m.row[i][1] * v.y + m.row[i][2] * v.z; };
    return {dot_row(0), dot_row(1), dot_row(2)};
}

bool invert_pivot_block(const path_block &d, path_block &inverse_d) noexcept {
    const vector3 d0{d.row[0][0], d.row[0][1], d.row[0][2]}, d1{d.row[1][0], d.row[1][1], d.row[1][2]},
        d2{d.row[2][0], d.row[2][1], d.row[2][2]};
    auto c0 = cross(d1, d2), c1 = cross(d2, d0), c2 = cross(d0, d1);
    auto det = dot(d0, c0);
    auto mean = (d0.x + d1.y + d2.z) / 3;
    if (!(mean > 0) || !(det > min_conditioning * mean * mean * mean)) return false;
    // The cofactors are the inverse's columns.
    auto inv_det = scalar(1) / det;
    store_row(inverse_d, 0, row4{c0.x, c1.x, c2.x, 0} * inv_det);
    store_row(inverse_d, 1, row4{c0.y, c1.y, c2.y, 0} * inv_det);
    store_row(inverse_d, 2, row4{c0.z, c1.z, c2.z, 0} * inv_det);
    return true;
}

} // namespace

void build_joint_paths(joint_path_set &set, std::span<joint_anchor *const> pivots,
                       std::span<const solver_body_index> other_projected,
                       std::span<const solver_body> bodies) {
    auto &b = set.build;
    auto num_pivots = static_cast<std::uint32_t>(pivots.size());
    b.degree.assign(bodies.size(), 0);
    b.pivot_degree.assign(bodies.size(), 0);
    b.incident.resize(2 * bodies.size());
    for (std::uint32_t i = 0; i < num_pivots; ++i) {
        for (auto body : pivots[i]->body) {
            if (!moves(bodies[body])) continue;
            ++b.degree[body];
            auto k = b.pivot_degree[body]++;
            if (k < 2) b.incident[2 * body + k] = i;
        }
    }
    for (auto body : other_projected)
        if (moves(bodies[body])) ++b.degree[body];

    // A body links the two pivots it holds into one path when nothing else the projection moves
    // touches it.
    auto links = [&](solver_body_index body) { return b.degree[body] == 2 && b.pivot_degree[body] == 2; };
    auto across = [&](solver_body_index body, std::uint32_t i) {
        return b.incident[2 * body] == i ? b.incident[2 * body + 1] : b.incident[2 * body];
    };
    auto side_of = [&](std::uint32_t i, solver_body_index body) {
        return pivots[i]->body[0] == body ? 0u : 1u;
    };

    b.visited.assign(num_pivots, 0);
    b.anchors.clear();
    b.shared_side.clear();
    b.path_begin.clear();
    b.path_colour.clear();
    b.path_isolated.clear();
    b.colouring.reset(bodies);
    for (std::uint32_t u = 0; u < num_pivots; ++u) {
        if (b.visited[u]) continue;
        // Back from u to the first pivot of its path, leaving each through `out`: a ring of
        // links comes back to u, and is then opened at u's first body.
        auto start = u;
        std::uint32_t out = 0;
        for (;;) {
            auto body = pivots[start]->body[out];
            if (!links(body)) break;
            auto previous = across(body, start);
            if (previous == u) {
                start = u;
                out = 0u;
                break;
            }
            out = 1u - side_of(previous, body);
            start = previous;
        }
        // Then forward to its last.
        auto first_body = pivots[start]->body[out];
        auto last_body = first_body;
        b.path_begin.push_back(static_cast<std::uint32_t>(b.anchors.size()));
        b.shared_side.push_back(0);
        for (std::uint32_t i = start, in = out;;) {
            b.visited[i] = 1;
            b.anchors.push_back(pivots[i]);
            auto next_side = 1u - in;
            auto body = pivots[i]->body[next_side];
            auto next = links(body) ? across(body, i) : i;
            if (next == i || b.visited[next]) {
                last_body = body;
                break;
            }
            in = side_of(next, body);
            b.shared_side.push_back(static_cast<std::uint8_t>(in | (next_side << 1)));
            i = next;
        }
        auto length = static_cast<std::uint32_t>(b.anchors.size()) - b.path_begin.back();
        auto ends_here = [&](solver_body_index body) { return !moves(bodies[body]) || b.degree[body] == 1; };
        b.path_isolated.push_back(ends_here(first_body) && ends_here(last_body));
        // Only its end bodies can be shared with other paths.
        b.path_colour.push_back(b.colouring.assign(first_body, last_body, length));
    }

    // The paths in colour order, each colour's in the order found.
    auto num_paths = static_cast<std::uint32_t>(b.path_colour.size());
    auto num_anchors = static_cast<std::uint32_t>(b.anchors.size());
    b.path_begin.push_back(num_anchors);
    b.colouring.colour_ranges(b.colour_begin);
    set.anchors.resize(num_anchors);
    set.shared_side.resize(num_anchors);
    set.path_begin.resize(num_paths + 1);
    set.isolated.resize(num_paths);
    for (std::uint32_t p = 0; p < num_paths; ++p) {
        auto from = b.path_begin[p], length = b.path_begin[p + 1] - from;
        auto place = b.colouring.next_place(b.path_colour[p], length);
        set.path_begin[place.constraint] = place.first_point;
        set.isolated[place.constraint] = b.path_isolated[p];
        for (std::uint32_t k = 0; k < length; ++k) {
            set.anchors[place.first_point + k] = b.anchors[from + k];
            set.shared_side[place.first_point + k] = b.shared_side[from + k];
        }
    }
    set.path_begin[num_paths] = num_anchors;

    set.block_begin.clear();
    set.colour_block_begin.clear();
    for (std::size_t k = 0; k + 1 < b.colour_begin.size(); ++k) {
        set.colour_block_begin.push_back(static_cast<std::uint32_t>(set.block_begin.size()));
        for (auto p = b.colour_begin[k]; p < b.colour_begin[k + 1]; p += paths_per_task)
            set.block_begin.push_back(p);
    }
    set.colour_block_begin.push_back(static_cast<std::uint32_t>(set.block_begin.size()));
    set.block_begin.push_back(num_paths);

    set.poses.resize(num_anchors);
    set.inverse_pivot.resize(num_anchors);
    set.coupling.resize(num_anchors);
    set.work.resize(num_anchors);
    set.factored.assign(num_paths, 0);
    set.widest_gap.assign(num_paths, 0);
}

namespace {

// What each pivot of a path contributes to the path's system on its own, measured
// detail::wide_lanes pivots at a time: K_kk, the inverse of K_kk that the joint keeps for its
// velocity passes, and K_k-1,k. Each lane computes K and its inverse operation for operation as
// point_mass_matrix() and inverse_point_mass() do (wide_scalar.hpp has no fused multiply-adds),
// so that a joint keeps the bits update_point_mass() would give it.
namespace wide_blocks {

using detail::wide;
using detail::wide3;
using detail::wide_matrix3x3;
constexpr std::uint32_t lanes = detail::wide_lanes;

// One array of lanes per scalar the lanes read.
struct lane_inputs {
    scalar mass_a[lanes], mass_b[lanes]; // The bodies' inverse masses.
    scalar rA[3][lanes], rB[3][lanes];
    scalar inertia_a[9][lanes], inertia_b[9][lanes];
    // For K_k-1,k: the shared body's lever arm in the pivot before, 1 where the shared body is
    // this pivot's body B (else A), and -1 where it is on different sides of the two joints.
    scalar r_previous[3][lanes];
    scalar shared_is_b[lanes];
    scalar sign[lanes];
};

void put(scalar (&lane_arrays)[3][lanes], std::uint32_t lane, const vector3 &v) noexcept {
    lane_arrays[0][lane] = v.x;
    lane_arrays[1][lane] = v.y;
    lane_arrays[2][lane] = v.z;
}

void put(scalar (&lane_arrays)[9][lanes], std::uint32_t lane, const matrix3x3 &m) noexcept {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            lane_arrays[3 * i + j][lane] = m[i][j];
}

wide_matrix3x3 load(const scalar (&lane_arrays)[9][lanes]) noexcept {
    wide_matrix3x3 m;
    for (int i = 0; i < 3; ++i)
        m.row[i] = {detail::wide_load(lane_arrays[3 * i]), detail::wide_load(lane_arrays[3 * i + 1]),
                    detail::wide_load(lane_arrays[3 * i + 2])};
    return m;
}

// The rows of [v], as constraint_row.cpp writes them.
void skew_rows(const wide3 &v, wide3 (&rows)[3]) noexcept {
    auto zero = detail::wide_set(0);
    rows[0] = {zero, -v.z, v.y};
    rows[1] = {v.z, zero, -v.x};
    rows[2] = {-v.y, v.x, zero};
}

// The upper triangle of -[r] I [r] for a symmetric I, as point_mass_matrix() computes it: xx,
// xy, xz, yy, yz, zz.
struct wide_symmetric {
    wide xx, xy, xz, yy, yz, zz;
};

wide_symmetric lever_inertia(const wide3 &r, const wide_matrix3x3 &inertia) noexcept {
    wide3 s[3];
    skew_rows(r, s);
    const wide3 u[3]{inertia * s[0], inertia * s[1], inertia * s[2]};
    return {dot(s[0], u[0]), dot(s[0], u[1]), dot(s[0], u[2]),
            dot(s[1], u[1]), dot(s[1], u[2]), dot(s[2], u[2])};
}

// -[u] I [v]: how a point at lever arm u of a body moves, through the body's turning, under a
// unit impulse at lever arm v. Entry (i, j) is (e_i x u) . I (e_j x v).
wide_matrix3x3 lever_product(const wide3 &u, const wide_matrix3x3 &inertia, const wide3 &v) noexcept {
    wide3 s[3], t[3];
    skew_rows(u, s);
    skew_rows(v, t);
    const wide3 w[3]{inertia * t[0], inertia * t[1], inertia * t[2]};
    wide_matrix3x3 m;
    for (int i = 0; i < 3; ++i)
        m.row[i] = {dot(s[i], w[0]), dot(s[i], w[1]), dot(s[i], w[2])};
    return m;
}

// Measures the blocks of the pivots added to it, a lane each, whenever its lanes are full and
// when flushed: K_kk into set.inverse_pivot[k] (inverted there by factor_path()), its inverse into
// the joint, marked current for the next warm_point_mass(), and for a pivot after the first of its
// path K_k-1,k into set.coupling[k]. The pivots may come from any paths of one colour: they share
// no moving body, so that each path's poses stay as measured until the path itself moves.
class lane_batch {
public:
    lane_batch(joint_path_set &set, std::span<const solver_body> bodies) noexcept
        : set(set)
        , bodies(bodies) {}

    // Pivot k, after the first of its path when `coupled`.
    void add(std::uint32_t k, bool coupled) noexcept {
        fill(count, k, coupled);
        pivot[count] = k;
        has_coupling[count] = coupled;
        if (++count == lanes) flush();
    }

    void flush() noexcept;

private:
    void fill(std::uint32_t lane, std::uint32_t k, bool coupled) noexcept;

    joint_path_set &set;
    std::span<const solver_body> bodies;
    lane_inputs in;
    std::uint32_t pivot[lanes];
    bool has_coupling[lanes];
    std::uint32_t count{0};
};

void lane_batch::fill(std::uint32_t lane, std::uint32_t k, bool coupled) noexcept {
    auto &anchor = *set.anchors[k];
    auto &pose = set.poses[k];
    auto &a = bodies[anchor.body[0]];
    auto &b = bodies[anchor.body[1]];
    in.mass_a[lane] = a.inv_mass;
    in.mass_b[lane] = b.inv_mass;
    put(in.rA, lane, pose.rA);
    put(in.rB, lane, pose.rB);
    put(in.inertia_a, lane, a.inv_inertia);
    put(in.inertia_b, lane, b.inv_inertia);
    if (!coupled) {
        put(in.r_previous, lane, vector3_zero);
        in.shared_is_b[lane] = 0;
        in.sign[lane] = 1;
        return;
    }
    // K_k-1,k: how pivot k-1 moves under an impulse at pivot k, through their shared body; the
    // sign is + when the body is on the same side of both joints.
    auto side = set.shared_side[k];
    bool here_second = side & 1, previous_second = (side >> 1) & 1;
    put(in.r_previous, lane, previous_second ? set.poses[k - 1].rB : set.poses[k - 1].rA);
    in.shared_is_b[lane] = here_second ? scalar(1) : scalar(0);
    in.sign[lane] = here_second != previous_second ? scalar(-1) : scalar(1);
}

void lane_batch::flush() noexcept {
    using detail::wide_load;
    using detail::wide_set;
    using detail::wide_store;
    if (count == 0) return;
    // Lanes left empty repeat the first, and are not stored.
    for (auto lane = count; lane < lanes; ++lane)
        fill(lane, pivot[0], has_coupling[0]);

    // K = diagonal_matrix(the masses) + the two lever terms, summed in point_mass_matrix()'s
    // order.
    auto zero = wide_set(0);
    auto mass_a = wide_load(in.mass_a), mass_b = wide_load(in.mass_b);
    auto mass = mass_a + mass_b;
    auto rA = detail::wide3_load(in.rA), rB = detail::wide3_load(in.rB);
    auto inertia_a = load(in.inertia_a), inertia_b = load(in.inertia_b);
    auto la = lever_inertia(rA, inertia_a);
    auto lb = lever_inertia(rB, inertia_b);
    const wide3 k0{(mass + la.xx) + lb.xx, (zero + la.xy) + lb.xy, (zero + la.xz) + lb.xz};
    const wide3 k1{(zero + la.xy) + lb.xy, (mass + la.yy) + lb.yy, (zero + la.yz) + lb.yz};
    const wide3 k2{(zero + la.xz) + lb.xz, (zero + la.yz) + lb.yz, (mass + la.zz) + lb.zz};
    // Its inverse from the cofactors, as inverse_point_mass() makes it.
    auto c0 = cross(k1, k2), c1 = cross(k2, k0), c2 = cross(k0, k1);
    auto det = dot(k0, c0);
    auto valid = (wide_set(scalar(1e-12)) < det) | (det < wide_set(scalar(-1e-12)));
    auto inv_det = wide_set(1) / det;
    // The coupling: diagonal_matrix(the shared body's inverse mass) + the lever product, negated
    // where the sides differ.
    auto shared_is_b = zero < wide_load(in.shared_is_b);
    auto shared_mass = select(shared_is_b, mass_b, mass_a), sign = wide_load(in.sign);
    wide_matrix3x3 shared_inertia;
    for (int i = 0; i < 3; ++i)
        shared_inertia.row[i] = detail::select(shared_is_b, inertia_b.row[i], inertia_a.row[i]);
    auto lp =
        lever_product(detail::wide3_load(in.r_previous), shared_inertia, detail::select(shared_is_b, rB, rA));

    scalar k_out[9][lanes], inverse_out[9][lanes], coupling_out[9][lanes], valid_out[lanes];
    const wide3 *k_rows[3]{&k0, &k1, &k2};
    const wide3 *cofactors[3]{&c0, &c1, &c2};
    for (int i = 0; i < 3; ++i) {
        const wide k_row[3]{k_rows[i]->x, k_rows[i]->y, k_rows[i]->z};
        const wide lp_row[3]{lp.row[i].x, lp.row[i].y, lp.row[i].z};
        for (int j = 0; j < 3; ++j) {
            const wide cofactor = i == 0 ? cofactors[j]->x : i == 1 ? cofactors[j]->y : cofactors[j]->z;
            wide_store(k_out[3 * i + j], k_row[j]);
            wide_store(inverse_out[3 * i + j], select(valid, cofactor * inv_det, zero));
            wide_store(coupling_out[3 * i + j], ((i == j ? shared_mass : zero) + lp_row[j]) * sign);
        }
    }
    wide_store(valid_out, select(valid, wide_set(1), zero));

    for (std::uint32_t lane = 0; lane < count; ++lane) {
        auto k = pivot[lane];
        auto &anchor = *set.anchors[k];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                set.inverse_pivot[k].row[i][j] = k_out[3 * i + j][lane];
                anchor.point_mass[i][j] = inverse_out[3 * i + j][lane];
                if (has_coupling[lane]) set.coupling[k].row[i][j] = coupling_out[3 * i + j][lane];
            }
            set.inverse_pivot[k].row[i][3] = 0;
            set.coupling[k].row[i][3] = 0;
        }
        anchor.point_mass_valid = valid_out[lane] != 0;
        anchor.point_mass_current = true;
    }
    count = 0;
}

} // namespace wide_blocks

// The block-tridiagonal system K p = rhs of a path's pivots at set.poses, factored from its first
// pivot to its last: D_k = K_kk - K_k,k-1 D_k-1^-1 K_k-1,k, from the blocks a lane_batch measured.
// K is measured at the present poses: taken where the sub-step's warm start measured it, a
// sub-step's turning earlier, it no longer matches the separations, and the whipping end of a
// swinging 100-link chain blew up within 200 steps. Each joint's own K_kk is kept for the relax
// pass and the next sub-step's velocity passes (point_mass_current), which would otherwise
// measure it again at nearly the same poses. False when a block cannot be inverted.
bool factor_path(joint_path_set &set, std::uint32_t first, std::uint32_t last) {
    for (auto k = first; k < last; ++k) {
        auto d = set.inverse_pivot[k];
        if (k > first) {
            // G = D_k-1^-1 C, row by row as matrix3x3's product; then D_k = K_kk - C^T G, whose
            // row i is G's rows weighted by C's column i.
            auto &c = set.coupling[k];
            auto &previous = set.inverse_pivot[k - 1];
            const row4 c_rows[3]{load_row(c, 0), load_row(c, 1), load_row(c, 2)};
            row4 g[3];
            for (int i = 0; i < 3; ++i)
                g[i] = (c_rows[0] * previous.row[i][0] + c_rows[1] * previous.row[i][1]) +
                       c_rows[2] * previous.row[i][2];
            for (int i = 0; i < 3; ++i)
                store_row(d, i,
                          load_row(d, i) - ((g[0] * c.row[0][i] + g[1] * c.row[1][i]) + g[2] * c.row[2][i]));
            for (int i = 0; i < 3; ++i)
                store_row(c, i, g[i]);
        }
        if (!invert_pivot_block(d, set.inverse_pivot[k])) return false;
    }
    return true;
}

// What is left of a path's pass once its poses are measured.
enum class path_step : std::uint8_t {
    done,   // Nothing: left as it is, or projected one joint at a time.
    factor, // Factor, then solve: its blocks are in a lane_batch.
    solve,  // Solve with the factors of an earlier pass.
};

void one_at_a_time(joint_path_set &set, std::uint32_t p, std::span<solver_body> bodies, scalar fraction,
                   scalar inv_h) {
    for (auto k = set.path_begin[p]; k < set.path_begin[p + 1]; ++k) {
        auto &anchor = *set.anchors[k];
        project_point(anchor, bodies[anchor.body[0]], bodies[anchor.body[1]], fraction, inv_h);
    }
}

// The first half of a path's pass: measures its poses and decides what is left to do, handing its
// pivots to `batch` when it is to be factored.
path_step begin_path(joint_path_set &set, std::uint32_t p, std::span<solver_body> bodies, scalar fraction,
                     scalar inv_h, bool refactor, wide_blocks::lane_batch &batch) {
    auto first = set.path_begin[p], last = set.path_begin[p + 1];
    // A path that meets nothing else the projection moves is solved in full by the first pass.
    if (!refactor && set.isolated[p] && set.widest_gap[p] < wide_gap_sqr && last - first > 1)
        return path_step::done;
    if (last - first == 1 || (!refactor && !set.factored[p])) {
        one_at_a_time(set, p, bodies, fraction, inv_h);
        return path_step::done;
    }
    // The widest gap of the pass before: past a millimetre, its corrections turned the bodies
    // enough that the factors made before them no longer fit.
    auto previous_widest = set.widest_gap[p];
    scalar widest = 0;
    for (auto k = first; k < last; ++k) {
        auto &anchor = *set.anchors[k];
        set.poses[k] = current_pose(anchor, bodies[anchor.body[0]], bodies[anchor.body[1]]);
        widest = std::max(widest, length_sqr(set.poses[k].d));
    }
    set.widest_gap[p] = widest;
    bool apart = widest > (refactor ? path_tolerance_sqr : settled_gap_sqr);
    // Wide gaps mean large turns, before or after which the factors made earlier no longer match
    // the poses: they are made again.
    if (refactor || std::max(widest, previous_widest) >= wide_gap_sqr) {
        set.factored[p] = 0;
        if (!apart) return path_step::done;
        for (auto k = first; k < last; ++k)
            batch.add(k, k > first);
        return path_step::factor;
    }
    if (!apart) return path_step::done;
    if (!set.factored[p]) {
        one_at_a_time(set, p, bodies, fraction, inv_h);
        return path_step::done;
    }
    return path_step::solve;
}

// The second half: factors the path if begin_path() said so, and moves its bodies.
void finish_path(joint_path_set &set, std::uint32_t p, std::span<solver_body> bodies, scalar fraction,
                 scalar inv_h, path_step step) {
    auto first = set.path_begin[p], last = set.path_begin[p + 1];
    if (step == path_step::factor) {
        set.factored[p] = factor_path(set, first, last);
        if (!set.factored[p]) {
            one_at_a_time(set, p, bodies, fraction, inv_h);
            return;
        }
    }
    // Forward: y_k = -fraction d_k - K_k,k-1 D_k-1^-1 y_k-1; back: p_k = D_k^-1 y_k - G_k+1 p_k+1.
    auto &work = set.work;
    work[first] = set.poses[first].d * -fraction;
    for (auto k = first + 1; k < last; ++k)
        work[k] = to_vector(to_row(set.poses[k].d) * -fraction - weighted_rows(set.coupling[k], work[k - 1]));
    work[last - 1] = times(set.inverse_pivot[last - 1], work[last - 1]);
    for (auto k = last - 1; k-- > first;)
        work[k] = times(set.inverse_pivot[k], work[k]) - times(set.coupling[k + 1], work[k + 1]);
    // Each body moves once: a body shared by two pivots takes both their corrections in one turn.
    vector3 carried_dv = vector3_zero, carried_dw = vector3_zero;
    for (auto k = first; k < last; ++k) {
        auto &anchor = *set.anchors[k];
        auto &pose = set.poses[k];
        vector3 dv[2], dw[2];
        for (unsigned side = 0; side < 2; ++side) {
            auto &body = bodies[anchor.body[side]];
            auto impulse = side == 0 ? work[k] : -work[k];
            dv[side] = impulse * body.inv_mass;
            dw[side] = body.inv_inertia * cross(side == 0 ? pose.rA : pose.rB, impulse);
        }
        if (k > first) {
            auto side = set.shared_side[k] & 1;
            dv[side] += carried_dv;
            dw[side] += carried_dw;
        }
        // The body shared with the next pivot waits for that pivot's correction.
        auto carried_side = k + 1 < last ? (set.shared_side[k + 1] >> 1) & 1 : 2u;
        for (unsigned side = 0; side < 2; ++side) {
            if (side == carried_side) {
                carried_dv = dv[side];
                carried_dw = dw[side];
            } else {
                move_body(bodies[anchor.body[side]], dv[side], dw[side], inv_h);
            }
        }
    }
}

} // namespace

namespace {

// Projects the paths of one block, which are of one colour: all of them are measured, then all
// of them move.
void project_path_block(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                        bool refactor, std::uint32_t block) {
    auto from = set.block_begin[block], to = set.block_begin[block + 1];
    path_step steps[paths_per_task];
    wide_blocks::lane_batch batch(set, bodies);
    for (auto p = from; p < to; ++p)
        steps[p - from] = begin_path(set, p, bodies, fraction, inv_h, refactor, batch);
    batch.flush();
    for (auto p = from; p < to; ++p)
        if (steps[p - from] != path_step::done) finish_path(set, p, bodies, fraction, inv_h, steps[p - from]);
}

} // namespace

void project_joint_paths(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                         bool refactor, task_scheduler *scheduler) {
    parallel_for_stages(scheduler, set.sync, set.colour_block_begin, [&](std::size_t, std::uint32_t block) {
        project_path_block(set, bodies, fraction, inv_h, refactor, block);
    });
}

void project_joint_paths(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                         bool refactor, stage_queue &queue) {
    auto *paths = &set;
    for (std::size_t k = 0; k + 1 < set.colour_block_begin.size(); ++k) {
        auto first = set.colour_block_begin[k];
        queue.add(set.colour_block_begin[k + 1] - first,
                  [paths, bodies, fraction, inv_h, refactor, first](std::uint32_t b) {
                      project_path_block(*paths, bodies, fraction, inv_h, refactor, first + b);
                  });
    }
}

} // namespace edyn
