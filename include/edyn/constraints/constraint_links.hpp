#ifndef EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP

#include "edyn/ecs/registry.hpp"
#include <vector>

namespace edyn {

// Each body (or external entity) keeps the list of the constraints that join it, threaded
// through the constraint entities, so that finding a body's constraints costs as many steps as
// it has constraints, and linking or unlinking one costs a constant: building or clearing a
// scene stays linear in its size. Kept by the simulation's listeners.

// On a constraint entity: the two entities it joins and its neighbours in each one's list.
// An entity holding several constraint components is listed once, under the first one's bodies.
struct constraint_links {
    entity body[2]{null, null};
    entity next[2]{null, null};
    entity prev[2]{null, null};
    unsigned num_constraints{0}; // constraint components on the entity
};

// On a body that has constraints: the first of them.
struct constraint_list {
    entity first{null};
};

// Adds `constraint` (joining body0 and body1) to both bodies' lists; a second constraint
// component on the same entity only counts itself.
void link_constraint(registry &registry, entity constraint, entity body0, entity body1);
// Counts a constraint component of `constraint` out; the last one removes its links.
void release_constraint(registry &registry, entity constraint);
// Takes `constraint` out of its bodies' lists (listener of on_destroy<constraint_links>).
void unlink_constraint(registry &registry, entity constraint);

// A constraint entity and the two entities it joins.
struct constraint_ref {
    entity constraint;
    entity body[2];
};

// Appends to `out` every constraint that has `body` as one of its bodies, newest first.
void constraints_of(const registry &registry, entity body, std::vector<constraint_ref> &out);

// Destroys every constraint that has `body` as one of its bodies (a constraint does not outlive
// its bodies).
void destroy_constraints_of(registry &registry, entity body);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP
