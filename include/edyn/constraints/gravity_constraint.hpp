#ifndef EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

// Newton's universal gravitational constant, m^3 / (kg s^2).
inline constexpr scalar gravitational_constant = scalar(6.674e-11);

// Newtonian attraction G mA mB / r^2 between the centres of mass of the two bodies.
struct gravity_constraint {
    entity body[2]{null, null};
};

template<>
inline constexpr const char *constraint_type_name<gravity_constraint> = "gravity_constraint";

inline void validate_constraint(const gravity_constraint &) noexcept {}

struct gravity_constraint_solver {
    using component = gravity_constraint;
    solver_body_index body[2]{0, 0};
    // Centre of mass B minus centre of mass A when the step began.
    vector3 separation{vector3_zero};
    // G mA mB.
    scalar strength{0};
};

gravity_constraint_solver make_constraint_solver(const registry &registry, const gravity_constraint &c,
                                                 constraint_body_indices indices);
inline void warm_start(gravity_constraint_solver &, std::span<solver_body>) noexcept {}
// Applies the attraction's impulse over the sub-step (biased pass only: it is a force, and
// must act once per sub-step).
void solve(gravity_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
inline void store_impulses(const gravity_constraint_solver &, gravity_constraint &) noexcept {}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP
