#ifndef EDYN_SCENES_PIVOT_SEPARATION_HPP
#define EDYN_SCENES_PIVOT_SEPARATION_HPP

// How far joints are pulled apart: the figure the tests, the demo and edyn-bench give for the
// jointed scenes.

#include <edyn/edyn.hpp>

namespace edyn::scenes {

// The distance between a joint's two pivots in world space, in metres: zero while it holds.
scalar pivot_separation(const registry &registry, const point_constraint &joint);
scalar pivot_separation(const registry &registry, const hinge_constraint &joint);
scalar pivot_separation(const registry &registry, const cvjoint_constraint &joint);

// The largest pivot_separation of any point constraint, hinge or CV joint in the registry.
scalar max_pivot_separation(const registry &registry);

} // namespace edyn::scenes

#endif // EDYN_SCENES_PIVOT_SEPARATION_HPP
