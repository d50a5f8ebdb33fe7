#include "edyn/constraints/gravity_constraint.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include <cmath>

namespace edyn {

gravity_constraint_solver make_constraint_solver(const registry &registry, const gravity_constraint &c,
                                                 constraint_body_indices indices) {
    gravity_constraint_solver s;
    s.body[0] = indices.a;
    s.body[1] = indices.b;
    s.separation = registry.get<position>(c.body[1]) - registry.get<position>(c.body[0]);
    auto *mA = registry.try_get<mass>(c.body[0]);
    auto *mB = registry.try_get<mass>(c.body[1]);
    // A body made static or kinematic after the constraint carries large_scalar as its mass,
    // finite but no mass to attract with: the attraction stops while it is not dynamic.
    auto dynamic = registry.all_of<dynamic_tag>(c.body[0]) && registry.all_of<dynamic_tag>(c.body[1]);
    if (dynamic && mA && mB && std::isfinite(mA->s) && std::isfinite(mB->s)) {
        s.strength = gravitational_constant * mA->s * mB->s;
    }
    return s;
}

void solve(gravity_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    if (!ctx.use_bias || s.strength == 0) return;
    auto &a = bodies[s.body[0]];
    auto &b = bodies[s.body[1]];
    auto d = s.separation + b.delta_position - a.delta_position;
    auto dist_sqr = length_sqr(d);
    if (!(dist_sqr > scalar(1e-12))) return;
    // Impulse on A towards B over the sub-step, and its opposite on B.
    auto p = d * (s.strength * ctx.h / (dist_sqr * std::sqrt(dist_sqr)));
    if (moves(a)) a.linvel += p * a.inv_mass;
    if (moves(b)) b.linvel -= p * b.inv_mass;
}

} // namespace edyn
