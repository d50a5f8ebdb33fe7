#ifndef EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/null_constraint.hpp"
#include <type_traits>
#include <utility>

namespace edyn {

struct gravity_constraint;

/// Throws std::invalid_argument unless body0 and body1 are two distinct rigid bodies (or, when
/// `allow_external`, external entities).
/// make_constraint() calls it before creating anything; external entities are allowed for a
/// null_constraint only, and a gravity_constraint needs two dynamic bodies.
/// @param registry The registry the bodies live in.
/// @param type Name of the constraint type, for the message.
/// @param body0 The first body.
/// @param body1 The second body.
/// @param allow_external Whether an entity tagged with `external_tag` may stand for a body.
/// @param require_dynamic Whether both bodies must be dynamic (static and kinematic bodies carry
/// `large_scalar` as their mass, which a gravity_constraint cannot multiply).
/// @throws std::invalid_argument When a body is null or not a valid entity, when it is neither a
/// rigid body nor (with `allow_external`) an external entity, when (with `require_dynamic`) it is
/// not dynamic, or when body0 equals body1.
void validate_constraint_bodies(const registry &registry, const char *type, entity body0, entity body1,
                                bool allow_external, bool require_dynamic = false);

/// Creates a constraint of type T between body0 and body1 on a new entity and returns it.
/// `setup` receives the component (bodies already set) to assign pivots, frames, limits and so
/// on. The result is validated before anything is created: bad bodies or fields throw
/// std::invalid_argument naming the field, and leave the registry as it was. The constraint
/// joins the bodies' islands and is destroyed with either body.
///
/// Call it on the main registry from the thread that owns it. In asynchronous mode the new
/// component travels to the simulation worker like any other registered component, with the
/// values `setup` gave it; changing the component later needs `replace` or `patch` to travel.
/// Any body the setup writes into `body` is overwritten with body0 and body1.
/// @tparam T The constraint component, one of `constraint_types`.
/// @tparam Setup A callable taking `T &`.
/// @param registry The registry holding both bodies; the constraint entity is created in it.
/// @param body0 The first body (`body[0]` of the constraint).
/// @param body1 The second body (`body[1]` of the constraint).
/// @param setup Called once with the component before it is validated and emplaced.
/// @return The new constraint entity.
/// @throws std::invalid_argument When the bodies are not two distinct valid rigid bodies (an
/// external entity is also accepted for a null_constraint; a gravity_constraint needs both
/// dynamic), or when a field set by `setup` is
/// out of range (see the validate_constraint function of T). Exceptions thrown by `setup`
/// itself propagate; in every case the registry is left as it was.
template<typename T, typename Setup>
entity make_constraint(registry &registry, entity body0, entity body1, Setup &&setup) {
    validate_constraint_bodies(registry, constraint_type_name<T>, body0, body1,
                               std::is_same_v<T, null_constraint>, std::is_same_v<T, gravity_constraint>);
    T con{};
    con.body[0] = body0;
    con.body[1] = body1;
    std::forward<Setup>(setup)(con);
    // The setup may configure the constraint but not move it to other bodies.
    con.body[0] = body0;
    con.body[1] = body1;
    validate_constraint(con);
    auto e = registry.create();
    registry.emplace<T>(e, con);
    return e;
}

/// Creates a constraint of type T between body0 and body1 with every other field at its
/// default (pivots at the bodies' origins, identity frames; see T for the rest).
/// @tparam T The constraint component, one of `constraint_types`.
/// @param registry The registry holding both bodies; the constraint entity is created in it.
/// @param body0 The first body (`body[0]` of the constraint).
/// @param body1 The second body (`body[1]` of the constraint).
/// @return The new constraint entity.
/// @throws std::invalid_argument When the bodies are not two distinct valid rigid bodies (an
/// external entity is also accepted for a null_constraint; a gravity_constraint needs both
/// dynamic); the registry is left as it was.
template<typename T>
entity make_constraint(registry &registry, entity body0, entity body1) {
    return make_constraint<T>(registry, body0, body1, [](T &) {});
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_MAKE_CONSTRAINT_HPP
