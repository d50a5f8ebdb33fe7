#include "edyn/constraints/cone_constraint.hpp"
#include "../math/arctan2.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/constraints/cvjoint_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/dynamics/velocity.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

void validate_constraint(const cone_constraint &c) {
    constexpr auto type = constraint_type_name<cone_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_orthonormal(type, "frame", c.frame);
    const char *spans[2]{"span_angle[0]", "span_angle[1]"};
    for (int i = 0; i < 2; ++i) {
        if (!(c.span_angle[i] > 0 && c.span_angle[i] < pi / 2)) {
            throw_constraint_error(type, spans[i],
                                   "must be in (0, pi/2), got " + std::to_string(c.span_angle[i]));
        }
    }
    check_constraint_unit_interval(type, "restitution", c.restitution);
    check_constraint_non_negative(type, "bump_stop_angle", c.bump_stop_angle);
    check_constraint_non_negative(type, "bump_stop_stiffness", c.bump_stop_stiffness);
}

namespace {

// The cone's row: C is the angle between the point's direction and the wall, measured in the
// plane of the axis and the point (positive inside), and the jacobian is its rate.
struct cone_row {
    jacobian j;
    scalar C;
    bool valid;
    scalar radius; // The point's distance from the apex (m).
};

cone_row current_row(const cone_constraint_solver &s, const joint_pose &pose, const solver_body &a) noexcept {
    auto frame = rotate_frame(a.delta_rotation, s.frame);
    auto r = -pose.d; // apex to the point
    auto e0 = frame.column(0), e1 = frame.column(1), e2 = frame.column(2);
    auto x = dot(r, e0), y = dot(r, e1), z = dot(r, e2);
    auto rho = std::sqrt(y * y + z * z);
    auto len = length(r);
    // At the apex or on the axis the wall is as far as the cone is wide: nothing to do.
    if (!(len > scalar(1e-6)) || !(rho > scalar(1e-6) * len)) return {{}, 0, false, 0};
    // The wall's half-angle alpha in the point's direction about the axis is the polar radius of
    // the ellipse of semi-axes tan0, tan1: tan alpha = k rho / m with k = tan0 tan1 and
    // m = |(tan1 y, tan0 z)|. The point's own angle from the axis is theta = atan2(rho, x), and
    // alpha - theta is the argument of (m + i k rho)(x - i rho): one arctangent.
    auto k = s.span_tan[0] * s.span_tan[1];
    auto m = std::sqrt(square(s.span_tan[1] * y) + square(s.span_tan[0] * z));
    auto C = detail::arctan2(rho * (k * x - m), x * m + k * rho * rho);
    // d theta / d r = (cos theta u - sin theta e0) / |r| with u the radial direction; C = alpha
    // - theta grows along n. The point is B's pivot; A's lever arm reaches the same point, since
    // the cone turns with A.
    // (sin theta = rho / |r| and cos theta = x / |r|.)
    auto u = (e1 * y + e2 * z) / rho;
    auto n = (e0 * rho - u * x) / (len * len);
    return {linear_jacobian(-n, pose.rA - pose.d, pose.rB), C, true, len};
}

// How far from the apex, on the cone's body, a joint's pivot may lie for the joint to hold the
// apex (m).
constexpr scalar apex_tolerance = scalar(1e-3);

// Whether a joint of type Joint on `entity` joins the cone's two bodies at its apex.
template<typename Joint>
bool holds_apex(const registry &registry, entity entity, const cone_constraint &c) {
    auto *joint = registry.try_get<Joint>(entity);
    if (joint == nullptr) return false;
    for (int i = 0; i < 2; ++i) {
        if (joint->body[i] == c.body[0] && joint->body[1 - i] == c.body[1])
            return distance_sqr(joint->pivot[i], c.pivot[0]) <= apex_tolerance * apex_tolerance;
    }
    return false;
}

// Whether a point or CV joint holds the cone's point body at its apex. Walks the point body's
// constraint list: a few entries on a limb.
bool find_apex_joint(const registry &registry, const cone_constraint &c) {
    auto *list = registry.try_get<constraint_list>(c.body[1]);
    if (list == nullptr) return false;
    for (auto e = list->first; e != null;) {
        if (holds_apex<point_constraint>(registry, e, c) || holds_apex<cvjoint_constraint>(registry, e, c))
            return true;
        const auto &links = registry.get<constraint_links>(e);
        e = links.next[links.body[0] == c.body[1] ? 0 : 1];
    }
    return false;
}

// A bounce of a point whose body a joint holds at the apex, solved as an isolated collision:
// the wall's row and the apex's 3x3 block iterated together from zero impulses, so that the
// point leaves the wall at `bounce` with the body turning about the apex. The wall's row alone
// would move the apex, and the joint would then take part of the bounce back.
void bounce_about_apex(const cone_constraint_solver &s, const jacobian &wall, scalar bounce, solver_body &a,
                       solver_body &b) noexcept {
    constexpr int iterations = 32;
    auto pose = current_pose(s.anchor, a, b);
    // The apex is pivot A; on B it is the point pivot B plus the separation.
    joint_pose apex{pose.rA, pose.rB + pose.d, vector3_zero};
    matrix3x3 apex_mass;
    if (!inverse_point_mass(a, b, apex, apex_mass)) return;
    auto wall_mass = row_effective_mass(wall, a, b);
    scalar wall_impulse = 0;
    for (int k = 0; k < iterations; ++k) {
        auto new_impulse =
            std::max(wall_impulse + wall_mass * (bounce - row_velocity(wall, a, b)), scalar(0));
        apply_row_impulse(wall, a, b, new_impulse - wall_impulse);
        wall_impulse = new_impulse;
        auto hold = -(apex_mass * relative_velocity(a, b, apex.rA, apex.rB));
        apply_impulse(a, b, hold, apex.rA, apex.rB);
    }
}

} // namespace

cone_constraint_solver make_constraint_solver(const registry &registry, const cone_constraint &c,
                                              constraint_body_indices indices) {
    cone_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.frame = world_frame(registry, c.body[0], c.frame);
    for (int i = 0; i < 2; ++i)
        s.span_tan[i] = std::tan(c.span_angle[i]);
    s.restitution = c.restitution;
    s.bump_stop_angle = c.bump_stop_angle;
    s.bump_stop_stiffness = c.bump_stop_stiffness;
    s.impulse = c.impulse;
    s.bump_stop_impulse = c.bump_stop_impulse;
    if (c.restitution > 0) {
        solver_body a, b;
        a.linvel = registry.get<linvel>(c.body[0]);
        a.angvel = registry.get<angvel>(c.body[0]);
        b.linvel = registry.get<linvel>(c.body[1]);
        b.angvel = registry.get<angvel>(c.body[1]);
        auto row = current_row(s, current_pose(s.anchor, a, b), a);
        if (row.valid) s.start_rate = row_velocity(row.j, a, b);
        s.apex_held = find_apex_joint(registry, c);
    }
    return s;
}

void refresh_geometry(cone_constraint_solver &s, std::span<const solver_body> bodies) noexcept {
    auto row = current_row(s, s.anchor.pose, bodies[s.anchor.body[0]]);
    s.wall = row.j;
    s.wall_angle = row.C;
    s.wall_valid = row.valid;
    s.wall_radius = row.radius;
}

void warm_start(cone_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    if (!s.wall_valid) {
        s.impulse = s.bump_stop_impulse = 0;
        return;
    }
    apply_row_impulse(s.wall, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]],
                      s.impulse + s.bump_stop_impulse);
}

void solve(cone_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    if (!s.wall_valid) return;
    const auto &wall = s.wall;
    const auto angle = s.wall_angle;

    if (s.bump_stop_angle > 0 && s.bump_stop_stiffness > 0) {
        if (angle < s.bump_stop_angle) {
            solve_spring_row(wall, angle - s.bump_stop_angle, s.bump_stop_stiffness, 0, s.bump_stop_impulse,
                             a, b, ctx, true);
        } else {
            s.bump_stop_impulse = 0;
        }
    }

    if (s.restitution > 0 && !s.bounced) {
        // A wall hit in the coming sub-step faster than the threshold bounces once per step,
        // with the approach speed it had before the wall started braking it. Checked in both
        // passes: the relax pass after the step's last integration would otherwise brake the
        // approach speculatively, and the next step would see no speed left to bounce with.
        auto rate = row_velocity(wall, a, b);
        auto approach = std::min(rate, s.start_rate);
        if (approach < -ctx.restitution_threshold && angle + rate * ctx.h <= 0) {
            s.bounced = true;
            // The warm-started push is part of the approach being answered.
            apply_row_impulse(wall, a, b, -s.impulse);
            s.impulse = 0;
            auto bounce = -s.restitution * approach;
            if (s.apex_held) {
                bounce_about_apex(s, wall, bounce, a, b);
            } else {
                auto mass = row_effective_mass(wall, a, b);
                auto p = std::max(mass * (bounce - row_velocity(wall, a, b)), scalar(0));
                // Not accumulated in the wall's impulse, which would take it back once separating.
                apply_row_impulse(wall, a, b, p);
            }
            return;
        }
    }
    // A point far outside is drawn back across the wall no faster than a joint's pivots are
    // drawn together (constraint_solver_settings::max_correction_speed): the spring alone
    // flung a point 45 degrees out at 33 m/s, and one behind the apex at the world's speed cap.
    solve_limit_row(wall, angle, s.impulse, a, b, ctx, ctx.max_correction_speed / s.wall_radius);
}

void store_impulses(const cone_constraint_solver &s, cone_constraint &c) noexcept {
    c.impulse = s.impulse;
    c.bump_stop_impulse = s.bump_stop_impulse;
}

} // namespace edyn
