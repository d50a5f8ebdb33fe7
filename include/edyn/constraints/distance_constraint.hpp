#ifndef EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

// Keeps the pivots (object space, relative to each origin) `distance` apart, like a rigid rod
// with ball joints at both ends.
struct distance_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    scalar distance{0};
    scalar impulse{0};
};

template<>
inline constexpr const char *constraint_type_name<distance_constraint> = "distance_constraint";

void validate_constraint(const distance_constraint &c);

struct distance_constraint_solver {
    using component = distance_constraint;
    joint_anchor anchor;
    scalar distance{0};
    scalar impulse{0};
};

distance_constraint_solver make_constraint_solver(const registry &registry, const distance_constraint &c,
                                                  constraint_body_indices indices);
void warm_start(distance_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const distance_constraint_solver &s, distance_constraint &c) noexcept;
inline void project_positions(distance_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    project_distance(s.anchor, s.distance, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction,
                     inv_h);
}

// Direction and length of d; false when the pivots coincide and no direction exists.
bool pivot_direction(const vector3 &d, vector3 &direction, scalar &length) noexcept;

// The pivots of a distance-like joint now, and the unit direction and length between them.
struct pivot_axis {
    joint_pose pose;
    vector3 direction;
    scalar length;
};

// False when the pivots coincide and no direction exists.
bool current_pivot_axis(const joint_anchor &anchor, const solver_body &a, const solver_body &b,
                        pivot_axis &axis) noexcept;

// Re-applies an impulse along the current direction between the pivots (distance and soft
// distance joints).
void warm_start_pivot_axis(const joint_anchor &anchor, scalar impulse,
                           std::span<solver_body> bodies) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP
