#ifndef EDYN_CONSTRAINTS_CONSTRAINTS_HPP
#define EDYN_CONSTRAINTS_CONSTRAINTS_HPP

// Every constraint a program can make with make_constraint.
#include "edyn/constraints/cone_constraint.hpp"
#include "edyn/constraints/cvjoint_constraint.hpp"
#include "edyn/constraints/distance_constraint.hpp"
#include "edyn/constraints/generic_constraint.hpp"
#include "edyn/constraints/gravity_constraint.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/null_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/constraints/soft_distance_constraint.hpp"
#include "edyn/ecs/entity_members.hpp"
#include <type_traits>

namespace edyn {

/// A list of constraint types, carried as template arguments only (it holds nothing).
/// @tparam T The constraint components.
template<typename... T>
struct constraint_type_list {};

/// Every constraint component, in the order the solver visits them.
using constraint_types = constraint_type_list<point_constraint, distance_constraint, soft_distance_constraint,
                                              hinge_constraint, cvjoint_constraint, cone_constraint,
                                              generic_constraint, gravity_constraint, null_constraint>;

/// Whether T is one of the types of a constraint_type_list.
/// @tparam T The type looked for.
/// @tparam Ts The types of the list.
/// @return True when T is among Ts.
template<typename T, typename... Ts>
constexpr bool is_constraint_in(constraint_type_list<Ts...>) noexcept {
    return (std::is_same_v<T, Ts> || ...);
}

/// Satisfied by the constraint components, those listed in `constraint_types`.
template<typename T>
concept constraint_component = is_constraint_in<T>(constraint_types{});

/// A constraint holds its two bodies.
/// Lets a constraint copied into another registry (the asynchronous worker's, a network
/// peer's) have its bodies translated into that registry's entities.
/// @tparam T The constraint component.
template<constraint_component T>
struct entity_members<T> {
    /// Calls `fn` on each of the constraint's two bodies, body[0] then body[1], as lvalues it
    /// may overwrite.
    /// @tparam Fn A callable taking `entity &`.
    /// @param con The constraint.
    /// @param fn Called once per body.
    template<typename Fn>
    static void each(T &con, Fn &&fn) {
        fn(con.body[0]);
        fn(con.body[1]);
    }
};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINTS_HPP
