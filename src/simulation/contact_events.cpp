#include "edyn/simulation/contact_events.hpp"
#include <cstddef>

namespace edyn {

namespace {
contact_events &events(registry &registry) { return registry.ctx().emplace<contact_events>(); }
} // namespace

sink<contact_signal_t> on_contact_started(registry &registry) { return sink{events(registry).started}; }
sink<contact_signal_t> on_contact_ended(registry &registry) { return sink{events(registry).ended}; }
sink<contact_point_signal_t> on_contact_point_created(registry &registry) {
    return sink{events(registry).point_created};
}
sink<contact_point_signal_t> on_contact_point_destroyed(registry &registry) {
    return sink{events(registry).point_destroyed};
}

void contact_events::publish(const event &e) {
    switch (e.type) {
    case kind::started:
        started.publish(e.manifold);
        break;
    case kind::point_created:
        point_created.publish(e.manifold, e.id);
        break;
    case kind::point_destroyed:
        point_destroyed.publish(e.manifold, e.id);
        break;
    case kind::ended:
        ended.publish(e.manifold);
        break;
    }
}

void contact_events::deliver(const registry &registry) {
    // What was handed out leaves `pending` however the loop ends: a listener that throws leaves
    // the events after its own for the next delivery, and none is told twice.
    struct drop_delivered {
        contact_events &events;
        ~drop_delivered() {
            events.pending.erase(events.pending.begin(),
                                 events.pending.begin() + std::ptrdiff_t(events.delivered));
            events.delivered = 0;
        }
    } drop{*this};
    // Listeners may cause new events (by destroying bodies): those are delivered as well.
    for (delivered = 0; delivered < pending.size();) {
        auto e = pending[delivered++];
        if (registry.valid(e.manifold)) publish(e);
    }
}

contact_events::untold contact_events::withdraw(entity manifold) {
    untold taken;
    for (auto i = delivered; i < pending.size(); ++i) {
        auto &e = pending[i];
        if (e.manifold != manifold) continue;
        if (e.type == kind::started) {
            taken.started = true;
            e.manifold = null;
        } else if (e.type == kind::point_created) {
            taken.ids |= std::uint32_t{1} << e.id;
            e.manifold = null;
        }
    }
    return taken;
}

} // namespace edyn
