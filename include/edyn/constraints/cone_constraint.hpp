#ifndef EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/math/math.hpp"
#include <span>

namespace edyn {

// Keeps pivot[1] of body[1] inside a cone attached to body[0]: its apex is pivot[0], its axis
// the first column of `frame` (body[0]'s object space). The cone may be elliptical: it opens
// by span_angle[0] towards the frame's second column and by span_angle[1] towards the third.
// Usually paired with a point or CV joint at the apex, as a swing limit (shoulders, hips).
struct cone_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    matrix3x3 frame{matrix3x3_identity};
    // Half-angles of the cone in radians, each in (0, pi/2).
    scalar span_angle[2]{pi / 4, pi / 4};
    // Restitution of the cone's wall in [0, 1].
    scalar restitution{0};
    // Within bump_stop_angle of the wall, a spring of bump_stop_stiffness (Nm/rad) pushes the
    // point back towards the axis.
    scalar bump_stop_angle{0};
    scalar bump_stop_stiffness{0};

    // Last step's impulses per sub-step, for warm starting.
    scalar impulse{0};
    scalar bump_stop_impulse{0};
};

template<>
inline constexpr const char *constraint_type_name<cone_constraint> = "cone_constraint";

void validate_constraint(const cone_constraint &c);

// The cone's half-angle in the direction (cos phi, sin phi) of its cross-section, for spans
// whose tangents are tan0 and tan1: the polar radius of the ellipse of semi-axes tan0, tan1.
scalar cone_half_angle(scalar tan0, scalar tan1, scalar cos_phi, scalar sin_phi) noexcept;

struct cone_constraint_solver {
    using component = cone_constraint;
    joint_anchor anchor;
    matrix3x3 frame; // world space, at the start of the step
    scalar span_tan[2];
    scalar restitution, bump_stop_angle, bump_stop_stiffness;
    // Rate at which the point approached the wall when the step began (negative: approaching).
    scalar start_rate{0};
    bool bounced{false};
    scalar impulse, bump_stop_impulse;
};

cone_constraint_solver make_constraint_solver(const registry &registry, const cone_constraint &c,
                                              constraint_body_indices indices);
void warm_start(cone_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(cone_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const cone_constraint_solver &s, cone_constraint &c) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP
