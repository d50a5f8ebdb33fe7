#ifndef EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP

#include "edyn/ecs/registry.hpp"
#include <vector>

namespace edyn {

/// On a constraint entity: the two entities it joins and its neighbours in each one's list.
/// An entity holding several constraint components is listed once, under the first one's bodies.
///
/// Each body (or external entity) keeps the list of the constraints that join it, threaded
/// through the constraint entities, so that finding a body's constraints costs as many steps as
/// it has constraints, and linking or unlinking one costs a constant: building or clearing a
/// scene stays linear in its size. Kept by the simulation's listeners.
struct constraint_links {
    entity body[2]{null, null}; ///< The two entities the constraint joins.
    /// Next constraint in each body's list (index i: the list of body[i]); null at the end.
    entity next[2]{null, null};
    /// Previous constraint in each body's list (index i: the list of body[i]); null at the head.
    entity prev[2]{null, null};
    unsigned num_constraints{0}; ///< Constraint components on the entity.
};

/// On a body that has constraints: the first of them.
/// The head of the list threaded through constraint_links; written by the engine's listeners.
struct constraint_list {
    entity first{null}; ///< The newest constraint joining the body; null when none is left.
};

/// Adds `constraint` (joining body0 and body1) to both bodies' lists; a second constraint
/// component on the same entity only counts itself.
/// Called by the engine when a constraint component is constructed. A body that is not a valid
/// entity is skipped; a body joined to itself is listed once.
/// @param registry The registry holding the constraint and its bodies.
/// @param constraint The constraint entity.
/// @param body0 Its first body.
/// @param body1 Its second body.
void link_constraint(registry &registry, entity constraint, entity body0, entity body1);
/// Counts a constraint component of `constraint` out; the last one removes its links.
/// Called by the engine when a constraint component is destroyed; does nothing on an entity
/// without links.
/// @param registry The registry holding the constraint.
/// @param constraint The constraint entity.
void release_constraint(registry &registry, entity constraint);
/// Takes `constraint` out of its bodies' lists (listener of on_destroy<constraint_links>).
/// A body whose list is already gone (it is being destroyed) is skipped.
/// @param registry The registry holding the constraint; it must have constraint_links.
/// @param constraint The constraint entity.
void unlink_constraint(registry &registry, entity constraint);

/// A constraint entity and the two entities it joins.
struct constraint_ref {
    entity constraint; ///< The constraint entity.
    entity body[2];    ///< The two entities it joins, as in its constraint_links.
};

/// Appends to `out` every constraint that has `body` as one of its bodies, newest first.
/// Appends nothing for an invalid entity or one without constraints; does not clear `out`.
/// @param registry The registry holding the body.
/// @param body The body (or external entity).
/// @param out Receives one constraint_ref per constraint entity.
void constraints_of(const registry &registry, entity body, std::vector<constraint_ref> &out);

/// Destroys every constraint that has `body` as one of its bodies (a constraint does not outlive
/// its bodies).
/// The engine calls it when a body or an external entity is destroyed; the constraint entities
/// are destroyed whole, with every component on them.
/// @param registry The registry holding the body.
/// @param body The body (or external entity).
void destroy_constraints_of(registry &registry, entity body);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_LINKS_HPP
