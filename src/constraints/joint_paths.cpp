#include "edyn/constraints/joint_paths.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

namespace {

// Paths per block handed to one thread at a time.
constexpr std::uint32_t paths_per_task = 16;

// Pivots closer than this (m², a tenth of a micrometre apart) need no correction, as in
// project_point.
constexpr scalar path_tolerance_sqr = scalar(1e-12);

// A millimetre, squared (m²): an isolated path whose widest gap at a pass was narrower is left
// by the later passes, as the pass's solve leaves of a gap g about g^2 / l at lever arms l, a
// few micrometres at a chain's links; a wider gap has its path factored again.
constexpr scalar wide_gap_sqr = scalar(1e-6);

// A Schur complement whose determinant falls below this fraction of the cube of its mean
// eigenvalue is too badly conditioned to invert in the scalar's precision.
constexpr scalar min_conditioning = scalar(1e-6);

bool invert_pivot_block(const matrix3x3 &d, matrix3x3 &inverse_d) noexcept {
    auto c0 = cross(d[1], d[2]), c1 = cross(d[2], d[0]), c2 = cross(d[0], d[1]);
    auto det = dot(d[0], c0);
    auto mean = (d[0][0] + d[1][1] + d[2][2]) / 3;
    if (!(mean > 0) || !(det > min_conditioning * mean * mean * mean)) return false;
    inverse_d = matrix3x3_columns(c0, c1, c2) * (scalar(1) / det);
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

// The block-tridiagonal system K p = rhs of a path's pivots at set.poses, factored from its first
// pivot to its last: D_k = K_kk - K_k,k-1 D_k-1^-1 K_k-1,k. K is measured at the present poses:
// taken where the sub-step's warm start measured it, a sub-step's turning earlier, it no longer
// matches the separations, and the whipping end of a swinging 100-link chain blew up within
// 200 steps. Each joint's own K_kk is kept for the relax pass and the next sub-step's velocity
// passes (keep_point_mass), which would otherwise measure it again at nearly the same poses.
// False when a block cannot be inverted.
bool factor_path(joint_path_set &set, std::uint32_t first, std::uint32_t last,
                 std::span<const solver_body> bodies) {
    for (auto k = first; k < last; ++k) {
        auto &anchor = *set.anchors[k];
        auto &pose = set.poses[k];
        auto d = point_mass_matrix(bodies[anchor.body[0]], bodies[anchor.body[1]], pose);
        keep_point_mass(anchor, d);
        if (k > first) {
            // K_k-1,k: how pivot k-1 moves under an impulse at pivot k, through their shared body;
            // the sign is + when the body is on the same side of both joints.
            auto side = set.shared_side[k];
            bool here_second = side & 1, previous_second = (side >> 1) & 1;
            auto &shared = bodies[anchor.body[here_second ? 1 : 0]];
            auto &r_here = here_second ? pose.rB : pose.rA;
            auto &r_previous = previous_second ? set.poses[k - 1].rB : set.poses[k - 1].rA;
            auto c = diagonal_matrix(vector3_one * shared.inv_mass) +
                     lever_product(r_previous, shared.inv_inertia, r_here);
            if (here_second != previous_second) c = c * scalar(-1);
            auto g = set.inverse_pivot[k - 1] * c;
            set.coupling[k] = g;
            d = d - transpose(c) * g;
        }
        if (!invert_pivot_block(d, set.inverse_pivot[k])) return false;
    }
    return true;
}

void project_path(joint_path_set &set, std::uint32_t p, std::span<solver_body> bodies, scalar fraction,
                  scalar inv_h, bool refactor) {
    auto first = set.path_begin[p], last = set.path_begin[p + 1];
    auto one_at_a_time = [&] {
        for (auto k = first; k < last; ++k) {
            auto &anchor = *set.anchors[k];
            project_point(anchor, bodies[anchor.body[0]], bodies[anchor.body[1]], fraction, inv_h);
        }
    };
    // A path that meets nothing else the projection moves is solved in full by the first pass.
    if (!refactor && set.isolated[p] && set.widest_gap[p] < wide_gap_sqr && last - first > 1) return;
    if (last - first == 1 || (!refactor && !set.factored[p])) {
        one_at_a_time();
        return;
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
    bool apart = widest > path_tolerance_sqr;
    // Wide gaps mean large turns, before or after which the factors made earlier no longer match
    // the poses: they are made again.
    if (refactor || std::max(widest, previous_widest) >= wide_gap_sqr)
        set.factored[p] = apart && factor_path(set, first, last, bodies);
    if (!apart) return;
    if (!set.factored[p]) {
        one_at_a_time();
        return;
    }
    // Forward: y_k = -fraction d_k - K_k,k-1 D_k-1^-1 y_k-1; back: p_k = D_k^-1 y_k - G_k+1 p_k+1.
    auto &work = set.work;
    work[first] = set.poses[first].d * -fraction;
    for (auto k = first + 1; k < last; ++k)
        work[k] = set.poses[k].d * -fraction - work[k - 1] * set.coupling[k];
    work[last - 1] = set.inverse_pivot[last - 1] * work[last - 1];
    for (auto k = last - 1; k-- > first;)
        work[k] = set.inverse_pivot[k] * work[k] - set.coupling[k + 1] * work[k + 1];
    // Each body moves once: a body shared by two pivots takes both their corrections in one turn.
    vector3 carried_dv = vector3_zero, carried_dw = vector3_zero;
    for (auto k = first; k < last; ++k) {
        auto &anchor = *set.anchors[k];
        auto &pose = set.poses[k];
        vector3 dv[2], dw[2];
        for (unsigned side = 0; side < 2; ++side) {
            auto &body = bodies[anchor.body[side]];
            auto p = side == 0 ? work[k] : -work[k];
            dv[side] = p * body.inv_mass;
            dw[side] = body.inv_inertia * cross(side == 0 ? pose.rA : pose.rB, p);
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

void project_joint_paths(joint_path_set &set, std::span<solver_body> bodies, scalar fraction, scalar inv_h,
                         bool refactor, task_scheduler *scheduler) {
    parallel_for_stages(scheduler, set.sync, set.colour_block_begin, [&](std::size_t, std::uint32_t block) {
        for (auto p = set.block_begin[block]; p < set.block_begin[block + 1]; ++p)
            project_path(set, p, bodies, fraction, inv_h, refactor);
    });
}

} // namespace edyn
