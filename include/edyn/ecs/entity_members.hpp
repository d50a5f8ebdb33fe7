#ifndef EDYN_ECS_ENTITY_MEMBERS_HPP
#define EDYN_ECS_ENTITY_MEMBERS_HPP

#include "edyn/ecs/entity.hpp"
#include <utility>

namespace edyn {

/// Trait that tells which members of a component hold entities.
///
/// A component copied into another registry (the asynchronous worker's, a network peer's) must
/// have them translated into that registry's entities; a component whose members hold none needs
/// nothing, which is what this primary template says. A component that does hold entities
/// declares them by specialising this trait with an `each` that calls `fn` on every entity it
/// holds, as an lvalue the caller may overwrite:
///
/// @code
/// struct target { edyn::entity entity; std::vector<edyn::entity> followers; };
/// template<> struct edyn::entity_members<target> {
///     template<typename Fn> static void each(target &t, Fn &&fn) {
///         fn(t.entity);
///         for (auto &e : t.followers) fn(e);
///     }
/// };
/// @endcode
///
/// `fn` is never given edyn::null to translate: null stays null. This replaces EnTT's meta
/// system (`entt::meta`, `entt::as_ref_t`) for this purpose.
/// @tparam Component The component type.
template<typename Component>
struct entity_members {
    /// Calls `fn(entity &)` on every entity-valued member of a component; this primary template
    /// declares none, so it does nothing.
    template<typename Fn>
    static void each(Component &, Fn &&) {}
};

/// Replaces every entity held by `component` (as `entity_members` declares them) with
/// `map(entity)`, null excepted.
/// @param component The component to translate, in place.
/// @param map Callable `entity(entity)` giving the entity to store instead, for example a look-up
/// in an `entity_map`.
template<typename Component, typename Map>
void map_entity_members(Component &component, Map &&map) {
    entity_members<Component>::each(component, [&](entity &e) {
        if (e != null) e = map(e);
    });
}

} // namespace edyn

#endif // EDYN_ECS_ENTITY_MEMBERS_HPP
