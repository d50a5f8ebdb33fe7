#ifndef EDYN_ECS_ENTITY_MEMBERS_HPP
#define EDYN_ECS_ENTITY_MEMBERS_HPP

#include "edyn/ecs/entity.hpp"
#include <utility>

namespace edyn {

// Which members of a component hold entities. A component copied into another registry (the
// asynchronous worker's, a network peer's) must have them translated into that registry's
// entities; a component whose members hold none needs nothing. A component that does hold
// entities declares them by specialising this trait with an `each` that calls `fn` on every
// entity it holds, as an lvalue the caller may overwrite:
//
//   struct target { edyn::entity entity; std::vector<edyn::entity> followers; };
//   template<> struct edyn::entity_members<target> {
//       template<typename Fn> static void each(target &t, Fn &&fn) {
//           fn(t.entity);
//           for (auto &e : t.followers) fn(e);
//       }
//   };
//
// `fn` is never given edyn::null to translate: null stays null.
template<typename Component>
struct entity_members {
    template<typename Fn>
    static void each(Component &, Fn &&) {}
};

// Replaces every entity held by `component` with `map(entity)`, null excepted.
template<typename Component, typename Map>
void map_entity_members(Component &component, Map &&map) {
    entity_members<Component>::each(component, [&](entity &e) {
        if (e != null) e = map(e);
    });
}

} // namespace edyn

#endif // EDYN_ECS_ENTITY_MEMBERS_HPP
