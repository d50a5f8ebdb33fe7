#ifndef EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include <cstdint>
#include <limits>
#include <span>

namespace edyn {

// How a degree of freedom of a generic constraint moves.
enum class dof_mode : std::uint8_t {
    free,    // unconstrained (springs, damping and friction still act)
    locked,  // held at zero
    limited, // kept within [min, max]
};

// One degree of freedom. Linear ones are in metres (forces in N), angular ones in radians
// (torques in Nm).
struct generic_dof {
    dof_mode mode{dof_mode::locked};
    scalar min{-std::numeric_limits<scalar>::infinity()};
    scalar max{std::numeric_limits<scalar>::infinity()};
    // A spring of `stiffness` (N/m or Nm/rad) pulls the coordinate towards `rest`.
    scalar stiffness{0};
    scalar rest{0};
    // Force or torque per unit rate (N/(m/s) or Nm/(rad/s)).
    scalar damping{0};
    // Force or torque opposing motion along the axis (N or Nm).
    scalar friction{0};
};

// Six degrees of freedom between two bodies, each free, locked or limited. The coordinates are
// measured in body[0]'s frame (frame[0], object space, at pivot[0]): linear[i] is the offset of
// pivot[1] from pivot[0] along frame[0]'s column i; angular[i] is the rotation of frame[1]
// from frame[0] about column i (the components of the rotation vector taking frame[0] to
// frame[1], exact for rotations about a single axis). Every degree of freedom is locked by
// default: a weld.
struct generic_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    generic_dof linear[3]{};
    generic_dof angular[3]{};

    // Last step's impulses per sub-step, for warm starting: rows 0-2 linear, 3-5 angular.
    // Three locked linear (or angular) degrees of freedom are solved as one block, whose
    // impulse (world space) is kept instead of the rows'.
    vector3 linear_block_impulse{vector3_zero};
    vector3 angular_block_impulse{vector3_zero};
    scalar impulse[6]{0, 0, 0, 0, 0, 0};
    scalar limit_impulse[6][2]{};
    scalar spring_impulse[6]{0, 0, 0, 0, 0, 0};
    scalar friction_impulse[6]{0, 0, 0, 0, 0, 0};
};

template<>
inline constexpr const char *constraint_type_name<generic_constraint> = "generic_constraint";

void validate_constraint(const generic_constraint &c);

struct generic_constraint_solver {
    using component = generic_constraint;
    joint_anchor anchor;
    matrix3x3 frameA, frameB; // world space, at the start of the step
    generic_dof dof[6];
    // All three linear (angular) degrees of freedom locked: solved as a block.
    bool linear_block{false}, angular_block{false};
    vector3 linear_block_impulse, angular_block_impulse;
    scalar impulse[6];
    scalar limit_impulse[6][2];
    scalar spring_impulse[6];
    scalar friction_impulse[6];
};

generic_constraint_solver make_constraint_solver(const registry &registry, const generic_constraint &c,
                                                 constraint_body_indices indices);
void warm_start(generic_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(generic_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const generic_constraint_solver &s, generic_constraint &c) noexcept;
// With all three linear degrees of freedom locked, the pivots are held as a ball joint's.
inline void project_positions(generic_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    if (s.linear_block)
        project_point(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction, inv_h);
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP
