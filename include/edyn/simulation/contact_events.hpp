#ifndef EDYN_SIMULATION_CONTACT_EVENTS_HPP
#define EDYN_SIMULATION_CONTACT_EVENTS_HPP

#include "edyn/collision/contact_manifold.hpp"
#include "edyn/ecs/registry.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

using contact_signal_t = sigh<void(entity)>;
using contact_point_signal_t = sigh<void(entity, contact_manifold::id_type)>;

// Collision events. They are recorded during the narrowphase and delivered at the end of the
// step, so the solver's impulses are in the manifold when listeners read it. Per manifold the
// order is: started, points created, points destroyed, ended. A manifold destroyed while in
// contact (its bodies' AABBs separated, a body was destroyed or filtered out) reports its points
// destroyed and contact ended at once, while the entity is still valid.
//
//   edyn::on_contact_started(registry).connect<&fn>(registry);  // void fn(registry &, entity)
sink<contact_signal_t> on_contact_started(registry &registry);
sink<contact_signal_t> on_contact_ended(registry &registry);
// The manifold entity and the point's id (its slot in contact_manifold::point).
sink<contact_point_signal_t> on_contact_point_created(registry &registry);
sink<contact_point_signal_t> on_contact_point_destroyed(registry &registry);

// The signals and the events waiting for the end of the step, in the registry's context.
struct contact_events {
    enum class kind : std::uint8_t { started, point_created, point_destroyed, ended };
    struct event {
        kind type;
        entity manifold;
        contact_manifold::id_type id;
    };

    contact_signal_t started;
    contact_signal_t ended;
    contact_point_signal_t point_created;
    contact_point_signal_t point_destroyed;
    std::vector<event> pending;

    bool has_listeners() const noexcept {
        return !started.empty() || !ended.empty() || !point_created.empty() || !point_destroyed.empty();
    }
    // Delivers the pending events in order, skipping manifolds destroyed meanwhile.
    void deliver(const registry &registry);
    // Delivers one event now.
    void publish(const event &e);
};

} // namespace edyn

#endif // EDYN_SIMULATION_CONTACT_EVENTS_HPP
