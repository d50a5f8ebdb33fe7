#ifndef EDYN_SIMULATION_CONTACT_EVENTS_HPP
#define EDYN_SIMULATION_CONTACT_EVENTS_HPP

#include "edyn/collision/contact_manifold.hpp"
#include "edyn/ecs/registry.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

/// Signal of a contact starting or ending; listeners get the manifold entity.
using contact_signal_t = sigh<void(entity)>;
/// Signal of a contact point created or destroyed; listeners get the manifold entity and the
/// point's id (its slot in contact_manifold::point).
using contact_point_signal_t = sigh<void(entity, contact_manifold::id_type)>;

/// Sink of the event raised when two bodies start touching (their manifold gets its first
/// point).
/// Collision events are recorded during the narrowphase and delivered at the end of the step,
/// so the solver's impulses are in the manifold when listeners read it. Per manifold the order
/// is: started, points destroyed, points created, ended. A point created in the slot of one
/// destroyed in the same step comes after it, with the same id: the slot then holds the new
/// point, which a point_destroyed listener reads if it reads the slot. A manifold destroyed while in contact
/// (its bodies' AABBs separated, a body was destroyed or filtered out) reports its points
/// destroyed and contact ended at once, while the entity is still valid. Events are recorded
/// only while some listener is connected. In asynchronous mode they are delivered on the
/// calling thread during update() or wait_for_simulation(), with main-registry entities.
/// @code
/// edyn::on_contact_started(registry).connect<&fn>(registry); // void fn(registry &, entity)
/// @endcode
/// @param registry The registry whose events to observe.
/// @return The sink to connect listeners to; they receive the manifold entity.
sink<contact_signal_t> on_contact_started(registry &registry);
/// Sink of the event raised when two bodies stop touching (their manifold loses its last point,
/// or is destroyed while in contact).
/// Delivered as on_contact_started describes, after the manifold's other events.
/// @param registry The registry whose events to observe.
/// @return The sink to connect listeners to; they receive the manifold entity.
sink<contact_signal_t> on_contact_ended(registry &registry);
/// Sink of the event raised when a manifold gets a new contact point.
/// Delivered as on_contact_started describes.
/// @param registry The registry whose events to observe.
/// @return The sink to connect listeners to; they receive the manifold entity and the point's
/// id (its slot in contact_manifold::point).
sink<contact_point_signal_t> on_contact_point_created(registry &registry);
/// Sink of the event raised when a contact point is removed from its manifold.
/// Delivered as on_contact_started describes.
/// @param registry The registry whose events to observe.
/// @return The sink to connect listeners to; they receive the manifold entity and the point's
/// id (its slot in contact_manifold::point).
sink<contact_point_signal_t> on_contact_point_destroyed(registry &registry);

/// The signals and the events waiting for the end of the step, in the registry's context.
/// Created by attach or by the first on_contact_* call; the narrowphase appends to `pending`
/// and the step delivers them. Programs use the on_contact_* sinks rather than this directly.
struct contact_events {
    /// What happened to a manifold.
    enum class kind : std::uint8_t {
        started,         ///< The manifold got its first point.
        point_created,   ///< A point was added.
        point_destroyed, ///< A point was removed.
        ended            ///< The manifold lost its last point, or was destroyed in contact.
    };
    /// One recorded event, waiting to be delivered.
    struct event {
        kind type;                    ///< What happened.
        entity manifold;              ///< The manifold entity it happened to.
        contact_manifold::id_type id; ///< The point's id, for point events.
    };

    contact_signal_t started;               ///< Listeners of on_contact_started.
    contact_signal_t ended;                 ///< Listeners of on_contact_ended.
    contact_point_signal_t point_created;   ///< Listeners of on_contact_point_created.
    contact_point_signal_t point_destroyed; ///< Listeners of on_contact_point_destroyed.
    std::vector<event> pending;             ///< Events recorded this step, in order.
    /// How many of `pending` deliver() has handed out so far (0 outside deliver()).
    std::size_t delivered{0};

    /// What of a manifold's contact its listeners have not been told yet.
    struct untold {
        bool started{false};  ///< Its start.
        std::uint32_t ids{0}; ///< The points created, by id (bit `id`).
    };

    /// Whether any of the four signals has a listener; events are only recorded then.
    /// @return True when at least one listener is connected.
    bool has_listeners() const noexcept {
        return !started.empty() || !ended.empty() || !point_created.empty() || !point_destroyed.empty();
    }
    /// Delivers the pending events in order, skipping manifolds destroyed meanwhile.
    /// Events that listeners cause (by destroying bodies) are delivered in the same call;
    /// `pending` is empty afterwards. When a listener throws, the events handed out so far,
    /// its own included, leave `pending`; the others stay for the next call.
    /// @param registry The registry the manifolds live in.
    void deliver(const registry &registry);
    /// Delivers one event now, to the listeners of its kind.
    /// @param e The event.
    void publish(const event &e);
    /// Takes the start and the points created of a manifold being destroyed out of the events
    /// still to deliver (a listener told of an earlier event destroyed one of its bodies), so
    /// that its listeners are told of no end of what they were never told began.
    /// @param manifold The manifold entity.
    /// @return What was taken out.
    untold withdraw(entity manifold);
};

} // namespace edyn

#endif // EDYN_SIMULATION_CONTACT_EVENTS_HPP
