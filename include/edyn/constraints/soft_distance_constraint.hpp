#ifndef EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

// A spring between the pivots (object space, relative to each origin) with rest length
// `distance`, stiffness in N/m and damping in N/(m/s).
struct soft_distance_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    scalar distance{0};
    scalar stiffness{1e6};
    scalar damping{1e3};
    scalar impulse{0};
};

template<>
inline constexpr const char *constraint_type_name<soft_distance_constraint> = "soft_distance_constraint";

void validate_constraint(const soft_distance_constraint &c);

struct soft_distance_constraint_solver {
    using component = soft_distance_constraint;
    joint_anchor anchor;
    scalar distance{0};
    scalar stiffness{0};
    scalar damping{0};
    scalar impulse{0};
};

soft_distance_constraint_solver make_constraint_solver(const registry &registry,
                                                       const soft_distance_constraint &c,
                                                       constraint_body_indices indices);
void warm_start(soft_distance_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(soft_distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const soft_distance_constraint_solver &s, soft_distance_constraint &c) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP
